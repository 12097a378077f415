# Guards the data path: each folder of src/ may include only itself and the stages its library
# links (transitively), so that an include can never reach a stage the link lines do not give it.
# Run as: cmake -DSOURCE_DIR=<repository> -DALLOWED=<file> -P check_layers.cmake
#
# ALLOWED is the file tests/allowed_layers.cmake writes at configure time from the targets' links
# (set(allowed_<folder> "<stages>") for each folder of src/ the build defines); the stages are not
# written a second time here. A folder of src/ with a CMakeLists.txt that the build does not add
# (one left out by an option) has nothing built to check; one without is an error. A .cpp file no
# target compiles in this configuration (an option left it out) is not checked either.
include(${ALLOWED})

set(problems 0)
file(GLOB stages LIST_DIRECTORIES true RELATIVE ${SOURCE_DIR}/src ${SOURCE_DIR}/src/*)
foreach(stage IN LISTS stages)
  if(NOT IS_DIRECTORY ${SOURCE_DIR}/src/${stage})
    continue()
  endif()
  if(NOT DEFINED allowed_${stage})
    if(EXISTS ${SOURCE_DIR}/src/${stage}/CMakeLists.txt)
      message(STATUS "src/${stage}/: not built in this configuration, not checked")
    else()
      message(SEND_ERROR "src/${stage}/: no CMakeLists.txt defines its library (twinraster_${stage}) and links")
      math(EXPR problems "${problems} + 1")
    endif()
    continue()
  endif()
  file(GLOB_RECURSE files ${SOURCE_DIR}/src/${stage}/*.hpp ${SOURCE_DIR}/src/${stage}/*.cpp)
  foreach(file IN LISTS files)
    if(file MATCHES "\\.cpp$" AND DEFINED compiled_${stage})
      list(FIND compiled_${stage} ${file} is_compiled)
      if(is_compiled EQUAL -1)
        continue()  # left out by an option (gpu/'s Vulkan files without Vulkan): the default build checks it
      endif()
    endif()
    file(STRINGS ${file} includes REGEX "^#include \"[a-z0-9_]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"([a-z0-9_]+)/.*" "\\1" target "${line}")
      list(FIND allowed_${stage} ${target} ok)
      if(ok EQUAL -1)
        file(RELATIVE_PATH where ${SOURCE_DIR} ${file})
        message(SEND_ERROR "${where}: ${stage}/ may not include ${target}/ (${line}): "
                           "its library does not link ${target}'s")
        math(EXPR problems "${problems} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()
message(STATUS "check_layers: ${problems} problems")
