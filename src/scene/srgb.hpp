// glTF's colours are linear; the chapter's colours are the bytes the image holds, which viewers
// show as sRGB. This is the one place a linear colour becomes a byte. It does not light anything.
#pragma once

#include "scene/scene.hpp"

#include <glm/vec4.hpp>

#include <cstdint>

namespace twinraster {

// sRGB's transfer function (IEC 61966-2-1): 12.92·c up to c = 0.0031308, 1.055·c^(1/2.4) - 0.055
// above; clamped to [0, 1] first, then rounded to the nearest of 0..255. Exact for every double:
// the byte is looked up among the 255 linear values where it changes, which are precomputed.
std::uint8_t SrgbByte(double linear);

// The three channels of a linear RGBA colour (alpha is not drawn: the image is opaque).
Rgb8 SrgbColour(const glm::dvec4& linear);

}  // namespace twinraster
