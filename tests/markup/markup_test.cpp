// The markup every page shares, on its own: escaping, links and numbers.
#include "markup/markup.hpp"

#include "support/catch.hpp"

#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

using namespace twinraster::markup;

TEST_CASE("Escape: markup, quotes, ampersands and control characters come out as text", "[markup]") {
  CHECK(Escape("<script>alert(\"x\")</script>") == "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;");
  CHECK(Escape("a&b 'c'") == "a&amp;b &#39;c&#39;");
  CHECK(Escape("tab\there\x01") == "tab\there\xEF\xBF\xBD");
  CHECK(Escape("plain") == "plain");
}

TEST_CASE("Href: file names become links that point at themselves", "[markup]") {
  CHECK(Href("../out/a b#1.png") == "../out/a%20b%231.png");
  CHECK(Href("thumbs/<x>\".png") == "thumbs/%3Cx%3E%22.png");
  CHECK(Href("x-y_z.~1/2.png") == "x-y_z.~1/2.png");
}

TEST_CASE("Number writes what printf's %.*g writes: random doubles of every size and round decimals", "[markup]") {
  std::mt19937_64 random(2026);
  int compared = 0;
  for (int i = 0; i < 200000; ++i) {
    double value = 0;
    switch (i % 3) {
      case 0: value = std::bit_cast<double>(random()); break;                                 // any bit pattern
      case 1: value = static_cast<double>(random() % 2000001) / 1000.0 - 1000.0; break;       // pixel-like
      default: value = std::ldexp(static_cast<double>(random() >> 11), -int(random() % 90));  // fractions
    }
    if (!std::isfinite(value)) continue;
    for (const int digits : {1, 4, 6, 10, 17}) {
      char expected[64];
      std::snprintf(expected, sizeof expected, "%.*g", digits, value);
      INFO(expected);
      CHECK(Number(value, digits) == expected);
      ++compared;
    }
  }
  CHECK(compared > 900000);
  CHECK(Number(0.5, 6) == "0.5");
  CHECK(Number(-0.0, 6) == "-0");
  CHECK(Number(1.5e6, 6) == "1.5e+06");
  CHECK(Number(std::numeric_limits<double>::quiet_NaN(), 6) == "nan");
  CHECK(Number(-std::numeric_limits<double>::infinity(), 6) == "-inf");
}
