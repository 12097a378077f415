#include "run_report/image_notes.hpp"

#include <charconv>

namespace twinraster::run_report {

namespace {

constexpr const char* kDevice = "twinraster:device";
constexpr const char* kSubpixelBits = "twinraster:subPixelPrecisionBits";
constexpr const char* kStrictLines = "twinraster:strictLines";

const std::string* Find(const files::PngNotes& notes, const char* key) {
  for (const auto& [k, v] : notes) {
    if (k == key) return &v;
  }
  return nullptr;
}

}  // namespace

files::PngNotes NotesOf(const verify::DrawnBy& drawn_by) {
  return {{kDevice, drawn_by.device},
          {kSubpixelBits, std::to_string(drawn_by.rasterizes.subpixel_bits)},
          {kStrictLines, drawn_by.rasterizes.strict_lines ? "true" : "false"}};
}

std::optional<verify::DrawnBy> DrawnByOf(const files::PngNotes& notes) {
  const std::string *device = Find(notes, kDevice), *bits = Find(notes, kSubpixelBits),
                    *strict = Find(notes, kStrictLines);
  if (!device || !bits || !strict || (*strict != "true" && *strict != "false")) return std::nullopt;
  int n = -1;
  const auto [end, error] = std::from_chars(bits->data(), bits->data() + bits->size(), n);
  if (error != std::errc() || end != bits->data() + bits->size() || n < 0 || n > 24) return std::nullopt;
  return verify::DrawnBy{*device, {.subpixel_bits = n, .strict_lines = *strict == "true"}};
}

}  // namespace twinraster::run_report
