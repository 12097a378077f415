#include "verify/verification.hpp"

#include <sstream>

namespace twinraster::verify {

namespace {

std::string Colour(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

}  // namespace

std::string RangeText(const ColourRange& r) {
  if (r.lo == r.hi) return Colour(r.lo);
  const auto channel = [](int lo, int hi) { return lo == hi ? std::to_string(lo) : std::to_string(lo) + ".." + std::to_string(hi); };
  return "(" + channel(r.lo.r, r.hi.r) + ", " + channel(r.lo.g, r.hi.g) + ", " + channel(r.lo.b, r.hi.b) + ")";
}

std::string VerificationText(const Verification& v) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed;
  const double percent = 100.0 * v.UncertainFraction();
  if (v.Passed()) {
    s << "passes: " << v.certain << " px certain, " << v.uncertain << " uncertain (" << percent << " % of the "
      << v.covered << " covered), 0 violations";
  } else {
    s << "fails: " << v.violations << (v.violations == 1 ? " pixel is" : " pixels are") << " not allowed; worst at ("
      << v.worst->x << ", " << v.worst->y << "): " << Colour(v.worst->colour) << ", allowed ";
    for (std::size_t i = 0; i < v.worst->allowed.size(); ++i) s << (i ? " or " : "") << RangeText(v.worst->allowed[i]);
    s << "; " << v.certain << " px certain, " << v.uncertain << " uncertain";
  }
  s << " (subpixel bits " << v.subpixel_bits << ")";
  return s.str();
}

}  // namespace twinraster::verify
