// The project's own sine and cosine of degrees, tangent and hypotenuse, against quadruple
// precision: within 1 ulp on over a million angles (random ones in [-720, 720], every integer and
// half-integer degree in [-3600, 3600], magnitudes up to a scene's 1e12 degrees), exact at the
// quarter turns, odd, even and periodic. Each sweep prints its worst error, how many results are
// not the double nearest the truth, and on how many angles the expression the chain used before,
// glibc's std::sin and std::cos of degrees·π/180, gives other bits.
#include "base/trigonometry.hpp"

#include "support/catch.hpp"
#include "support/quad_reference.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

// A fixed stream of doubles uniform in [low, high), the same on every machine (splitmix64).
class Angles {
 public:
  explicit Angles(std::uint64_t seed) : state_(seed) {}
  double Next(double low, double high) {
    state_ += 0x9e3779b97f4a7c15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return low + (high - low) * std::ldexp(static_cast<double>(z >> 11), -53);
  }

 private:
  std::uint64_t state_;
};

#ifdef TWINRASTER_QUAD_REFERENCE

using test::Quad;

// sin and cos of `degrees`° in quadruple precision. The angle is first brought to |t| ≤ 45° by
// exact steps (fmod by 360, then whole quarter turns), so the reference keeps its 113 bits near
// the zeros of sin and cos too.
struct QuadSineCosine {
  Quad sine, cosine;
};
QuadSineCosine Reference(double degrees) {
  const double r = std::fmod(degrees, 360.0);
  const double quarters = std::round(r / 90.0);
  const Quad x = static_cast<Quad>(r - 90.0 * quarters) * test::QuadPi() / 180;
  const Quad s = test::sinq(x), c = test::cosq(x);
  switch ((static_cast<int>(quarters) % 4 + 4) % 4) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
  }
}

// What a sweep measured.
struct Sweep {
  std::size_t angles = 0;
  double worst = 0;               // ulp
  double worst_at = 0;            // degrees
  std::size_t not_nearest = 0;    // results other than the double nearest the truth
  std::size_t glibc_differs = 0;  // angles where std::sin or std::cos of degrees·π/180 gives other bits
  std::size_t glibc_over_one = 0;

  void Add(double degrees) {
    ++angles;
    const SineCosine own = SineCosineOfDegrees(degrees);
    const QuadSineCosine truth = Reference(degrees);
    for (const auto& [value, exact] : {std::pair{own.sine, truth.sine}, std::pair{own.cosine, truth.cosine}}) {
      const double error = test::UlpError(value, exact);
      if (error > worst) worst = error, worst_at = degrees;
      if (!test::CorrectlyRounded(value, exact)) ++not_nearest;
    }
    const double theta = degrees * std::numbers::pi / 180.0;  // rotation.cpp's expression before
    const double s = std::sin(theta), c = std::cos(theta);
    if (s != own.sine || c != own.cosine) ++glibc_differs;
    if (test::UlpError(s, truth.sine) >= 1 || test::UlpError(c, truth.cosine) >= 1) ++glibc_over_one;
  }

  void Print(const std::string& what) const {
    std::printf(
        "%s: %zu angles; worst error %.4f ulp (at %.17g degrees); %zu of %zu results not the nearest double; "
        "std::sin/std::cos of degrees*pi/180 (glibc) give other bits on %zu angles (%.2f %%), 1 ulp or more "
        "off on %zu\n",
        what.c_str(), angles, worst, worst_at, not_nearest, 2 * angles, glibc_differs,
        100.0 * static_cast<double>(glibc_differs) / static_cast<double>(angles), glibc_over_one);
  }
};

#endif

void NeedQuadReference() {
#ifndef TWINRASTER_QUAD_REFERENCE
  TWINRASTER_SKIP("no __float128 with libquadmath on this platform: nothing to measure against");
#endif
}

}  // namespace

TEST_CASE("Own sine and cosine: within 1 ulp on a million random angles in [-720 720] degrees") {
  NeedQuadReference();
#ifdef TWINRASTER_QUAD_REFERENCE
  Sweep sweep;
  Angles angles(40);
  for (int i = 0; i < 1'000'000; ++i) sweep.Add(angles.Next(-720, 720));
  sweep.Print("random in [-720, 720]");
  CHECK(sweep.worst < 1.0);
  CHECK(sweep.not_nearest < sweep.angles / 1000);  // faithful, and nearly always the nearest double
#endif
}

TEST_CASE("Own sine and cosine: within 1 ulp on every integer and half-integer degree in [-3600 3600]") {
  NeedQuadReference();
#ifdef TWINRASTER_QUAD_REFERENCE
  Sweep sweep;
  for (int half = -7200; half <= 7200; ++half) sweep.Add(half / 2.0);
  sweep.Print("integers and halves in [-3600, 3600]");
  CHECK(sweep.worst < 1.0);
#endif
}

TEST_CASE("Own sine and cosine: within 1 ulp on large angles up to a scene's 1e12 degrees") {
  NeedQuadReference();
#ifdef TWINRASTER_QUAD_REFERENCE
  Sweep sweep;
  Angles angles(12);
  for (int i = 0; i < 200'000; ++i) {
    const double magnitude = std::pow(10.0, angles.Next(3, 12));  // 1e3 to 1e12, as many per decade
    sweep.Add(angles.Next(-1, 1) * magnitude);
  }
  for (const double d : {1e12, -1e12, 1e12 - 0.5, 999'999'999'999.75, 0x1p39, 1e-300, -5e-324, 1e-10, 45.0})
    sweep.Add(d);
  sweep.Print("magnitudes 1e3 to 1e12");
  CHECK(sweep.worst < 1.0);
#endif
}

TEST_CASE("Own sine and cosine of the rounded radians degrees*pi/180 as the demos compute them: within 1 ulp") {
  NeedQuadReference();
#ifdef TWINRASTER_QUAD_REFERENCE
  Angles angles(180);
  std::vector<double> degrees;
  for (int half = -7200; half <= 7200; ++half) degrees.push_back(half / 2.0);
  for (int i = 0; i < 300'000; ++i) degrees.push_back(angles.Next(-720, 720));
  for (int i = 0; i < 20'000; ++i) degrees.push_back(angles.Next(-1, 1) * std::pow(10.0, angles.Next(3, 12)));
  double worst = 0;
  std::size_t not_nearest = 0, glibc_differs = 0;
  for (const double d : degrees) {
    const double x = d * std::numbers::pi / 180.0;
    const SineCosine own = SineCosineOfRoundedRadians(d);
    const Quad s = test::sinq(x), c = test::cosq(x);
    worst = std::max({worst, test::UlpError(own.sine, s), test::UlpError(own.cosine, c)});
    not_nearest += !test::CorrectlyRounded(own.sine, s) + !test::CorrectlyRounded(own.cosine, c);
    if (own.sine != std::sin(x) || own.cosine != std::cos(x)) ++glibc_differs;
  }
  std::printf(
      "rounded radians: %zu angles; worst error %.4f ulp; %zu results not the nearest double; glibc's "
      "std::sin/std::cos of the same double give other bits on %zu angles\n",
      degrees.size(), worst, not_nearest, glibc_differs);
  CHECK(worst < 1.0);
  CHECK(SineCosineOfRoundedRadians(-30).sine == -0.49999999999999994);  // the demos' sin -30°
  CHECK(SineCosineOfRoundedRadians(180).sine == 1.2246467991473532e-16);
#endif
}

TEST_CASE("Own sine and cosine: exact at the quarter turns and sin 30 degrees is 0.5") {
  for (int quarter = -40; quarter <= 40; ++quarter) {
    const double degrees = 90.0 * quarter;
    const SineCosine sc = SineCosineOfDegrees(degrees);
    const int q = (quarter % 4 + 4) % 4;
    INFO(degrees << " degrees");
    CHECK(sc.sine == (q == 1 ? 1.0 : q == 3 ? -1.0 : 0.0));
    CHECK(sc.cosine == (q == 0 ? 1.0 : q == 2 ? -1.0 : 0.0));
    if (sc.sine == 0) CHECK(std::signbit(sc.sine) == std::signbit(degrees));  // IEEE 754's sinPi
    if (sc.cosine == 0) CHECK_FALSE(std::signbit(sc.cosine));
  }
  CHECK(std::signbit(SineCosineOfDegrees(-0.0).sine));
  CHECK(SineCosineOfDegrees(30).sine == 0.5);
  CHECK(SineCosineOfDegrees(150).sine == 0.5);
  CHECK(SineCosineOfDegrees(-30).sine == -0.5);
  CHECK(SineCosineOfDegrees(60).cosine == 0.5);
  CHECK(SineCosineOfDegrees(1e12).sine == SineCosineOfDegrees(1e12 - 360 * 2'777'777'777.0).sine);
  CHECK(std::isnan(SineCosineOfDegrees(std::numeric_limits<double>::infinity()).sine));
}

TEST_CASE("Own sine is odd and cosine even and both repeat every 360 degrees") {
  Angles angles(7);
  for (int i = 0; i < 100'000; ++i) {
    const double d = i < 14'401 ? (i - 7200) / 2.0 : angles.Next(-720, 720);
    const SineCosine plus = SineCosineOfDegrees(d), minus = SineCosineOfDegrees(-d);
    INFO(d << " degrees");
    REQUIRE(minus.sine == -plus.sine);
    REQUIRE(minus.cosine == plus.cosine);
    if (i < 14'401) {  // d + 360 is exact for these
      const SineCosine turned = SineCosineOfDegrees(d + 360);
      REQUIRE(turned.sine == plus.sine);
      REQUIRE(turned.cosine == plus.cosine);
      REQUIRE(SineCosineOfDegrees(90 - d).sine == plus.cosine);  // complementary angles
    }
    REQUIRE(plus.sine * plus.sine + plus.cosine * plus.cosine == Approx(1.0).epsilon(1e-15));
  }
}

TEST_CASE("Own tangent: within 1 ulp for half fields of view in (0 pi/2)") {
  NeedQuadReference();
#ifdef TWINRASTER_QUAD_REFERENCE
  Angles angles(24);
  double worst = 0;
  std::size_t not_nearest = 0, glibc_differs = 0;
  const double half_pi = std::numbers::pi / 2;
  std::vector<double> xs = {1e-300, 1e-8, std::numbers::pi / 4, std::nextafter(half_pi, 0.0), 0.5 * 0.8};
  for (int i = 0; i < 300'000; ++i) xs.push_back(angles.Next(0, half_pi));
  for (const double x : xs) {
    const double own = TangentOfRadians(x);
    const Quad truth = test::tanq(static_cast<Quad>(x));
    worst = std::max(worst, test::UlpError(own, truth));
    if (!test::CorrectlyRounded(own, truth)) ++not_nearest;
    if (std::tan(x) != own) ++glibc_differs;
    REQUIRE(TangentOfRadians(-x) == -own);
  }
  std::printf(
      "tangent: %zu angles in (0, pi/2); worst error %.4f ulp; %zu not the nearest double; std::tan differs on %zu\n",
      xs.size(), worst, not_nearest, glibc_differs);
  CHECK(worst < 1.0);
  CHECK(TangentOfRadians(0.0) == 0.0);
#endif
}

TEST_CASE("Own hypotenuse: within 2 ulp and no overflow or underflow in the squares") {
  CHECK(Hypotenuse(3, 4) == 5);
  CHECK(Hypotenuse(-3, 4, 12) == 13);
  CHECK(Hypotenuse(0, 0, 0) == 0);
  CHECK(Hypotenuse(3e300, 4e300) == Approx(5e300).epsilon(1e-15));
  CHECK(Hypotenuse(3e-310, 4e-310) == Approx(5e-310).epsilon(1e-6));  // subnormal: fewer digits
  CHECK(std::isinf(Hypotenuse(std::numeric_limits<double>::infinity(), 1)));
  CHECK(std::isnan(Hypotenuse(std::nan(""), 1)));
#ifdef TWINRASTER_QUAD_REFERENCE
  Angles values(3);
  double worst = 0;
  for (int i = 0; i < 100'000; ++i) {
    const double x = values.Next(-1e12, 1e12), y = values.Next(-1, 1), z = values.Next(-1e6, 1e6);
    const Quad truth = test::sqrtq(static_cast<Quad>(x) * x + static_cast<Quad>(y) * y + static_cast<Quad>(z) * z);
    worst = std::max(worst, test::UlpError(Hypotenuse(x, y, z), truth));
  }
  std::printf("hypotenuse: worst error %.4f ulp on 100000 random vectors\n", worst);
  CHECK(worst < 2.0);
#endif
}
