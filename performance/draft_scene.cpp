// SPDX-License-Identifier: MIT
#include <tutti/performance/draft_scene.hpp>
#include <tutti/performance/families.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <string_view>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/music/general_midi.hpp>
#include <tutti/music/part_names.hpp>
#include <tutti/piano_model/content_dir.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>

namespace tutti::performance {
namespace {

using json = nlohmann::ordered_json;
constexpr double kPi = 3.14159265358979323846;

// Part-name words: music/part_names.hpp.
std::vector<std::string> words_of(std::string_view text) { return music::part_name_words(text); }

bool any_word_in(const std::vector<std::string>& words, std::initializer_list<std::string_view> set) {
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

bool has_notes(const music::Score& score, int part) {
  return std::any_of(score.notes.begin(), score.notes.end(),
                     [&](const music::Note& n) { return n.part == part; });
}

std::string part_label(const music::Part& part) {
  return part.name.empty() ? part.id : part.name;
}

// How a scene names a part: its name when no other part shares it, else its id.
std::string part_reference(const music::Score& score, int p) {
  const music::Part& part = score.parts[static_cast<std::size_t>(p)];
  if (part.name.empty()) return part.id;
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  int same = 0;
  for (const music::Part& other : score.parts) same += lower(other.name) == lower(part.name);
  return same == 1 ? part.name : part.id;
}

// Sections in seating order, from the audience's left.
struct Section {
  std::string_view model;
  std::string_view word;  // for player names: "Trumpet 1"
};
constexpr Section kSections[] = {{"trumpet", "Trumpet"},
                                 {"horn", "Horn"},
                                 {"trombone", "Trombone"},
                                 {"euphonium", "Euphonium"},
                                 {"tuba", "Tuba"}};

std::size_t section_of(const brass::Instrument& instrument) {
  for (std::size_t s = 0; s < std::size(kSections); ++s) {
    if (instrument.model_name() == kSections[s].model) return s;
  }
  return std::size(kSections) - 1;
}

// A keyboard player other than the pianist: the instrument and the parts they play.
struct Keyboardist {
  const piano::KeyboardInstrument* instrument = nullptr;
  std::vector<int> parts;
};

// Keyboard player k's bench x: the pianist keeps the origin (where the piano plugin's default
// bench is); the others sit to the audience's left of it, a piano's width and some apart.
double keyboardist_x(bool with_piano, std::size_t k) {
  constexpr double kSpacing_m = 1.7;
  const std::size_t seat = k + (with_piano ? 1 : 0);
  return seat == 0 ? 0.0 : -kSpacing_m * static_cast<double>(seat);  // never -0.0 in the file
}

struct Player {
  std::string name;
  std::string camera_stem;  // "trumpet_1"
  const brass::Instrument* instrument = nullptr;
  int part = 0;
  int voice = 1;
  std::size_t section = 0;
  double x = 0.0;
  double z = 0.0;
  double facing_deg = 0.0;
};

std::string camera_stem_of(const std::string& name) {
  std::string stem;
  for (char c : name) {
    stem += std::isalnum(static_cast<unsigned char>(c)) != 0
                ? static_cast<char>(std::tolower(static_cast<unsigned char>(c)))
                : '_';
  }
  return stem;
}

double round_mm(double v) { return std::round(v * 1000.0) / 1000.0; }

json vec3(double x, double y, double z) { return json::array({round_mm(x), round_mm(y), round_mm(z)}); }

// A point `distance` metres from (x, z) toward `angle_deg` (0 = +Z, positive toward +X).
std::pair<double, double> ahead(double x, double z, double angle_deg, double distance) {
  const double a = angle_deg * kPi / 180.0;
  return {x + distance * std::sin(a), z + distance * std::cos(a)};
}

json camera(const std::string& name, double px, double py, double pz, double tx, double ty,
            double tz, double fov_deg) {
  return json{{"name", name},
              {"position_m", vec3(px, py, pz)},
              {"target_m", vec3(tx, ty, tz)},
              {"fov_deg", fov_deg}};
}

// Seated players in a shallow arc (content/scenes/quintet.json's seating, for any number): one
// metre apart, the middle ones forward, each turned a little toward the middle.
void seat_in_arc(std::vector<Player>& players, double centre_x) {
  const double n = static_cast<double>(players.size());
  const double half = (n - 1.0) / 2.0;
  for (std::size_t i = 0; i < players.size(); ++i) {
    const double offset = static_cast<double>(i) - half;
    players[i].x = centre_x + offset;
    players[i].z = half > 0 ? 0.6 * (1.0 - (offset / half) * (offset / half)) : 0.6;
    players[i].facing_deg = std::clamp(-10.0 * offset, -30.0, 30.0);
  }
}

// A camera framing everything in x ∈ [left, right] (metres) near the floor from the front.
json wide_camera(const std::string& name, double left, double right, double front_z,
                 double fov_deg) {
  const double aspect = 16.0 / 9.0;
  const double half_width = (right - left) / 2.0;
  const double tan_half = std::tan(fov_deg * kPi / 360.0) * aspect;
  const double distance = half_width / tan_half + 0.8;
  const double cx = (left + right) / 2.0;
  return camera(name, cx, 1.5 + 0.05 * distance, front_z + distance, cx, 0.95, front_z - 0.3,
                fov_deg);
}

// Onsets per group in [from, to) seconds.
struct Window {
  double start_s = 0.0;
  double end_s = 0.0;
};

std::vector<Window> shot_windows(const music::Score& score) {
  // Two bars a window, or one bar when two last longer than 12 s, or four when two are shorter
  // than 4 s: cuts land on bar lines, every few seconds.
  int numerator = 4;
  int denominator = 4;
  if (!score.time_signatures.empty()) {
    numerator = score.time_signatures.front().numerator;
    denominator = score.time_signatures.front().denominator;
  }
  const double bar_beats = numerator * 4.0 / std::max(1, denominator);
  const double end_beats = score.tempo_map.beats_at_seconds(score.end_s);
  std::vector<Window> windows;
  double beats = 0.0;
  while (beats < end_beats - 1e-9) {
    const double start_s = score.tempo_map.seconds_at_beats(beats);
    double bars = 2.0;
    const double two_bars_s = score.tempo_map.seconds_at_beats(beats + 2.0 * bar_beats) - start_s;
    if (two_bars_s > 12.0) bars = 1.0;
    if (two_bars_s < 4.0) bars = 4.0;
    const double next = beats + bars * bar_beats;
    windows.push_back({start_s, score.tempo_map.seconds_at_beats(std::min(next, end_beats))});
    beats = next;
  }
  if (windows.empty()) windows.push_back({0.0, std::max(score.end_s, 1.0)});
  return windows;
}

void write_json(const json& value, int indent, std::string& out) {
  auto all_scalars = [](const json& v) {
    return std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_primitive(); });
  };
  auto flat = [&](const json& v) {
    return std::all_of(v.begin(), v.end(), [&](const json& e) {
      return e.is_primitive() || (e.is_array() && all_scalars(e));
    });
  };
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (value.is_array() && !value.empty() && !all_scalars(value)) {
    out += "[\n";
    for (std::size_t i = 0; i < value.size(); ++i) {
      out += pad;
      write_json(value[i], indent + 2, out);
      out += i + 1 < value.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else if (value.is_object() && !value.empty() && !(flat(value) && value.dump().size() <= 100)) {
    out += "{\n";
    std::size_t i = 0;
    for (auto it = value.begin(); it != value.end(); ++it, ++i) {
      out += pad + json(it.key()).dump() + ": ";
      write_json(it.value(), indent + 2, out);
      out += i + 1 < value.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else {
    // One line, with a space after each separator, as the hand-written scenes are.
    std::string line = value.dump();
    std::string spaced;
    bool in_string = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      spaced += c;
      if (c == '"' && (i == 0 || line[i - 1] != '\\')) in_string = !in_string;
      if (!in_string && (c == ',' || c == ':')) spaced += ' ';
    }
    out += spaced;
  }
}

}  // namespace

std::string format_scene_document(const nlohmann::ordered_json& document) {
  std::string out;
  write_json(document, 0, out);
  return out + "\n";
}

Result<scene::Scene> load_scene_or_music(const std::filesystem::path& file,
                                         const std::filesystem::path& content_dir,
                                         std::vector<std::string>* notes) {
  const scene::LoadOptions options = scene_load_options(content_dir);
  if (!is_music_file(file)) return scene::load_scene(file, options);
  auto score = music::load_score(file);
  if (!score) return score.error();
  auto drafted = draft_scene(*score, std::filesystem::absolute(file));
  if (!drafted) return drafted.error();
  if (notes != nullptr) *notes = drafted->notes;
  return scene::parse_scene(nlohmann::json::parse(drafted->document.dump()),
                            file.filename().string(), std::filesystem::current_path(), options);
}

bool is_music_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".mid" || ext == ".midi" || ext == ".kar" || ext == ".smf" || ext == ".musicxml" ||
         ext == ".xml" || ext == ".mxl" || ext == ".txt";
}

std::filesystem::path music_reference_from(const std::filesystem::path& scene_file,
                                           const std::filesystem::path& music_file) {
  std::error_code ec;
  const std::filesystem::path scene_dir =
      std::filesystem::weakly_canonical(std::filesystem::absolute(scene_file, ec), ec).parent_path();
  const std::filesystem::path music = std::filesystem::weakly_canonical(
      std::filesystem::absolute(music_file, ec), ec);
  if (ec) return std::filesystem::absolute(music_file);
  const std::filesystem::path relative = music.lexically_relative(scene_dir);
  // Relative while the two are near each other (a project folder); else the full path.
  int ups = 0;
  for (const std::filesystem::path& part : relative) ups += part == "..";
  if (relative.empty() || ups > 1) return music;
  return relative;
}

Result<DraftedScene> draft_scene(const music::Score& score,
                                 const std::filesystem::path& music_reference) {
  auto known = brass::load_all_instruments();
  if (!known) return known.error();
  DraftedScene drafted;

  // Brass parts, then piano parts; everything else gets a note.
  const std::vector<brass::BrassPart> brass_parts = brass::find_brass_parts(score, *known);
  std::set<int> brass_indices;
  for (const brass::BrassPart& b : brass_parts) brass_indices.insert(b.part);
  auto instruments = piano::KeyboardInstruments::load(
      piano::keyboard_instruments_path(piano::default_content_dir()));
  if (!instruments) return instruments.error();
  std::vector<int> piano_parts;
  // The keyboard family's other instruments (content/piano/instruments.json), one player each,
  // in the file's order: an organist, a harpsichordist, a keyboardist at a synth, ...
  std::vector<Keyboardist> keyboardists;
  std::vector<std::string> unplayed;
  for (std::size_t p = 0; p < score.parts.size(); ++p) {
    const int part = static_cast<int>(p);
    if (brass_indices.count(part) != 0 || !has_notes(score, part)) continue;
    const music::Part& info = score.parts[p];
    const std::vector<std::string> words = words_of(info.name);
    // By name first; by General MIDI program unless the name says another instrument (files
    // that state no program leave it at 0, "piano").
    const piano::KeyboardInstrument* keyboard = nullptr;
    if (!info.percussion) {
      keyboard = instruments->recognise(words, -1);
      if (keyboard == nullptr && names_a_keyboard(words)) keyboard = instruments->find("piano");
      if (keyboard == nullptr && !names_another_instrument(words)) {
        keyboard = instruments->recognise({}, info.program);
      }
    }
    if (keyboard == nullptr) {
      unplayed.push_back(part_label(info));
    } else if (keyboard->id == "piano") {
      piano_parts.push_back(part);
    } else {
      auto same = std::find_if(keyboardists.begin(), keyboardists.end(),
                               [&](const Keyboardist& k) { return k.instrument == keyboard; });
      if (same == keyboardists.end()) {
        keyboardists.push_back(Keyboardist{keyboard, {}});
        same = keyboardists.end() - 1;
      }
      same->parts.push_back(part);
    }
  }
  const bool plays_nothing = brass_parts.empty() && piano_parts.empty() && keyboardists.empty();
  if (!unplayed.empty() && !plays_nothing) {
    std::string parts;
    for (const std::string& name : unplayed) parts += (parts.empty() ? "" : ", ") + name;
    drafted.notes.push_back(std::to_string(unplayed.size()) + " part" +
                            (unplayed.size() == 1 ? "" : "s") +
                            " not played (tutti plays trumpet, horn, trombone, euphonium, tuba "
                            "and keyboards): " + parts);
  }
  if (plays_nothing) {
    std::string parts;
    for (const std::string& name : unplayed) parts += (parts.empty() ? "" : ", ") + name;
    return Error{score.source + ": no part tutti can play (parts: " +
                 (parts.empty() ? std::string("none with notes") : parts) +
                 "); tutti plays trumpet, horn, trombone, euphonium, tuba and keyboards"};
  }

  // Players, by section, then part order, then voice.
  std::vector<Player> players;
  for (const brass::BrassPart& b : brass_parts) {
    for (int v = 0; v < b.voices; ++v) {
      Player player;
      player.instrument = b.instrument;
      player.part = b.part;
      player.voice = v + 1;
      player.section = section_of(*b.instrument);
      players.push_back(player);
    }
  }
  std::stable_sort(players.begin(), players.end(),
                   [](const Player& a, const Player& b) { return a.section < b.section; });
  std::map<std::size_t, int> section_sizes;
  for (const Player& p : players) ++section_sizes[p.section];
  std::map<std::size_t, int> numbered;
  for (Player& p : players) {
    const int n = ++numbered[p.section];
    p.name = std::string(kSections[p.section].word);
    if (section_sizes[p.section] > 1) p.name += " " + std::to_string(n);
    p.camera_stem = camera_stem_of(p.name);
  }

  // The piano stays where the piano plugin builds it (keys' front at the origin), the other
  // keyboards to its left and the brass to its right, as seen from the audience.
  const bool with_piano = !piano_parts.empty();
  const double arc_half = players.empty() ? 0.0 : (static_cast<double>(players.size()) - 1) / 2.0;
  const double arc_centre = with_piano || !keyboardists.empty() ? 2.2 + arc_half : 0.0;
  seat_in_arc(players, arc_centre);

  json document;
  std::string summary;
  for (const auto& [section, count] : section_sizes) {
    summary += (summary.empty() ? "" : ", ") + std::to_string(count) + " " +
               std::string(kSections[section].model) + (count > 1 ? "s" : "");
  }
  if (with_piano) summary += (summary.empty() ? "" : " and ") + std::string("a pianist");
  for (const Keyboardist& k : keyboardists) {
    const std::string& who = k.instrument->player;
    const bool vowel = std::string_view("aeiou").find(who.front()) != std::string_view::npos;
    summary += (summary.empty() ? "" : " and ") + std::string(vowel ? "an " : "a ") + who;
  }
  const std::string piece = std::filesystem::path(score.source).filename().string();
  document["description"] = "Made by tutti scene new from " + piece + ": " + summary +
                            (unplayed.empty() ? "." : " (not played: " + [&] {
                              std::string s;
                              for (const std::string& u : unplayed) s += (s.empty() ? "" : ", ") + u;
                              return s;
                            }() + ").");
  document["music"] = music_reference.generic_string();
  document["seed"] = std::uint64_t{1};

  json performers = json::array();
  for (std::size_t i = 0; i < players.size(); ++i) {
    const Player& p = players[i];
    json performer{{"name", p.name},
                   {"instrument", p.instrument->id},
                   {"part", part_reference(score, p.part)},
                   {"position_m", vec3(p.x, 0.0, p.z)},
                   {"facing_deg", round_mm(p.facing_deg)},
                   {"stance", "seated"},
                   {"music_stand", false}};
    if (p.voice != 1) performer["voice"] = p.voice;
    if (i == 0) performer["lead"] = true;
    performers.push_back(std::move(performer));
  }
  if (!performers.empty()) document["performers"] = std::move(performers);
  if (with_piano && keyboardists.empty()) {
    json parts = json::array();
    for (int p : piano_parts) parts.push_back(part_reference(score, p));
    document["pianist"] = json{{"parts", std::move(parts)}};
  } else if (!keyboardists.empty()) {
    json pianists = json::array();
    if (with_piano) {
      json parts = json::array();
      for (int p : piano_parts) parts.push_back(part_reference(score, p));
      pianists.push_back(json{{"parts", std::move(parts)}});
    }
    for (std::size_t k = 0; k < keyboardists.size(); ++k) {
      json parts = json::array();
      for (int p : keyboardists[k].parts) parts.push_back(part_reference(score, p));
      pianists.push_back(json{{"instrument", keyboardists[k].instrument->id},
                              {"parts", std::move(parts)},
                              {"position_m", vec3(keyboardist_x(with_piano, k), 0.0, 0.6)},
                              {"facing_deg", 180}});
    }
    document["pianists"] = std::move(pianists);
  }

  // Cameras: the whole group, each section, each player (front, and the lead from the side),
  // the piano's (content/scenes/piano.json).
  json cameras = json::array();
  double left = players.empty() ? 0.0 : players.front().x;
  double right = players.empty() ? 0.0 : players.back().x;
  if (with_piano) left = std::min(left, -0.8), right = std::max(right, 0.8);
  if (!keyboardists.empty()) {
    left = std::min(left, keyboardist_x(with_piano, keyboardists.size() - 1) - 0.8);
    right = std::max(right, with_piano ? 0.8 : keyboardist_x(false, 0) + 0.8);
  }
  if (players.empty() && keyboardists.empty()) {
    cameras.push_back(camera("wide", 2.4, 1.55, 3.0, 0.0, 0.95, 0.25, 40.0));
  } else {
    cameras.push_back(wide_camera("wide", left - 0.7, right + 0.7, 0.6, 40.0));
  }
  std::map<std::string, std::vector<std::string>> group_cameras;  // group → cameras to cycle
  for (const auto& [section, count] : section_sizes) {
    if (count < 2 || count == static_cast<int>(players.size())) continue;
    double l = 1e9;
    double r = -1e9;
    for (const Player& p : players) {
      if (p.section == section) l = std::min(l, p.x), r = std::max(r, p.x);
    }
    const std::string name = std::string(kSections[section].model) + "s";
    cameras.push_back(wide_camera(name, l - 0.6, r + 0.6, 0.8, 32.0));
    group_cameras[std::string(kSections[section].model)].push_back(name);
  }
  for (std::size_t i = 0; i < players.size(); ++i) {
    const Player& p = players[i];
    const auto [cx, cz] = ahead(p.x, p.z, p.facing_deg, 2.3);
    const auto [tx, tz] = ahead(p.x, p.z, p.facing_deg, 0.1);
    cameras.push_back(camera(p.camera_stem + "_front", cx, 1.3, cz, tx, 1.0, tz, 30.0));
    std::vector<std::string>& list = group_cameras[std::string(kSections[p.section].model)];
    list.push_back(p.camera_stem + "_front");
    if (i == 0) {
      const auto [sx, sz] = ahead(p.x, p.z, p.facing_deg + (p.x <= arc_centre ? -45.0 : 45.0), 1.34);
      cameras.push_back(camera(p.camera_stem + "_side", sx, 1.3, sz, tx, 0.98, tz, 38.0));
      list.insert(list.begin() + 1, p.camera_stem + "_side");
    }
  }
  if (with_piano) {
    if (!players.empty()) cameras.push_back(camera("piano", 2.4, 1.55, 3.0, 0.0, 0.95, 0.25, 40.0));
    cameras.push_back(camera("piano_hands", 0.55, 1.45, 0.75, 0.0, 0.74, -0.05, 38.0));
    cameras.push_back(camera("piano_treble_end", 1.25, 0.98, 0.3, -0.1, 0.76, -0.02, 32.0));
    cameras.push_back(camera("piano_face", -0.9, 1.3, -0.35, 0.0, 1.15, 0.6, 34.0));
    group_cameras["piano"] = {"piano_hands", "piano_treble_end", "piano_face"};
    if (!players.empty()) group_cameras["piano"].push_back("piano");
  }
  // Each other keyboard player: their hands from over the right shoulder, as the pianist's.
  for (std::size_t k = 0; k < keyboardists.size(); ++k) {
    const double x = keyboardist_x(with_piano, k);
    const std::string name = keyboardists[k].instrument->id + "_hands";
    cameras.push_back(camera(name, x + 0.55, 1.45, 0.75, x, 0.74, -0.05, 38.0));
    group_cameras[keyboardists[k].instrument->id] = {name};
  }
  document["cameras"] = std::move(cameras);

  // Shots: every window of a few bars goes to the group with the most onsets there; each group
  // cycles through its cameras; the whole group opens, every fourth cut and when nobody plays.
  std::map<int, std::string> group_of_part;
  for (const Player& p : players) group_of_part[p.part] = std::string(kSections[p.section].model);
  for (int p : piano_parts) group_of_part[p] = "piano";
  for (const Keyboardist& k : keyboardists) {
    for (int p : k.parts) group_of_part[p] = k.instrument->id;
  }
  json shots = json::array();
  shots.push_back(json{{"camera", "wide"}, {"start_s", 0}});
  std::string on_screen = "wide";
  std::map<std::string, std::size_t> next_camera;
  int cuts = 0;
  const std::vector<Window> windows = shot_windows(score);
  for (std::size_t w = 0; w < windows.size(); ++w) {
    std::map<std::string, int> onsets;
    for (const music::Note& n : score.notes) {
      if (n.onset_s < windows[w].start_s || n.onset_s >= windows[w].end_s) continue;
      auto group = group_of_part.find(n.part);
      if (group != group_of_part.end()) ++onsets[group->second];
    }
    std::string chosen = "wide";
    int most = 0;
    for (const auto& [group, count] : onsets) {
      if (count > most) most = count, chosen = group;
    }
    std::string shot_camera = "wide";
    const bool wide = chosen == "wide" || w + 1 == windows.size() ||
                      (cuts % 4 == 3 && on_screen != "wide");
    if (w > 0 && !wide) {
      const std::vector<std::string>& list = group_cameras[chosen];
      shot_camera = list[next_camera[chosen]++ % list.size()];
      if (shot_camera == on_screen && list.size() > 1) {
        shot_camera = list[next_camera[chosen]++ % list.size()];
      }
    }
    if (w == 0 || shot_camera == on_screen) continue;
    shots.push_back(json{{"camera", shot_camera}, {"start_s", round_mm(windows[w].start_s)}});
    on_screen = shot_camera;
    ++cuts;
  }
  document["shots"] = std::move(shots);
  // The lead's cue comes a beat before the first entrance: start early enough to see it.
  document["output"] = json{{"width", 1280},
                            {"height", 720},
                            {"fps", 30},
                            {"msaa", 4},
                            {"start_s", players.empty() ? 0.0 : -2.0}};
  drafted.document = std::move(document);
  return drafted;
}

}  // namespace tutti::performance
