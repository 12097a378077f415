// "Did you mean ...?": the candidate closest to a mistyped word, for scene keys, commands and options.
#pragma once

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster {

// Levenshtein distance: insertions, deletions and substitutions, each costing one.
inline std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

// The closest candidate, or "" when none is close enough that a typo could explain it (at most
// about a third of the word changed).
template <typename Range>
std::string ClosestMatch(std::string_view word, const Range& candidates) {
  std::string best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const auto& candidate : candidates) {
    const std::size_t d = EditDistance(word, candidate);
    if (d < best_distance) best_distance = d, best = std::string(candidate);
  }
  return best_distance <= std::max<std::size_t>(1, word.size() / 3 + 1) ? best : std::string();
}

inline std::string ClosestMatch(std::string_view word, std::initializer_list<std::string_view> candidates) {
  return ClosestMatch<std::initializer_list<std::string_view>>(word, candidates);
}

}  // namespace twinraster
