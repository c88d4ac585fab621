// SPDX-License-Identifier: MIT
// The keyboard family's part of `tutti scene new` (stage/family_draft.hpp): the piano parts go to
// the pianist at the piano plugin's default bench; each other keyboard instrument of
// content/piano/instruments.json (organ, harpsichord, synth, ...) named by a part or its General
// MIDI program gets a player of its own, sitting to the audience's left of the piano. Cameras:
// the pianist's hands, the treble end and the face (content/scenes/piano.json's), each other
// player's hands.
#include <tutti/piano/piano_plugin.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <tutti/music/part_names.hpp>
#include <tutti/piano_model/content_dir.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>
#include <tutti/stage/family_draft.hpp>

namespace tutti::piano {
namespace {

using nlohmann::ordered_json;

bool any_word_in(const std::vector<std::string>& words,
                 std::initializer_list<std::string_view> set) {
  for (const std::string& w : words) {
    for (std::string_view s : set) {
      // "Violins" and "Cellos" name their instrument too.
      if (w == s || (w.size() == s.size() + 1 && w.back() == 's' && w.starts_with(s))) return true;
    }
  }
  return false;
}

// A part named for a keyboard instrument.
bool names_a_keyboard(const std::vector<std::string>& words) {
  return any_word_in(words, {"piano", "pianoforte", "klavier", "clavier", "keyboard", "pno", "pf",
                             "fortepiano", "cembalo", "harpsichord", "clavecin"});
}

// A part named for something the pianist must not take: voices, strings, woodwinds, percussion
// and the rest of the orchestra (its General MIDI program is often left at 0, "piano", in
// MusicXML files that state none).
bool names_another_instrument(const std::vector<std::string>& words) {
  return any_word_in(
      words, {"soprano", "sopran", "alto", "contralto", "tenor", "bass", "basse", "baritone",
              "voice", "vocal", "vox", "choir", "chorus", "chor", "violin", "violino", "violini",
              "viola", "viole", "cello", "violoncello", "contrabass", "kontrabass", "strings",
              "flute", "flauto", "piccolo", "oboe", "clarinet", "clarinetto", "bassoon", "fagotto",
              "saxophone", "sax", "horn", "trumpet", "trombone", "tuba", "timpani", "timp",
              "percussion", "drum", "drums", "guitar", "harp", "organ", "celesta", "glockenspiel",
              "xylophone", "vibraphone", "marimba", "cymbal", "cymbals", "triangle", "recorder",
              "accordion", "banjo", "mandolin", "ukulele", "sitar", "lute"});
}

// The keyboard instrument a part is for: by name first; by General MIDI program unless the name
// says another instrument (files that state no program leave it at 0, "piano").
const piano_model::KeyboardInstrument* keyboard_of(
    const music::Part& info, const piano_model::KeyboardInstruments& instruments) {
  if (info.percussion) return nullptr;
  const std::vector<std::string> words = music::part_name_words(info.name);
  const piano_model::KeyboardInstrument* keyboard = instruments.recognise(words, -1);
  if (keyboard == nullptr && names_a_keyboard(words)) keyboard = instruments.find("piano");
  if (keyboard == nullptr && !names_another_instrument(words)) {
    keyboard = instruments.recognise({}, info.program);
  }
  return keyboard;
}

// A keyboard player other than the pianist: the instrument and the parts they play.
struct Keyboardist {
  const piano_model::KeyboardInstrument* instrument = nullptr;
  std::vector<int> parts;
};

// Keyboard player k's bench x: the pianist keeps the origin (where the piano plugin's default
// bench is); the others sit to the audience's left of it, a piano's width and some apart.
double keyboardist_x(bool with_piano, std::size_t k) {
  constexpr double kSpacing_m = 1.7;
  const std::size_t seat = k + (with_piano ? 1 : 0);
  return seat == 0 ? 0.0 : -kSpacing_m * static_cast<double>(seat);  // never -0.0 in the file
}

Result<piano_model::KeyboardInstruments> load_instruments() {
  return piano_model::KeyboardInstruments::load(
      piano_model::keyboard_instruments_path(piano_model::default_content_dir()));
}

ordered_json part_references(const music::Score& score, const std::vector<int>& parts) {
  ordered_json references = ordered_json::array();
  for (int p : parts) references.push_back(stage::draft_part_reference(score, p));
  return references;
}

}  // namespace

Result<std::vector<int>> PianoPlugin::draft_recognise(const music::Score& score,
                                                      std::span<const int> available) const {
  auto instruments = load_instruments();
  if (!instruments) return instruments.error();
  std::vector<int> parts;
  for (int p : available) {
    if (keyboard_of(score.parts[static_cast<std::size_t>(p)], *instruments) != nullptr) {
      parts.push_back(p);
    }
  }
  return parts;
}

Result<stage::FamilyDraft> PianoPlugin::draft(const music::Score& score,
                                              std::span<const int> parts,
                                              const stage::DraftPlace& place) const {
  auto instruments = load_instruments();
  if (!instruments) return instruments.error();
  std::vector<int> piano_parts;
  // The other instruments, one player each, in the order their parts come.
  std::vector<Keyboardist> keyboardists;
  for (int part : parts) {
    const piano_model::KeyboardInstrument* keyboard =
        keyboard_of(score.parts[static_cast<std::size_t>(part)], *instruments);
    if (keyboard == nullptr) continue;
    if (keyboard->id == "piano") {
      piano_parts.push_back(part);
      continue;
    }
    auto same = std::find_if(keyboardists.begin(), keyboardists.end(),
                             [&](const Keyboardist& k) { return k.instrument == keyboard; });
    if (same == keyboardists.end()) {
      keyboardists.push_back(Keyboardist{keyboard, {}});
      same = keyboardists.end() - 1;
    }
    same->parts.push_back(part);
  }
  stage::FamilyDraft draft;
  const bool with_piano = !piano_parts.empty();
  if (!with_piano && keyboardists.empty()) return draft;
  const double x0 = place.origin_x;

  if (with_piano) draft.summary = "a pianist";
  for (const Keyboardist& k : keyboardists) {
    const std::string& who = k.instrument->player;
    const bool vowel = std::string_view("aeiou").find(who.front()) != std::string_view::npos;
    draft.summary += (draft.summary.empty() ? "" : " and ") + std::string(vowel ? "an " : "a ") + who;
  }

  // The pianist alone is written the older way ("pianist", at the default bench).
  if (with_piano && keyboardists.empty()) {
    ordered_json pianist{{"parts", part_references(score, piano_parts)}};
    if (x0 != 0.0) pianist["position_m"] = stage::draft_vec3(x0, 0.0, 0.6);
    draft.section.emplace_back("pianist", std::move(pianist));
  } else {
    ordered_json pianists = ordered_json::array();
    if (with_piano) {
      ordered_json pianist{{"parts", part_references(score, piano_parts)}};
      if (x0 != 0.0) pianist["position_m"] = stage::draft_vec3(x0, 0.0, 0.6);
      pianists.push_back(std::move(pianist));
    }
    for (std::size_t k = 0; k < keyboardists.size(); ++k) {
      pianists.push_back(ordered_json{
          {"instrument", keyboardists[k].instrument->id},
          {"parts", part_references(score, keyboardists[k].parts)},
          {"position_m", stage::draft_vec3(x0 + keyboardist_x(with_piano, k), 0.0, 0.6)},
          {"facing_deg", 180}});
    }
    draft.section.emplace_back("pianists", std::move(pianists));
  }

  // The benches' reach along x: each instrument about 0.8 m either side of its bench.
  draft.right_m = x0 + (with_piano ? 0.8 : keyboardist_x(false, 0) + 0.8);
  draft.left_m = x0 + (keyboardists.empty() ? -0.8
                                            : keyboardist_x(with_piano, keyboardists.size() - 1) -
                                                  0.8);
  if (with_piano) draft.left_m = std::min(draft.left_m, x0 - 0.8);

  if (with_piano) {
    // content/scenes/piano.json's cameras.
    const ordered_json overview = stage::draft_camera(place.alone ? "wide" : "piano", x0 + 2.4,
                                                      1.55, 3.0, x0, 0.95, 0.25, 40.0);
    if (keyboardists.empty() && place.alone) draft.wide_camera_alone = overview;
    if (!place.alone) draft.cameras.push_back(overview);
    draft.cameras.push_back(
        stage::draft_camera("piano_hands", x0 + 0.55, 1.45, 0.75, x0, 0.74, -0.05, 38.0));
    draft.cameras.push_back(
        stage::draft_camera("piano_treble_end", x0 + 1.25, 0.98, 0.3, x0 - 0.1, 0.76, -0.02, 32.0));
    draft.cameras.push_back(
        stage::draft_camera("piano_face", x0 - 0.9, 1.3, -0.35, x0, 1.15, 0.6, 34.0));
    stage::DraftedGroup group{"piano", piano_parts, {"piano_hands", "piano_treble_end", "piano_face"}};
    if (!place.alone) group.cameras.push_back("piano");
    draft.groups.push_back(std::move(group));
  }
  // Each other keyboard player: their hands from over the right shoulder, as the pianist's, and
  // as much higher as the console stands raised (an organ's manual over its pedalboard).
  for (std::size_t k = 0; k < keyboardists.size(); ++k) {
    const double x = x0 + keyboardist_x(with_piano, k);
    const std::string name = keyboardists[k].instrument->id + "_hands";
    const auto& pedalboard = keyboardists[k].instrument->pedalboard;
    const double raise_m = pedalboard ? pedalboard->seat_raise_mm / 1000.0 : 0.0;
    draft.cameras.push_back(stage::draft_camera(name, x + 0.55, 1.45 + raise_m, 0.75, x,
                                                0.74 + raise_m, -0.05, 38.0));
    draft.groups.push_back({keyboardists[k].instrument->id, keyboardists[k].parts, {name}});
  }
  return draft;
}

}  // namespace tutti::piano
