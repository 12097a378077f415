// The browser module's native side: the fmaf proof's reference (exact on the constructed cases,
// and catching the double-rounding trap a naive fmaf falls into), the native fmaf's run with the
// digest the module's run must give (fmaf_expected.txt, checked in Chromium by check_module.py),
// and the embedded module's bytes or the reason they are missing.
#include "page_module/fmaf_check.hpp"
#include "page_module/module_blob.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

using namespace twinraster;

namespace {

std::uint32_t Bits(float f) { return std::bit_cast<std::uint32_t>(f); }

// The check's summary as the module's tr_fmaf_check writes it, without the first mismatch.
std::string Summary(const page_module::FmafCheck& check) {
  char line[96];
  std::snprintf(line, sizeof line, "%u cases, %u mismatches, digest %016llx", check.cases, check.mismatches,
                static_cast<unsigned long long>(check.digest));
  return line;
}

}  // namespace

TEST_CASE("ExactFmaf rounds once: midpoints nudged by a tiny c and signed zeros and overflow and subnormals") {
  using page_module::ExactFmaf;
  // 8388609 * 3 = 25165827: an odd 25-bit product, halfway between the floats 25165826 and 25165828.
  const float a = 8388609.0f, b = 3.0f;
  CHECK(Bits(ExactFmaf(a, b, 0.0f)) == Bits(25165828.0f));                    // the tie goes to even
  CHECK(Bits(ExactFmaf(a, b, std::ldexp(1.0f, -60))) == Bits(25165828.0f));   // just above: up
  CHECK(Bits(ExactFmaf(a, b, -std::ldexp(1.0f, -60))) == Bits(25165826.0f));  // just below: down
  CHECK(Bits(ExactFmaf(-a, b, std::ldexp(1.0f, -60))) == Bits(-25165826.0f));
  CHECK(Bits(ExactFmaf(3.0f, 5.0f, -15.0f)) == Bits(0.0f));   // exact cancellation: +0
  CHECK(Bits(ExactFmaf(-0.0f, 1.0f, -0.0f)) == Bits(-0.0f));  // -0 + -0
  CHECK(Bits(ExactFmaf(-0.0f, 1.0f, 0.0f)) == Bits(0.0f));
  const float max = std::numeric_limits<float>::max();
  CHECK(std::isinf(ExactFmaf(max, 1.0f, std::ldexp(1.0f, 103))));  // half an ulp over: the tie rounds up
  CHECK(Bits(ExactFmaf(max, 1.0f, std::ldexp(1.0f, 102))) == Bits(max));
  CHECK(Bits(ExactFmaf(max, 2.0f, -max)) == Bits(max));  // the product alone would overflow
  CHECK(Bits(ExactFmaf(std::ldexp(1.0f, -75), std::ldexp(1.0f, -75), 0.0f)) == Bits(0.0f));  // half the least: even
  CHECK(Bits(ExactFmaf(std::ldexp(1.5f, -75), std::ldexp(1.0f, -75), 0.0f)) == 1u);          // 3/4 of it: up
  CHECK(std::isnan(ExactFmaf(std::numeric_limits<float>::infinity(), 0.0f, 1.0f)));
}

TEST_CASE("ExactFmaf tells a correctly rounded fmaf from one that rounds to double first") {
  // (float)(a * b + c) in double rounds twice: on a midpoint product nudged by a c below a double's
  // last bit it lands on the tie, and the tie goes to even, against the nudge.
  int naive_wrong = 0;
  for (int k = 3; k < 64; k += 2) {
    const float a = static_cast<float>(((1 << 24) / k + 1) | 1), b = static_cast<float>(k);
    for (float c : {std::ldexp(1.0f, -40), -std::ldexp(1.0f, -40)}) {
      const float naive = static_cast<float>(static_cast<double>(a) * b + c);
      naive_wrong += Bits(naive) != Bits(page_module::ExactFmaf(a, b, c));
      CHECK(Bits(std::fmaf(a, b, c)) == Bits(page_module::ExactFmaf(a, b, c)));
    }
  }
  CHECK(naive_wrong > 10);
}

TEST_CASE(
    "The native fmaf equals ExactFmaf on 1.2 million random and the constructed triples with the module's digest") {
  const page_module::FmafCheck check = page_module::CheckFmaf(1, 1200000);
  CHECK(check.mismatches == 0);
  CHECK(check.cases > 1400000);
  std::string expected = test::ReadFile(test::SourcePath("tests/page_module/fmaf_expected.txt"));
  while (!expected.empty() && expected.back() == '\n') expected.pop_back();
  CHECK(Summary(check) == expected);
}

TEST_CASE("The embedded browser module is a WebAssembly binary or its absence is explained in one line") {
  const auto bytes = page_module::ModuleBytes();
  const std::string_view reason = page_module::ModuleMissingReason();
  if (bytes.empty()) {
    CHECK(reason.starts_with("this build has no browser module: "));
    CHECK(reason.find('\n') == std::string_view::npos);
    return;
  }
  CHECK(reason.empty());
  REQUIRE(bytes.size() > 8);
  CHECK(std::string(bytes.begin(), bytes.begin() + 8) == std::string("\0asm\1\0\0\0", 8));
  CHECK(bytes.size() < 700 * 1024);  // the page's budget (docs/building.md)
}
