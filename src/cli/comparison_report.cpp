#include "cli/comparison_report.hpp"

#include <nlohmann/json.hpp>

namespace twinraster {

nlohmann::ordered_json ComparisonJson(const Image& a, const Image& b, const Comparison& c) {
  nlohmann::ordered_json out;
  out["width"] = a.width;
  out["height"] = a.height;
  if (!c.same_size) {
    out["other_width"] = b.width;
    out["other_height"] = b.height;
  }
  out["same_size"] = c.same_size;
  out["differing_pixels"] = c.same_size ? nlohmann::ordered_json(c.differing_pixels) : nullptr;
  out["max_channel_difference"] = c.same_size ? nlohmann::ordered_json(c.max_channel_difference) : nullptr;
  out["identical"] = c.Equal();
  return out;
}

std::string ComparisonText(const Image& a, const Image& b, const Comparison& c) {
  if (!c.same_size) {
    return "sizes differ: " + std::to_string(a.width) + " x " + std::to_string(a.height) + " and " +
           std::to_string(b.width) + " x " + std::to_string(b.height);
  }
  return std::to_string(a.width) + " x " + std::to_string(a.height) + ": " + std::to_string(c.differing_pixels) +
         " differing pixels, max channel difference " + std::to_string(c.max_channel_difference) +
         (c.Equal() ? " (identical)" : "");
}

}  // namespace twinraster
