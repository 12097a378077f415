// Command-line values of `verify --coverage`: a clear colour written R,G,B or #rrggbb, and a
// percentage. Each malformed value is a UsageError naming the option and what it expects; this
// file judges nothing.
#pragma once

#include "scene/scene.hpp"

#include <string>

namespace twinraster::cli {

// "255,0,255", "255, 0, 255" or "#ff00ff" (either case); throws UsageError otherwise.
Rgb8 ParseColourArgument(const std::string& option, const std::string& value);
// A decimal number in 0..100 ("0.5", "2"); throws UsageError otherwise.
double ParsePercentArgument(const std::string& option, const std::string& value);

}  // namespace twinraster::cli
