# Keeps docs/code-layout.md's namespace rule true: every file of src/<folder>/ (its subfolders
# included) opens only its folder's namespace, twinraster::<folder>, or plain twinraster for the
# shared vocabulary; a part of the library may go one level down (twinraster::files::png_runs), and
# cli/ may forward-declare CLI11's classes in namespace CLI. It reads only the lines
# "namespace NAME {" at the start of a line (clang-format puts every namespace there), so it does
# not check what is declared outside any namespace.
# Run as: cmake -DSOURCE_DIR=<repository> -P check_namespaces.cmake
cmake_minimum_required(VERSION 3.25)  # IN_LIST
set(problems 0)
macro(problem text)
  message(SEND_ERROR "${text}")
  math(EXPR problems "${problems} + 1")
endmacro()

set(vocabulary base scene chain image)
file(GLOB folders LIST_DIRECTORIES true RELATIVE ${SOURCE_DIR}/src ${SOURCE_DIR}/src/*)
list(FILTER folders EXCLUDE REGEX "\\.")  # CMakeLists.txt and twinraster.hpp are no folders

set(files_seen 0)
foreach(folder IN LISTS folders)
  if(folder IN_LIST vocabulary)
    set(own "twinraster")
  else()
    set(own "twinraster::${folder}")
  endif()
  file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/src/${folder}/*.hpp ${SOURCE_DIR}/src/${folder}/*.cpp)
  foreach(file IN LISTS files)
    math(EXPR files_seen "${files_seen} + 1")
    file(STRINGS ${SOURCE_DIR}/${file} opened REGEX "^namespace [A-Za-z0-9_:]+ {")
    foreach(line IN LISTS opened)
      string(REGEX REPLACE "^namespace ([A-Za-z0-9_:]+) {.*$" "\\1" name "${line}")
      if(name STREQUAL own OR (folder STREQUAL "cli" AND name STREQUAL "CLI"))
        continue()
      endif()
      # One level down, named for a part of the library, never for another folder.
      if(name MATCHES "^${own}::([a-z0-9_]+)$" AND NOT CMAKE_MATCH_1 IN_LIST folders)
        continue()
      endif()
      problem("${file}: opens namespace ${name}; the files of src/${folder}/ are in ${own} (docs/code-layout.md)")
    endforeach()
  endforeach()
endforeach()

message(STATUS "check_namespaces: ${files_seen} files, ${problems} problems")
