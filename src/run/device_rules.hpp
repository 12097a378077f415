// The rules an image is judged by (subPixelPrecisionBits, strictLines) and where each came from: an
// option, the image's PNG notes, or neither, when the spec's loosest is assumed, so that every
// output can say what was assumed. It reads no file: cli/ hands it the notes and the options.
#pragma once

#include "verify/drawn_by.hpp"
#include "verify/verification.hpp"

#include <cstdint>
#include <optional>

namespace twinraster::run {

enum class RuleSource : std::uint8_t {
  kOption,   // --subpixel-bits or --strict-lines
  kNotes,    // the image's PNG notes (render writes them)
  kAssumed,  // neither: the spec's loosest (4 bits, non-strict lines)
};
const char* RuleSourceName(RuleSource source);  // "option", "notes", "assumed"

struct DeviceRules {
  verify::VerifyOptions rules;
  RuleSource subpixel_bits = RuleSource::kAssumed, strict_lines = RuleSource::kAssumed;
  bool AnyAssumed() const { return subpixel_bits == RuleSource::kAssumed || strict_lines == RuleSource::kAssumed; }
};

// Each option given, else what the notes say, else the spec's loosest.
DeviceRules ChooseDeviceRules(const std::optional<verify::DrawnBy>& notes, std::optional<int> subpixel_bits,
                              std::optional<bool> strict_lines);

}  // namespace twinraster::run
