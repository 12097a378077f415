#include "run/device_rules.hpp"

namespace twinraster::run {

const char* RuleSourceName(RuleSource source) {
  switch (source) {
    case RuleSource::kOption: return "option";
    case RuleSource::kNotes: return "notes";
    case RuleSource::kAssumed: break;
  }
  return "assumed";
}

DeviceRules ChooseDeviceRules(const std::optional<verify::DrawnBy>& notes, std::optional<int> subpixel_bits,
                              std::optional<bool> strict_lines) {
  DeviceRules d;
  if (notes) {
    d.rules = notes->rasterizes;
    d.subpixel_bits = d.strict_lines = RuleSource::kNotes;
  }
  if (subpixel_bits) {
    d.rules.subpixel_bits = *subpixel_bits;
    d.subpixel_bits = RuleSource::kOption;
  }
  if (strict_lines) {
    d.rules.strict_lines = *strict_lines;
    d.strict_lines = RuleSource::kOption;
  }
  return d;
}

}  // namespace twinraster::run
