# Guards against tests that never run. Fails when
#   - a tests/**/*_test.cpp is compiled into no test binary (but those that need Vulkan, in a build
#     configured without it, and those that test such a build, in one with Vulkan);
#   - a test binary lists no test case;
#   - a binary's test cases and its CTest entries differ, in number or by name (a case CTest never
#     runs, or an entry that names no case: catch_discover_tests splits names at ';', and a split
#     entry would otherwise "pass" running nothing);
#   - any CTest entry is disabled, inverted (WILL_FAIL), passed or skipped by a regular expression
#     on its output, or skipped by an exit code other than TWINRASTER_SKIP's 77.
# A test binary is any executable target defined under tests/; they and their sources come from
# BUILD_DIR/test_binaries.txt (written by tests/CMakeLists.txt from the targets, so that a binary
# with no CTest entry at all is still looked at). A case run again on another lavapipe path is an
# extra entry named "<path> path: <case>" (tests/twin, tests/verify); it must name a real case too.
# It does not build anything, nor run any test case: it only asks each binary for its list.
# Run as:
#   cmake -DBUILD_DIR=<build> -DSOURCE_DIR=<source> [-DCATCH2_MAJOR=<2|3>] -P check_test_lists.cmake
cmake_policy(VERSION 3.25)  # IN_LIST, string(JSON)
if(NOT BUILD_DIR OR NOT SOURCE_DIR)
  message(FATAL_ERROR "check_test_lists: set -DBUILD_DIR and -DSOURCE_DIR")
endif()
if(NOT CATCH2_MAJOR)
  include(${BUILD_DIR}/check_test_lists_args.cmake)  # written by tests/CMakeLists.txt
endif()

# The binaries and the sources compiled into them.
file(STRINGS ${BUILD_DIR}/test_binaries.txt binary_lines)
set(compiled)
set(binaries)
foreach(line IN LISTS binary_lines)
  string(REPLACE "|" ";" parts "${line}")
  list(GET parts 0 binary)
  list(APPEND binaries "${binary}")
  list(LENGTH parts nparts)
  if(nparts GREATER 1)
    list(GET parts 1 source)
    list(APPEND compiled "${source}")
  endif()
endforeach()
list(REMOVE_DUPLICATES binaries)

# Every test file is in some binary, but those this build leaves out for having Vulkan or not
# (its tests_left_out.txt, written by tests/CMakeLists.txt).
set(left_out)
if(EXISTS ${BUILD_DIR}/tests_left_out.txt)
  file(STRINGS ${BUILD_DIR}/tests_left_out.txt left_out)
endif()
set(problems 0)
file(GLOB_RECURSE test_files ${SOURCE_DIR}/tests/*_test.cpp)
foreach(file IN LISTS test_files)
  if(NOT file IN_LIST compiled AND NOT file IN_LIST left_out)
    message(SEND_ERROR "test file in no test binary (add it to its folder's add_executable): ${file}")
    math(EXPR problems "${problems} + 1")
  endif()
endforeach()
list(LENGTH test_files nfiles)
list(LENGTH binaries nbinaries)
if(nfiles EQUAL 0 OR nbinaries EQUAL 0)
  message(FATAL_ERROR "check_test_lists: found ${nfiles} test files and ${nbinaries} test binaries")
endif()

# The CTest entries that run a test binary, as "binary|case".
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --show-only=json-v1 WORKING_DIRECTORY ${BUILD_DIR}
                OUTPUT_VARIABLE json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_test_lists: ctest --show-only failed in ${BUILD_DIR}")
endif()
string(JSON count LENGTH "${json}" tests)
set(entries)
set(path_entries)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON name GET "${json}" tests ${i} name)
  # No entry may pass without judging: not disabled, not inverted, not passed or skipped by its
  # output, and skipped only by the project's own code (TWINRASTER_SKIP, 77).
  string(JSON property_count ERROR_VARIABLE no_properties LENGTH "${json}" tests ${i} properties)
  if(NOT no_properties AND property_count GREATER 0)
    math(EXPR last_property "${property_count} - 1")
    foreach(k RANGE ${last_property})
      string(JSON property GET "${json}" tests ${i} properties ${k} name)
      string(JSON value GET "${json}" tests ${i} properties ${k} value)
      if((property MATCHES "^(DISABLED|WILL_FAIL)$" AND value)
         OR property MATCHES "^(PASS|SKIP)_REGULAR_EXPRESSION$"
         OR (property STREQUAL "SKIP_RETURN_CODE" AND NOT value EQUAL 77))
        message(SEND_ERROR "CTest entry \"${name}\" has ${property} ${value}: it could pass or skip without judging")
        math(EXPR problems "${problems} + 1")
      endif()
    endforeach()
  endif()
  string(JSON command_length ERROR_VARIABLE no_command LENGTH "${json}" tests ${i} command)
  if(no_command OR command_length LESS 1)
    continue()  # an entry whose executable was not built (catch_discover_tests found nothing)
  endif()
  string(JSON binary GET "${json}" tests ${i} command 0)
  if(NOT binary IN_LIST binaries)
    continue()  # not a test binary: this guard itself, the page checks, the fuzz run, ...
  endif()
  set(spec "")
  if(command_length GREATER 1)
    string(JSON spec GET "${json}" tests ${i} command 1)
  endif()
  # catch_discover_tests escapes , [ ] \ in the spec; undo that to compare with the plain names.
  string(REGEX REPLACE "\\\\(.)" "\\1" spec "${spec}")
  if(spec MATCHES "^-")
    message(SEND_ERROR "CTest entry \"${name}\" starts with '-': Catch2 reads it as an option, not a test name")
    math(EXPR problems "${problems} + 1")
  endif()
  string(REGEX REPLACE "^[^ ]+ path: " "" case_name "${name}")
  if(NOT spec STREQUAL case_name)
    message(SEND_ERROR "CTest entry \"${name}\" runs the Catch2 spec \"${spec}\": a name CTest split or changed")
    math(EXPR problems "${problems} + 1")
  endif()
  if(name STREQUAL case_name)
    list(APPEND entries "${binary}|${spec}")
  else()
    list(APPEND path_entries "${binary}|${spec}")
  endif()
endforeach()

# Catch2 2 and 3 spell "print the test names, nothing else" differently.
if(CATCH2_MAJOR EQUAL 3)
  set(list_names --list-tests --verbosity quiet)
else()
  set(list_names --list-test-names-only)
endif()

# Each binary's own list of cases against its entries, binary by binary.
set(ncases 0)
foreach(binary IN LISTS binaries)
  execute_process(COMMAND ${binary} ${list_names} OUTPUT_VARIABLE names RESULT_VARIABLE ignored TIMEOUT 120)
  string(REPLACE ";" "\\;" names "${names}")
  string(REPLACE "\n" ";" names "${names}")
  set(cases)
  foreach(name IN LISTS names)
    if(NOT name STREQUAL "")
      list(APPEND cases "${binary}|${name}")
    endif()
  endforeach()
  set(binary_entries)
  foreach(e IN LISTS entries)
    if(e MATCHES "^([^|]*)\\|" AND CMAKE_MATCH_1 STREQUAL binary)
      list(APPEND binary_entries "${e}")
    endif()
  endforeach()
  list(LENGTH cases case_count)
  list(LENGTH binary_entries entry_count)
  math(EXPR ncases "${ncases} + ${case_count}")
  if(case_count EQUAL 0)
    message(SEND_ERROR "test binary that lists no test case: ${binary}")
    math(EXPR problems "${problems} + 1")
  elseif(NOT case_count EQUAL entry_count)
    message(SEND_ERROR "test binary with ${case_count} test cases but ${entry_count} CTest entries: ${binary}")
    math(EXPR problems "${problems} + 1")
  endif()
  foreach(c IN LISTS cases)
    if(NOT c IN_LIST binary_entries)
      message(SEND_ERROR "test case never run by CTest: ${c}")
      math(EXPR problems "${problems} + 1")
    endif()
  endforeach()
  foreach(e IN LISTS binary_entries path_entries)
    if(e MATCHES "^([^|]*)\\|" AND CMAKE_MATCH_1 STREQUAL binary AND NOT e IN_LIST cases)
      message(SEND_ERROR "CTest entry that matches no test case: ${e}")
      math(EXPR problems "${problems} + 1")
    endif()
  endforeach()
endforeach()
list(LENGTH entries nentries)
list(LENGTH path_entries npath)
message(STATUS "check_test_lists: ${nfiles} test files in ${nbinaries} test binaries, ${ncases} Catch2 test cases, "
               "${nentries} CTest entries (and ${npath} on other lavapipe paths), ${problems} problems")
