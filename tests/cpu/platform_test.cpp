// The platform (cpu/platform.hpp): the conversions as x86-64's instructions give them on every
// platform, denormals as zero for a stretch of work only, and which rules this platform can follow.
#include "cpu/platform.hpp"

#include "support/catch.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

using namespace twinraster::cpu;

TEST_CASE("platform: float to int rounds half to even, and anything that does not fit is INT32_MIN",
          "[cpu][platform]") {
  // The same values through a volatile give the same results: nothing here is folded away.
  volatile float half = 2.5f;
  CHECK(RoundHalfEvenToInt(half) == 2);
  CHECK(RoundHalfEvenToInt(0.5f) == 0);
  CHECK(RoundHalfEvenToInt(1.5f) == 2);
  CHECK(RoundHalfEvenToInt(2.5f) == 2);
  CHECK(RoundHalfEvenToInt(-2.5f) == -2);
  CHECK(RoundHalfEvenToInt(2.5000002f) == 3);
  constexpr std::int32_t kIndefinite = std::numeric_limits<std::int32_t>::min();
  CHECK(RoundHalfEvenToInt(std::numeric_limits<float>::quiet_NaN()) == kIndefinite);
  CHECK(RoundHalfEvenToInt(2147483648.0f) == kIndefinite);   // 2^31 does not fit; no saturation
  CHECK(RoundHalfEvenToInt(-2147483648.0f) == kIndefinite);  // -2^31 fits, and is the same value
  CHECK(RoundHalfEvenToInt(-3e9f) == kIndefinite);
}

TEST_CASE("platform: C's (int) truncates toward zero, INT32_MIN where C++ leaves it undefined", "[cpu][platform]") {
  // Through a volatile, as the rasterizer's values come: GCC folds a constant argument as a plain
  // C++ conversion, which saturates, where the instruction gives INT32_MIN.
  const auto truncate = [](float f) {
    volatile float v = f;
    return TruncateToInt(v);
  };
  CHECK(truncate(1.9f) == 1);
  CHECK(truncate(-1.9f) == -1);
  CHECK(truncate(-0.5f) == 0);
  constexpr std::int32_t kIndefinite = std::numeric_limits<std::int32_t>::min();
  CHECK(truncate(std::numeric_limits<float>::quiet_NaN()) == kIndefinite);
  CHECK(truncate(2147483648.0f) == kIndefinite);
  CHECK(truncate(2147483520.0f) == 2147483520);
}

TEST_CASE("platform: denormals as zero inside the stretch only, when this platform has the control",
          "[cpu][platform]") {
  const unsigned before = FloatControlWord();
  float tiny = 0;
  const std::uint32_t smallest = 1;  // the smallest positive denormal's bits
  std::memcpy(&tiny, &smallest, sizeof tiny);
  volatile float input = tiny;
  {
    const DenormalsAsZero flush(true);
    const float doubled = input * 2.0f;
    CHECK((doubled == 0.0f) == kHasDenormalsControl);  // read as 0: DAZ
  }
  CHECK(FloatControlWord() == before);
  CHECK(input * 2.0f != 0.0f);  // denormals are back
  {
    const DenormalsAsZero off(false);
    CHECK(input * 2.0f != 0.0f);
  }
}

TEST_CASE("platform: which rules it can follow", "[cpu][platform]") {
  CHECK(CanFollow(RasterRules{}));
  CHECK(CanFollow(RasterRules{.rasterizer = Rasterizer::kSwiftShader, .flush_denormals = true}) ==
        kHasDenormalsControl);
#if defined(__x86_64__)
  CHECK(kHasDenormalsControl);
  CHECK(std::string(ReadCpuFeatures().arch) == "x86-64");
  CHECK(ReadCpuFeatures().sse2);  // every x86-64 CPU has it
#endif
}
