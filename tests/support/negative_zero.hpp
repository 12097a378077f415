// Whether a text shows a negative zero as a number of its own ("-0", as %g writes -0.0), which a
// reader takes for a sign error; it does not flag "-0.5", "-0.0" (JSON's) nor an exponent ("1e-05").
#pragma once

#include <cctype>
#include <string_view>

namespace twinraster::test {

inline bool HasNegativeZero(std::string_view text) {
  for (std::size_t at = text.find("-0"); at != std::string_view::npos; at = text.find("-0", at + 1)) {
    const unsigned char before = at == 0 ? ' ' : static_cast<unsigned char>(text[at - 1]);
    const unsigned char after = at + 2 < text.size() ? static_cast<unsigned char>(text[at + 2]) : ' ';
    const bool inside_a_word = std::isalnum(before) || before == '.';
    const bool goes_on = std::isdigit(after) || after == '.';
    if (!inside_a_word && !goes_on) return true;
  }
  return false;
}

}  // namespace twinraster::test
