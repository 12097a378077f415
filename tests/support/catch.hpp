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

#include <string>

// Catch2 2 calls it Contains, Catch2 3 ContainsSubstring (its Contains is for ranges).
inline auto HasSubstring(const std::string& text) {
#if __has_include(<catch2/catch_test_macros.hpp>)
  return Catch::Matchers::ContainsSubstring(text);
#else
  return Catch::Matchers::Contains(text);
#endif
}
