// One include for Catch2 2 (Debian 12) and Catch2 3 (Debian 13): the macros, Approx and a
// substring matcher under the same names in both.
#pragma once

#if __has_include(<catch2/catch_test_macros.hpp>)
// Catch2 3 split the single header; these are the parts the tests use.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_message.hpp>
#include <catch2/catch_session.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
using Catch::Approx;
#else
#include <catch2/catch.hpp>
#endif

#include <cstdio>
#include <cstdlib>
#include <string>

// Catch2 2 calls it Contains, Catch2 3 ContainsSubstring (its Contains is for ranges).
inline auto HasSubstring(const std::string& text) {
#if __has_include(<catch2/catch_test_macros.hpp>)
  return Catch::Matchers::ContainsSubstring(text);
#else
  return Catch::Matchers::Contains(text);
#endif
}

// A case with nothing to judge on this machine says so and is reported as skipped by CTest, never
// as passed: the process ends at once with kSkippedExitCode, which every test entry declares as its
// SKIP_RETURN_CODE (tests/CMakeLists.txt), and which tests/main.cpp never returns for a failure.
// Catch2 2 has no SKIP, so both versions end the process the same way. This relies on CTest
// running one case per process; run by hand, a binary stops at the first skipped case. Only for a
// case that holds no device (the end-of-run work that releases the shared GPU is not done), and
// only after REQUIREs: a CHECK that failed before it would be lost with the process.
namespace twinraster::test {
inline constexpr int kSkippedExitCode = 77;
}
#define TWINRASTER_SKIP(reason)                                \
  do {                                                         \
    std::printf("SKIPPED: %s\n", std::string(reason).c_str()); \
    std::fflush(stdout);                                       \
    std::_Exit(twinraster::test::kSkippedExitCode);            \
  } while (false)
