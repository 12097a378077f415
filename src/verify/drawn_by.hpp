// Who drew an image and how that device rasterizes: what a judgement needs to know of the device
// (its subPixelPrecisionBits and strictLines). It does not read or write them anywhere: render
// fills it from the device, and run_report/image_notes.hpp keeps it in a PNG's notes.
#pragma once

#include "verify/verification.hpp"

#include <string>

namespace twinraster::verify {

struct DrawnBy {
  std::string device;        // its deviceName, or "CPU twin"
  VerifyOptions rasterizes;  // its subPixelPrecisionBits and strictLines
};

}  // namespace twinraster::verify
