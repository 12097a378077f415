# Keeps the README's layout section true: it names every entry directly under src/, tests/ and
# docs/, and every path it names exists; and docs/README.md, the manual's index, has a row for
# every entry of docs/.
# Run as: cmake -DSOURCE_DIR=<repository> -P check_layout.cmake
#
# The layout section runs from the line "## Layout" to the next "## " heading. A path there is a
# `backticked` word with no spaces, not starting with "-", holding a "/" or a "."; every path is
# relative to the repository, a folder ends with "/" and a file does not.
set(problems 0)
macro(problem text)
  message(SEND_ERROR "${text}")
  math(EXPR problems "${problems} + 1")
endmacro()

file(READ ${SOURCE_DIR}/README.md readme)
string(FIND "${readme}" "\n## Layout\n" start)
if(start EQUAL -1)
  message(FATAL_ERROR "README.md: no \"## Layout\" section")
endif()
string(SUBSTRING "${readme}" ${start} -1 section)
string(SUBSTRING "${section}" 1 -1 rest)
string(FIND "${rest}" "\n## " end)
if(NOT end EQUAL -1)
  string(SUBSTRING "${rest}" 0 ${end} section)
endif()

string(REGEX MATCHALL "`[^` \t\n]+`" words "${section}")
set(named "")
foreach(word IN LISTS words)
  string(REGEX REPLACE "^`(.*)`$" "\\1" path "${word}")
  if(path MATCHES "^-" OR NOT path MATCHES "[/.]")
    continue()
  endif()
  list(APPEND named "${path}")
  if(path MATCHES "/$")
    if(NOT IS_DIRECTORY ${SOURCE_DIR}/${path})
      problem("README.md, layout: ${path} names a folder that does not exist")
    endif()
  elseif(IS_DIRECTORY ${SOURCE_DIR}/${path})
    problem("README.md, layout: ${path} is a folder; write it as ${path}/")
  elseif(NOT EXISTS ${SOURCE_DIR}/${path})
    problem("README.md, layout: ${path} names a file that does not exist")
  endif()
endforeach()

file(READ ${SOURCE_DIR}/docs/README.md index)

# Every entry of the three folders, but hidden ones and Python's caches (written by running a
# script, never committed).
foreach(top IN ITEMS src tests docs)
  file(GLOB entries LIST_DIRECTORIES true RELATIVE ${SOURCE_DIR}/${top} ${SOURCE_DIR}/${top}/*)
  foreach(entry IN LISTS entries)
    if(entry MATCHES "^\\." OR entry STREQUAL "__pycache__")
      continue()
    endif()
    if(IS_DIRECTORY ${SOURCE_DIR}/${top}/${entry})
      set(expected "${top}/${entry}/")
    else()
      set(expected "${top}/${entry}")
    endif()
    list(FIND named "${expected}" found)
    if(found EQUAL -1)
      problem("README.md, layout: ${expected} is not named; add it with what it holds")
    endif()
    if(top STREQUAL "docs" AND NOT entry STREQUAL "README.md")
      # A row of the index's tables that starts with the entry's link: | [name](name) | or
      # | [folder/](folder) |.
      if(IS_DIRECTORY ${SOURCE_DIR}/docs/${entry})
        set(row "\n| [${entry}/](${entry}) |")
      else()
        set(row "\n| [${entry}](${entry}) |")
      endif()
      string(FIND "${index}" "${row}" listed)
      if(listed EQUAL -1)
        string(STRIP "${row}" row)
        problem("docs/README.md: ${entry} has no row of its own; add one starting ${row}")
      endif()
    endif()
  endforeach()
endforeach()

list(LENGTH named count)
message(STATUS "check_layout: ${count} paths named, ${problems} problems")
