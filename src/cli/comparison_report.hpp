// How `render --backend both` and `compare` report a comparison, as text or JSON.
#pragma once

#include "image/image.hpp"
#include "image/image_compare.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace twinraster {

nlohmann::ordered_json ComparisonJson(const Image& a, const Image& b, const Comparison& c);
std::string ComparisonText(const Image& a, const Image& b, const Comparison& c);

}  // namespace twinraster
