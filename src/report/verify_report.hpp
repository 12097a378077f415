// How `verify` and `render --verify` report a verification, as JSON (twinraster.verify/2) or as
// the sentence render prints about a GPU image that differs from the twin's.
#pragma once

#include "verify/verification.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace twinraster {

inline constexpr const char* kVerifyJsonFormat = "twinraster.verify/2";

// The verdict and counts, without file names: render nests it, verify adds its files around it.
nlohmann::ordered_json VerificationJson(const verify::Verification& v, const std::optional<std::string>& map,
                                        double verify_ms);

// "the images differ in 37 px, all within what Vulkan allows (...)" or
// "12 px are not allowed: first at (x, y) ..."
std::string DifferenceVerdict(std::uint64_t differing_pixels, const verify::Verification& v);

}  // namespace twinraster
