// SPDX-License-Identifier: MIT
#include <tutti/core/did_you_mean.hpp>

#include <algorithm>
#include <cctype>
#include <vector>

namespace tutti {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbours each cost one.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size();
  const std::size_t m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

}  // namespace

std::optional<std::string> closest_name(std::string_view typed,
                                        std::span<const std::string_view> known) {
  const std::string word = lower(typed);
  if (word.empty()) return std::nullopt;
  // A name that the typed word begins, up to a separator: fov → fov_deg.
  for (std::string_view name : known) {
    const std::string candidate = lower(name);
    if (candidate.size() > word.size() && candidate.starts_with(word) &&
        (candidate[word.size()] == '_' || candidate[word.size()] == '-')) {
      return std::string(name);
    }
  }
  // Edits of a word of one or two letters could be anything.
  if (word.size() < 3) return std::nullopt;
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (std::string_view name : known) {
    const std::size_t distance = edit_distance(word, lower(name));
    const std::size_t allowed = std::max<std::size_t>(1, std::min(word.size(), name.size()) / 3);
    if (distance <= allowed && (!best || distance < best_distance)) {
      best = std::string(name);
      best_distance = distance;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view typed, std::span<const std::string_view> known) {
  const std::optional<std::string> name = closest_name(typed, known);
  return name ? " (did you mean \"" + *name + "\"?)" : "";
}

}  // namespace tutti
