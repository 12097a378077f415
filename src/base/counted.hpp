// Counts in words for every message and report: a count and its noun in agreement ("1 triangle",
// "2 triangles"), and the indices a count allows. It chooses between the forms it is given and
// knows no other grammar.
#pragma once

#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>

namespace twinraster {

// "1 vertex", "3 vertices": `plural` defaults to `singular` with an "s". Any integer type, as
// given: no conversion between signed and unsigned.
template <std::integral Count>
std::string Counted(Count n, std::string_view singular, std::string_view plural = {}) {
  std::string text = std::to_string(n) + " ";
  if (n == 1) return text.append(singular);
  return plural.empty() ? text.append(singular).append("s") : text.append(plural);
}

// What an index counted from 0 may be, after a message that said how many there are:
// ": give 0 to 4", ": give 0", or nothing when there are none to give.
inline std::string ValidIndices(std::uint64_t n) {
  if (n == 0) return "";
  return n == 1 ? ": give 0" : ": give 0 to " + std::to_string(n - 1);
}

}  // namespace twinraster
