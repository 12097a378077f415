#include "run_report/comparison_report.hpp"

#include "base/counted.hpp"

#include <nlohmann/json.hpp>

namespace twinraster::run_report {

nlohmann::ordered_json CompareJson(const NamedImage& a, const NamedImage& b, const Comparison& c,
                                   const std::optional<std::string>& diff) {
  using Json = nlohmann::ordered_json;
  Json out;
  out["format"] = kCompareJsonFormat;
  for (const NamedImage* image : {&a, &b}) {
    out[image == &a ? "a" : "b"] = {{"file", image->file}, {"width", image->width}, {"height", image->height}};
  }
  out["same_size"] = c.same_size;
  // Pixels are compared only between images of one size.
  out["differing_pixels"] = c.same_size ? Json(c.differing_pixels) : Json(nullptr);
  out["max_channel_difference"] = c.same_size ? Json(c.max_channel_difference) : Json(nullptr);
  out["identical"] = c.Equal();
  out["diff"] = diff ? Json(*diff) : Json(nullptr);
  return out;
}

std::string ComparisonText(const NamedImage& a, const NamedImage& b, const Comparison& c) {
  if (!c.same_size) {
    return "sizes differ: " + std::to_string(a.width) + " x " + std::to_string(a.height) + " and " +
           std::to_string(b.width) + " x " + std::to_string(b.height);
  }
  return ComparisonText(a.width, a.height, c);
}

std::string ComparisonText(std::uint32_t width, std::uint32_t height, const Comparison& c) {
  return std::to_string(width) + " x " + std::to_string(height) + ": " +
         Counted(c.differing_pixels, "differing pixel") + ", max channel difference " +
         std::to_string(c.max_channel_difference) + (c.Equal() ? " (identical)" : "");
}

}  // namespace twinraster::run_report
