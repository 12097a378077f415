# twinraster_options: what every twinraster target compiles with, linked PRIVATE (as
# $<BUILD_INTERFACE:...>) so that none of it reaches a project that uses twinraster.
# Warnings are errors, and no floating-point contraction, because the CPU twin must round exactly
# where lavapipe rounds (a fused multiply-add rounds once, not twice; clang contracts by default).
add_library(twinraster_options INTERFACE)
target_compile_options(twinraster_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -ffp-contract=off
                       $<$<BOOL:${TWINRASTER_WERROR}>:-Werror>)
# g++ 12 reports false positives inside std::string's operator+ at -O2 (GCC bug 105329); clang
# has no such warning (and no such flag).
target_compile_options(twinraster_options INTERFACE $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)

# twinraster_precompile_headers(target header...): parses the headers most of a target's files
# include once, not in every file. Only with clang: g++ (12 at least) loses a precompiled header's
# `#pragma GCC diagnostic` state, so libstdc++'s own suppressions are gone and its false positives
# (-Wstringop-overflow in std::string) fail the build under -Werror.
function(twinraster_precompile_headers target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()
