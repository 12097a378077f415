# The browser module in the native build: whether clang can build it here (tried at configure
# time), the module built from the same sources by a second CMake build with
# cmake/toolchains/wasm32-wasi.cmake (an ExternalProject in build/browser_module/), and its bytes
# embedded in twinraster_page_module_blob (src/page_module/module_blob.hpp). Without the toolchain,
# the blob has no bytes and one line saying why. TWINRASTER_BROWSER_MODULE: AUTO, ON (fail the
# configure without the toolchain), OFF. Included by src/page_module/CMakeLists.txt.
set(module_packages "Debian's clang, lld, llvm, wasi-libc, libc++-dev-wasm32 and libclang-rt-dev-wasm32")
set(module_blob_cpp ${CMAKE_CURRENT_BINARY_DIR}/generated/module_blob.cpp)

# Finds llvm-ar and llvm-ranlib (Debian's llvm) beside clang++: the module's stages are static
# libraries of wasm32 objects, which GNU ar stores without the symbol index wasm-ld needs.
function(twinraster_find_wasm_archiver)
  execute_process(COMMAND ${TWINRASTER_BROWSER_MODULE_CXX} -dumpversion OUTPUT_VARIABLE version
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  string(REGEX MATCH "^[0-9]+" major "${version}")
  find_program(TWINRASTER_BROWSER_MODULE_AR NAMES llvm-ar llvm-ar-${major})
  find_program(TWINRASTER_BROWSER_MODULE_RANLIB NAMES llvm-ranlib llvm-ranlib-${major})
endfunction()

# Archives a small wasm32-wasi C++ library with llvm-ar and links it into a reactor with what the
# module needs: libc++'s strings, wasi-libc, and compiler-rt's builtins (a 128-bit multiply). Sets
# the variable named by `out` to "" on success, else to the reason.
function(twinraster_try_wasm_toolchain out)
  if(NOT TWINRASTER_BROWSER_MODULE_CXX)
    set(${out} "clang++ was not found" PARENT_SCOPE)
    return()
  endif()
  twinraster_find_wasm_archiver()
  if(NOT TWINRASTER_BROWSER_MODULE_AR OR NOT TWINRASTER_BROWSER_MODULE_RANLIB)
    set(${out} "llvm-ar and llvm-ranlib were not found" PARENT_SCOPE)
    return()
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/wasm_toolchain_check)
  file(REMOVE ${dir}/libcheck.a)
  file(WRITE ${dir}/square.cpp [=[
#include <string>
unsigned square_digits(unsigned long long a) {
  const unsigned __int128 square = static_cast<unsigned __int128>(a) * a;
  return static_cast<unsigned>(std::to_string(a).size() + static_cast<unsigned>(square >> 64));
}
]=])
  file(WRITE ${dir}/check.cpp [=[
unsigned square_digits(unsigned long long a);
extern "C" __attribute__((export_name("check"))) unsigned check(unsigned long long a) { return square_digits(a); }
]=])
  set(cxx ${TWINRASTER_BROWSER_MODULE_CXX} --target=wasm32-wasi -std=c++20 -O1)
  execute_process(COMMAND ${cxx} -c ${dir}/square.cpp -o ${dir}/square.o
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(result EQUAL 0)
    execute_process(COMMAND ${TWINRASTER_BROWSER_MODULE_AR} qcs ${dir}/libcheck.a ${dir}/square.o
                    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  endif()
  if(result EQUAL 0)
    execute_process(COMMAND ${cxx} -mexec-model=reactor ${dir}/check.cpp ${dir}/libcheck.a -o ${dir}/check.wasm
                    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  endif()
  if(result EQUAL 0)
    set(${out} "" PARENT_SCOPE)
  else()
    string(REGEX MATCH "[^\n]*error[^\n]*" first_error "${output}")
    set(${out} "${TWINRASTER_BROWSER_MODULE_CXX} could not link a wasm32-wasi C++ module (${first_error})" PARENT_SCOPE)
  endif()
endfunction()

set(module_reason "")
if(TWINRASTER_BROWSER_MODULE STREQUAL "OFF")
  set(module_reason "this build has no browser module: it was configured with -DTWINRASTER_BROWSER_MODULE=OFF")
elseif(TWINRASTER_BROWSER_MODULE STREQUAL "AUTO" AND NOT PROJECT_IS_TOP_LEVEL)
  # A project that adds twinraster with add_subdirectory links its libraries; building a second
  # copy of them for the browser would only cost it minutes.
  set(module_reason "this build has no browser module: twinraster is part of another project's build")
else()
  find_program(TWINRASTER_BROWSER_MODULE_CXX clang++)
  twinraster_try_wasm_toolchain(problem)
  if(problem)
    set(module_reason "this build has no browser module: clang's wasm32-wasi target (${module_packages}) was not found when it was configured")
    if(TWINRASTER_BROWSER_MODULE STREQUAL "ON")
      message(FATAL_ERROR "TWINRASTER_BROWSER_MODULE=ON, but ${problem}: install ${module_packages}")
    endif()
    message(STATUS "Browser module: none (${problem}); install ${module_packages} to embed it")
  endif()
endif()

add_library(twinraster_page_module_blob STATIC ${module_blob_cpp})
twinraster_stage_library(twinraster_page_module_blob)

if(module_reason)
  unset(TWINRASTER_BROWSER_MODULE_WASM CACHE)  # tests/page_module/ runs the browser's cases only with a module
  execute_process(COMMAND ${CMAKE_COMMAND} -DMODULE= "-DREASON=${module_reason}" -DOUTPUT=${module_blob_cpp}
                          -P ${PROJECT_SOURCE_DIR}/cmake/module_blob.cmake COMMAND_ERROR_IS_FATAL ANY)
  return()
endif()

message(STATUS "Browser module: built with ${TWINRASTER_BROWSER_MODULE_CXX} and ${TWINRASTER_BROWSER_MODULE_AR} for wasm32-wasi and embedded")
include(ExternalProject)
set(TWINRASTER_BROWSER_MODULE_DIR ${PROJECT_BINARY_DIR}/browser_module CACHE INTERNAL "")
set(TWINRASTER_BROWSER_MODULE_WASM ${TWINRASTER_BROWSER_MODULE_DIR}/src/page_module/twinraster_page.wasm
    CACHE INTERNAL "The browser module the native build embeds")
set(launcher "")
if(CMAKE_CXX_COMPILER_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER})
endif()
# Built at every build (the module's sources are most of the project's), which costs a make's
# look at its files when nothing changed; by the same make as the native build (its jobs).
ExternalProject_Add(twinraster_browser_module
  SOURCE_DIR ${PROJECT_SOURCE_DIR}
  BINARY_DIR ${TWINRASTER_BROWSER_MODULE_DIR}
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/cmake/toolchains/wasm32-wasi.cmake
             -DCMAKE_AR=${TWINRASTER_BROWSER_MODULE_AR} -DCMAKE_RANLIB=${TWINRASTER_BROWSER_MODULE_RANLIB}
             -DCMAKE_BUILD_TYPE=Release
             -DTWINRASTER_BROWSER_MODULE_BUILD=ON -DTWINRASTER_WERROR=${TWINRASTER_WERROR} ${launcher}
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON
  BUILD_BYPRODUCTS ${TWINRASTER_BROWSER_MODULE_WASM})
add_custom_command(OUTPUT ${module_blob_cpp}
  COMMAND ${CMAKE_COMMAND} -DMODULE=${TWINRASTER_BROWSER_MODULE_WASM} -DOUTPUT=${module_blob_cpp}
          -P ${PROJECT_SOURCE_DIR}/cmake/module_blob.cmake
  DEPENDS ${TWINRASTER_BROWSER_MODULE_WASM} twinraster_browser_module ${PROJECT_SOURCE_DIR}/cmake/module_blob.cmake
  COMMENT "Embedding the browser module"
  VERBATIM)
