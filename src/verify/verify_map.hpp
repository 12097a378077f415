// The verification map: the image in grey, uncertain pixels tinted amber, violations pure red.
#pragma once

#include "image/image.hpp"
#include "verify/verification.hpp"

namespace twinraster::verify {

// Certain pixels: the image's luminance, faded halfway to white; uncertain: that grey blended
// with amber; violations: (255, 0, 0). Throws std::invalid_argument if the sizes differ.
Image VerificationMap(const Image& image, const Verification& verification);

}  // namespace twinraster::verify
