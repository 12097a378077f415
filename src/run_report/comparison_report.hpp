// How `render --backend both` and `compare` report a comparison, as text or JSON, and the format
// names their --json outputs carry.
#pragma once

#include "image/image.hpp"
#include "image/image_compare.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace twinraster::run_report {

// compare --json's "format"; any change to its keys or their meaning gets a new number
// (docs/json-output.md, docs/schemas/).
inline constexpr const char* kCompareJsonFormat = "twinraster.compare/1";

struct NamedImage {
  std::string file;
  std::uint32_t width = 0, height = 0;
};

// The whole `compare --json` object; `diff` is the diff image written, if one was.
nlohmann::ordered_json CompareJson(const NamedImage& a, const NamedImage& b, const Comparison& c,
                                   const std::optional<std::string>& diff);
std::string ComparisonText(const NamedImage& a, const NamedImage& b, const Comparison& c);
// Two images of one size, `width` x `height`.
std::string ComparisonText(std::uint32_t width, std::uint32_t height, const Comparison& c);

}  // namespace twinraster::run_report
