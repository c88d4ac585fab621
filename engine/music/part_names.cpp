// SPDX-License-Identifier: MIT
#include <tutti/music/part_names.hpp>

#include <algorithm>

namespace tutti::music {

std::vector<std::string> part_name_words(std::string_view text) {
  std::vector<std::string> words;
  std::string word;
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if ((c >= 'a' && c <= 'z') || c >= 0x80) {
      word += ch;
    } else if (c >= 'A' && c <= 'Z') {
      word += static_cast<char>(c - 'A' + 'a');
    } else if (!word.empty()) {
      words.push_back(std::move(word));
      word.clear();
    }
  }
  if (!word.empty()) words.push_back(std::move(word));
  return words;
}

bool has_phrase(const std::vector<std::string>& words, const std::vector<std::string>& phrase) {
  if (phrase.empty() || phrase.size() > words.size()) return false;
  for (std::size_t start = 0; start + phrase.size() <= words.size(); ++start) {
    bool match = true;
    for (std::size_t k = 0; k < phrase.size() && match; ++k) {
      const std::string& w = words[start + k];
      const std::string& p = phrase[k];
      match = w == p || (k + 1 == phrase.size() && (w == p + "s" || w == p + "es"));
    }
    if (match) return true;
  }
  return false;
}

std::size_t longest_phrase(const std::vector<std::string>& words,
                           std::span<const std::string> phrases) {
  std::size_t best = 0;
  for (const std::string& phrase : phrases) {
    const std::vector<std::string> split = part_name_words(phrase);
    if (has_phrase(words, split)) best = std::max(best, split.size());
  }
  return best;
}

}  // namespace tutti::music
