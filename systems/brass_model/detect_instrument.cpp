// SPDX-License-Identifier: MIT
// detect_instrument: which known instrument a score part is written for, from its name (words
// in several languages, plurals) and else its General MIDI program.
#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/music/part_names.hpp>

namespace tutti::brass_model {
namespace {

using Words = std::vector<std::string>;

// Part-name words and phrases: music/part_names.hpp.
Words words_of(std::string_view text) { return music::part_name_words(text); }

std::size_t longest_match(const Words& words, const std::vector<std::string>& phrases) {
  return music::longest_phrase(words, phrases);
}

// The key a name states ("in Bb", "in B flat", "in Es", "en Ut", "in Sib"), as a pitch class.
// German usage for a bare "B" (= B♭; "H" = B), since no modern brass instrument is in B natural.
std::optional<int> stated_key(const Words& words) {
  struct Name {
    std::string_view word;
    int pitch_class;
  };
  static constexpr Name kKeys[] = {
      {"c", 0},   {"d", 2},   {"e", 4},   {"f", 5},    {"g", 7},    {"a", 9},   {"b", 10},
      {"h", 11},  {"bb", 10}, {"b♭", 10}, {"eb", 3},   {"e♭", 3},   {"ab", 8},  {"a♭", 8},
      {"db", 1},  {"d♭", 1},  {"gb", 6},  {"g♭", 6},   {"es", 3},   {"as", 8},  {"des", 1},
      {"ges", 6}, {"do", 0},  {"ut", 0},  {"re", 2},   {"ré", 2},   {"mi", 4},  {"fa", 5},
      {"sol", 7}, {"la", 9},  {"si", 11}, {"sib", 10}, {"si♭", 10}, {"mib", 3}, {"mi♭", 3},
      {"lab", 8}, {"la♭", 8},
  };
  for (std::size_t i = 0; i + 1 < words.size(); ++i) {
    if (words[i] != "in" && words[i] != "en") continue;
    for (const Name& key : kKeys) {
      if (words[i + 1] != key.word) continue;
      int pc = key.pitch_class;
      if (i + 2 < words.size()) {
        const std::string& next = words[i + 2];
        if (next == "flat" || next == "bémol" || next == "bemol" || next == "bemolle") pc -= 1;
        if (next == "sharp" || next == "dièse" || next == "diesis") pc += 1;
      }
      return (pc + 12) % 12;
    }
  }
  return std::nullopt;
}

// The key a name states in front of the instrument ("C Trumpet", "Bb trumpets", German "B
// Trompete" = B♭): a key word right before one of `names`. "A" is left out (the article).
std::optional<int> key_before_name(const Words& words, const std::vector<std::string>& names) {
  struct Name {
    std::string_view word;
    int pitch_class;
  };
  static constexpr Name kKeys[] = {{"c", 0},   {"d", 2},   {"e", 4},   {"f", 5},  {"g", 7},
                                   {"b", 10},  {"bb", 10}, {"b♭", 10}, {"eb", 3}, {"e♭", 3},
                                   {"es", 3},  {"ut", 0}};
  for (std::size_t i = 0; i + 1 < words.size(); ++i) {
    for (const Name& key : kKeys) {
      if (words[i] != key.word) continue;
      const Words rest(words.begin() + static_cast<std::ptrdiff_t>(i + 1), words.end());
      if (longest_match({rest.front()}, names) > 0) return key.pitch_class;
    }
  }
  return std::nullopt;
}

int pitch_class(int semitones) { return ((semitones % 12) + 12) % 12; }

// Among instruments that fit equally well: a stated transposition, then a key in the name ("in
// C", "C Trumpet"), then the preferred one (the B♭ trumpet: most parts, and MIDI at concert
// pitch, are played on it), then the first.
const Instrument* pick(const std::vector<const Instrument*>& fits, const music::Part& part,
                       const Words& words) {
  if (fits.empty()) return nullptr;
  auto first = [&](auto&& pred) -> const Instrument* {
    const auto it = std::find_if(fits.begin(), fits.end(), pred);
    return it == fits.end() ? nullptr : *it;
  };
  if (part.transpose_semitones != 0) {
    if (const Instrument* i = first([&](const Instrument* c) {
          return c->transposition_semitones == part.transpose_semitones;
        })) {
      return i;
    }
  }
  std::optional<int> key = stated_key(words);
  if (!key) {
    for (const Instrument* candidate : fits) {
      if ((key = key_before_name(words, candidate->names))) break;
    }
  }
  if (key) {
    if (const Instrument* i = first(
            [&](const Instrument* c) { return pitch_class(c->transposition_semitones) == *key; })) {
      return i;
    }
  }
  if (const Instrument* i = first([&](const Instrument* c) { return c->preferred; })) return i;
  return fits.front();
}

bool brass_program(int program) { return program >= 56 && program <= 63; }

}  // namespace

const Instrument* detect_instrument(const music::Part& part, std::span<const Instrument> known) {
  if (part.percussion) return nullptr;
  const Words words = words_of(part.name);
  std::vector<const Instrument*> by_name;
  std::vector<const Instrument*> by_program;
  std::size_t best = 0;
  for (const Instrument& instrument : known) {
    if (longest_match(words, instrument.not_names) > 0) continue;
    std::size_t score = longest_match(words, instrument.names);
    if (brass_program(part.program)) {
      score = std::max(score, longest_match(words, instrument.ambiguous_names));
    }
    if (score > best) {
      best = score;
      by_name.clear();
    }
    if (score > 0 && score == best) by_name.push_back(&instrument);
    if (std::find(instrument.gm_programs.begin(), instrument.gm_programs.end(), part.program) !=
        instrument.gm_programs.end()) {
      by_program.push_back(&instrument);
    }
  }
  return pick(by_name.empty() ? by_program : by_name, part, words);
}

}  // namespace tutti::brass_model
