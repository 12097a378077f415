#include "scene/srgb.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster {

std::uint8_t SrgbByte(double linear) {
  const double c = std::clamp(std::isnan(linear) ? 0.0 : linear, 0.0, 1.0);
  const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(std::clamp(encoded, 0.0, 1.0) * 255.0));
}

Rgb8 SrgbColour(const glm::dvec4& linear) { return Rgb8{SrgbByte(linear.x), SrgbByte(linear.y), SrgbByte(linear.z)}; }

}  // namespace twinraster
