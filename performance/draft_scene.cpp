// SPDX-License-Identifier: MIT
#include <tutti/performance/draft_scene.hpp>
#include <tutti/performance/families.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

#include <tutti/music/load_score.hpp>
#include <tutti/stage/family_draft.hpp>

namespace tutti::performance {
namespace {

using json = nlohmann::ordered_json;

bool has_notes(const music::Score& score, int part) {
  return std::any_of(score.notes.begin(), score.notes.end(),
                     [&](const music::Note& n) { return n.part == part; });
}

std::string part_label(const music::Part& part) {
  return part.name.empty() ? part.id : part.name;
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : std::string(separator)) + item;
  return text;
}

// "a, b and c".
std::string join_and(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  }
  return text;
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
  return draft_scene(score, music_reference, default_families());
}

Result<DraftedScene> draft_scene(const music::Score& score,
                                 const std::filesystem::path& music_reference,
                                 std::span<const stage::FamilyPlugin* const> families) {
  DraftedScene drafted;

  // Each family in turn takes the parts it plays among those with notes nobody has taken.
  std::vector<int> available;
  for (std::size_t p = 0; p < score.parts.size(); ++p) {
    if (has_notes(score, static_cast<int>(p))) available.push_back(static_cast<int>(p));
  }
  struct Taken {
    const stage::FamilyPlugin* family = nullptr;
    std::vector<int> parts;
    stage::FamilyDraft draft;
  };
  std::vector<Taken> taken;
  std::vector<std::string> plays;
  for (const stage::FamilyPlugin* family : families) {
    plays.emplace_back(family->draft_plays());
    auto parts = family->draft_recognise(score, available);
    if (!parts) return parts.error();
    if (parts->empty()) continue;
    for (int p : *parts) {
      available.erase(std::remove(available.begin(), available.end(), p), available.end());
    }
    taken.push_back({family, std::move(*parts), {}});
  }
  std::vector<std::string> unplayed;
  for (int p : available) unplayed.push_back(part_label(score.parts[static_cast<std::size_t>(p)]));
  const std::string tutti_plays = "tutti plays " + join_and(plays);
  if (taken.empty()) {
    return Error{score.source + ": no part tutti can play (parts: " +
                 (unplayed.empty() ? std::string("none with notes") : join(unplayed, ", ")) +
                 "); " + tutti_plays};
  }
  if (!unplayed.empty()) {
    drafted.notes.push_back(std::to_string(unplayed.size()) + " part" +
                            (unplayed.size() == 1 ? "" : "s") + " not played (" + tutti_plays +
                            "): " + join(unplayed, ", "));
  }

  // The families side by side from the audience's left, in their seating order: each drafted
  // where its frame's origin is, its players 1.4 m clear of the family on its left.
  std::vector<std::size_t> seating(taken.size());
  for (std::size_t i = 0; i < seating.size(); ++i) seating[i] = i;
  std::stable_sort(seating.begin(), seating.end(), [&](std::size_t a, std::size_t b) {
    return taken[a].family->draft_seating_order() < taken[b].family->draft_seating_order();
  });
  constexpr double kFamilyGap_m = 1.4;
  const bool alone = taken.size() == 1;
  double right_so_far = 0.0;
  for (std::size_t k = 0; k < seating.size(); ++k) {
    Taken& t = taken[seating[k]];
    stage::DraftPlace place{0.0, alone};
    if (k > 0) {
      auto measured = t.family->draft(score, t.parts, place);
      if (!measured) return measured.error();
      place.origin_x = right_so_far + kFamilyGap_m - measured->left_m;
    }
    auto draft = t.family->draft(score, t.parts, place);
    if (!draft) return draft.error();
    t.draft = std::move(*draft);
    right_so_far = t.draft.right_m;
  }

  json document;
  std::vector<std::string> summaries;
  for (const Taken& t : taken) summaries.push_back(t.draft.summary);
  const std::string piece = std::filesystem::path(score.source).filename().string();
  document["description"] = "Made by tutti scene new from " + piece + ": " +
                            join(summaries, " and ") +
                            (unplayed.empty() ? "." : " (not played: " + join(unplayed, ", ") + ").");
  document["music"] = music_reference.generic_string();
  document["seed"] = std::uint64_t{1};
  for (const Taken& t : taken) {
    for (const auto& [key, value] : t.draft.section) document[key] = value;
  }

  // Cameras: the whole group, then each family's.
  json cameras = json::array();
  if (alone && taken.front().draft.wide_camera_alone) {
    cameras.push_back(*taken.front().draft.wide_camera_alone);
  } else {
    double left = taken.front().draft.left_m;
    double right = taken.front().draft.right_m;
    for (const Taken& t : taken) {
      left = std::min(left, t.draft.left_m);
      right = std::max(right, t.draft.right_m);
    }
    cameras.push_back(stage::draft_wide_camera("wide", left - 0.7, right + 0.7, 0.6, 40.0));
  }
  std::map<std::string, std::vector<std::string>> group_cameras;  // group → cameras to cycle
  std::map<int, std::string> group_of_part;
  for (const Taken& t : taken) {
    for (const json& camera : t.draft.cameras) cameras.push_back(camera);
    for (const stage::DraftedGroup& group : t.draft.groups) {
      group_cameras[group.name] = group.cameras;
      for (int p : group.parts) group_of_part[p] = group.name;
    }
  }
  document["cameras"] = std::move(cameras);

  // Shots: every window of a few bars goes to the group with the most onsets there; each group
  // cycles through its cameras; the whole group opens, every fourth cut and when nobody plays.
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
    if (w > 0 && !wide && !group_cameras[chosen].empty()) {
      const std::vector<std::string>& list = group_cameras[chosen];
      shot_camera = list[next_camera[chosen]++ % list.size()];
      if (shot_camera == on_screen && list.size() > 1) {
        shot_camera = list[next_camera[chosen]++ % list.size()];
      }
    }
    if (w == 0 || shot_camera == on_screen) continue;
    shots.push_back(
        json{{"camera", shot_camera}, {"start_s", stage::draft_round_mm(windows[w].start_s)}});
    on_screen = shot_camera;
    ++cuts;
  }
  document["shots"] = std::move(shots);
  double pre_roll_s = 0.0;
  for (const Taken& t : taken) pre_roll_s = std::max(pre_roll_s, t.draft.pre_roll_s);
  document["output"] = json{{"width", 1280},
                            {"height", 720},
                            {"fps", 30},
                            {"msaa", 4},
                            {"start_s", pre_roll_s > 0.0 ? -pre_roll_s : 0.0}};
  drafted.document = std::move(document);
  return drafted;
}

}  // namespace tutti::performance
