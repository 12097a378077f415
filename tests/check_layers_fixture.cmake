# Proves that check_layers.cmake, with the lists tests/allowed_layers.cmake derives, catches an
# include its library's links do not allow: on tests/layers_fixture/ it must find exactly the one
# planted (src/low/low.hpp includes high/), derive top's list through high's link, and skip the
# folder the fixture does not build.
# Run as: cmake -DSOURCE_DIR=<repository> -DWORK_DIR=<empty folder> -P check_layers_fixture.cmake
set(fixture ${SOURCE_DIR}/tests/layers_fixture)
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${fixture} -B ${WORK_DIR} RESULT_VARIABLE failed OUTPUT_QUIET
                ERROR_VARIABLE error)
if(failed)
  message(FATAL_ERROR "configuring the fixture failed:\n${error}")
endif()
file(READ ${WORK_DIR}/allowed_layers.cmake allowed)
foreach(expected IN ITEMS "set(allowed_low \"low\")" "set(allowed_high \"high;low\")" "set(allowed_top \"top;high;low\")")
  string(FIND "${allowed}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the derived lists lack ${expected}:\n${allowed}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${fixture} -DALLOWED=${WORK_DIR}/allowed_layers.cmake -P
                        ${SOURCE_DIR}/tests/check_layers.cmake RESULT_VARIABLE failed OUTPUT_VARIABLE out
                ERROR_VARIABLE error)
string(REGEX REPLACE "[ \n]+" " " said "${out} ${error}")  # CMake wraps its error messages
foreach(expected IN ITEMS "src/low/low.hpp: low/ may not include high/" "src/unbuilt/: not built"
                          "check_layers: 1 problems")
  string(FIND "${said}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "check_layers.cmake did not say \"${expected}\":\n${out}${error}")
  endif()
endforeach()
if(NOT failed)
  message(FATAL_ERROR "check_layers.cmake found the violation but exited 0")
endif()
message(STATUS "check_layers_fixture: the planted violation is caught, and only it")
