// SPDX-License-Identifier: MIT
#include <tutti/humanoid/bone_names.hpp>

#include <algorithm>
#include <cctype>
#include <vector>

namespace tutti::humanoid {
namespace {

bool is_separator(char c) {
  return c == '_' || c == '.' || c == '-' || c == ' ' || c == ':' || c == '|' || c == '/';
}

bool is_lower(char c) { return std::islower(static_cast<unsigned char>(c)) != 0; }
bool is_upper(char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Words at separators, lower-to-upper changes ("ForeArm" -> fore, arm) and letter-digit changes
// ("Spine1" -> spine, 1), lower case.
std::vector<std::string> words(std::string_view text) {
  std::vector<std::string> out;
  std::string word;
  const auto flush = [&] {
    if (!word.empty()) out.push_back(word);
    word.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (is_separator(c)) {
      flush();
      continue;
    }
    if (!word.empty()) {
      const char previous = text[i - 1];
      const bool case_change = is_lower(previous) && is_upper(c);
      const bool digit_change = is_digit(previous) != is_digit(c);
      if (case_change || digit_change) flush();
    }
    word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  flush();
  return out;
}

// Rig-wide prefixes that say nothing about the bone.
bool is_prefix_word(const std::string& w) {
  static const char* const kPrefixes[] = {"mixamorig", "def", "org", "mch", "rig", "bip",
                                          "armature", "cc", "base", "j", "bip01", "bip001"};
  return std::any_of(std::begin(kPrefixes), std::end(kPrefixes),
                     [&](const char* p) { return w == p; });
}

}  // namespace

BoneName parse_bone_name(std::string_view name) {
  // Namespaces: "mixamorig:Hips", "Armature|Hips".
  const std::size_t cut = name.find_last_of(":|");
  if (cut != std::string_view::npos && cut + 1 < name.size()) name = name.substr(cut + 1);
  std::vector<std::string> w = words(name);
  BoneName out;
  // "Bip01": the digits split off; drop "bip" and a following number.
  for (std::size_t i = 0; i + 1 < w.size(); ++i) {
    if (w[i] == "bip" && is_digit(w[i + 1][0])) w.erase(w.begin() + static_cast<std::ptrdiff_t>(i) + 1);
  }
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const std::string& word = w[i];
    if (word == "left" || word == "l") {
      out.side = Side::left;
      continue;
    }
    if (word == "right" || word == "r") {
      out.side = Side::right;
      continue;
    }
    // Prefix words only at the front, and never the whole name.
    if (kept.empty() && i + 1 < w.size() && is_prefix_word(word)) continue;
    kept.push_back(word);
  }
  for (const std::string& word : kept) out.base += word;
  return out;
}

}  // namespace tutti::humanoid
