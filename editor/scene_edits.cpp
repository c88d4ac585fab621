// SPDX-License-Identifier: MIT
#include <tutti/editor/scene_edits.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace tutti::editor {
namespace {

// Times are written to the millisecond; two within half of one are the same.
constexpr double kSameTime_s = 0.0005;

std::string seconds(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f s", t);
  return text;
}

// The player's object in the document: `player.pointer` names an object.
Result<const Json*> player_json(const Json& document, const PlayerRef& player) {
  if (player.pointer.empty() || player.pointer.front() != '/') {
    return Error{"no player at \"" + player.pointer + "\""};
  }
  try {
    const Json::json_pointer pointer(player.pointer);
    if (document.contains(pointer) && document.at(pointer).is_object()) {
      return &document.at(pointer);
    }
  } catch (const Json::exception&) {
    // not a JSON pointer: no such player, as below
  }
  return Error{"the scene has no player at " + player.pointer};
}

// For labels: the name the stage shows, else the name the file gives, else where it is.
std::string player_name(const Json& object, const PlayerRef& ref) {
  if (!ref.name.empty()) return ref.name;
  if (object.contains("name") && object["name"].is_string())
    return object["name"].get<std::string>();
  return ref.pointer;
}

std::optional<Json> member(const Json& object, const char* key) {
  if (!object.is_object() || !object.contains(key)) return std::nullopt;
  return object[key];
}

// One change replacing (or creating, or removing) object[key] at `pointer`.
JsonChange replace(const Json& object, const std::string& pointer, const char* key,
                   std::optional<Json> after) {
  return JsonChange{pointer + "/" + key, member(object, key), std::move(after)};
}

std::vector<double> times_of(const Json& object, const char* key) {
  std::vector<double> out;
  if (object.is_object() && object.contains(key) && object[key].is_array()) {
    for (const Json& t : object[key]) {
      if (t.is_number()) out.push_back(t.get<double>());
    }
  }
  return out;
}

bool erase_time(std::vector<double>& times, double t) {
  const auto it = std::find_if(times.begin(), times.end(),
                               [&](double x) { return std::abs(x - t) < kSameTime_s; });
  if (it == times.end()) return false;
  times.erase(it);
  return true;
}

void insert_time(std::vector<double>& times, double t) {
  if (std::any_of(times.begin(), times.end(),
                  [&](double x) { return std::abs(x - t) < kSameTime_s; })) {
    return;
  }
  times.insert(std::upper_bound(times.begin(), times.end(), t), t);
}

// A time as the scene file says it: to the millisecond (6.667, not 6.666666666666667).
double to_millisecond(double t) { return std::round(t * 1000.0) / 1000.0; }

Json time_array(const std::vector<double>& times) {
  Json out = Json::array();
  for (double t : times) out.push_back(to_millisecond(t));
  return out;
}

// The performer's "breaths" object after the lists change (absent when both are empty).
std::optional<Json> breaths_object(const std::vector<double>& add,
                                   const std::vector<double>& remove) {
  if (add.empty() && remove.empty()) return std::nullopt;
  Json out = Json::object();
  if (!add.empty()) out["add"] = time_array(add);
  if (!remove.empty()) out["remove"] = time_array(remove);
  return out;
}

struct BreathLists {
  const Json* player = nullptr;
  std::vector<double> add;
  std::vector<double> remove;
};

Result<BreathLists> breath_lists(const Json& document, const PlayerRef& ref) {
  auto player = player_json(document, ref);
  if (!player) return player.error();
  BreathLists lists;
  lists.player = *player;
  if ((*player)->contains("breaths")) {
    lists.add = times_of((**player)["breaths"], "add");
    lists.remove = times_of((**player)["breaths"], "remove");
  }
  return lists;
}

Edit breath_edit(const BreathLists& lists, const PlayerRef& player, std::string label) {
  Edit edit;
  edit.label = std::move(label);
  edit.changes.push_back(
      replace(*lists.player, player.pointer, "breaths", breaths_object(lists.add, lists.remove)));
  return edit;
}

void add_breath_to(BreathLists& lists, double t) {
  if (!erase_time(lists.remove, t)) insert_time(lists.add, t);
}

void delete_breath_from(BreathLists& lists, double t, bool marked_only) {
  const bool was_marked = erase_time(lists.add, t);
  if (!(was_marked && marked_only)) insert_time(lists.remove, t);
}

Result<Edit> cue_edit(const Json& document, std::vector<double> cues, std::string label) {
  std::sort(cues.begin(), cues.end());
  Edit edit;
  edit.label = std::move(label);
  edit.changes.push_back(JsonChange{"/cues", member(document, "cues"), time_array(cues)});
  return edit;
}

Json expression_json(const scene::Expression& e) {
  Json out = Json::object();
  out["kind"] = std::string(scene::expression_name(e.kind));
  out["start_s"] = e.start_s;
  out["end_s"] = e.end_s;
  if (e.amount != 1.0) out["amount"] = e.amount;
  return out;
}

bool same_expression(const Json& item, const scene::Expression& e) {
  const double amount =
      item.contains("amount") && item["amount"].is_number() ? item["amount"].get<double>() : 1.0;
  return item.is_object() && item.value("kind", "") == scene::expression_name(e.kind) &&
         std::abs(item.value("start_s", 0.0) - e.start_s) < kSameTime_s &&
         std::abs(item.value("end_s", 0.0) - e.end_s) < kSameTime_s &&
         std::abs(amount - e.amount) < 1e-9;
}

// The shot list as written, with the implicit "first camera from 0" when there is none.
Result<Json> shot_list(const Json& document) {
  if (document.contains("shots")) return document["shots"];
  if (!document.contains("cameras") || !document["cameras"].is_array() ||
      document["cameras"].empty()) {
    return Error{"the scene has no cameras"};
  }
  Json shots = Json::array();
  Json first = Json::object();
  first["camera"] = document["cameras"][0].value("name", "");
  first["start_s"] = 0;
  shots.push_back(first);
  return shots;
}

Edit shots_edit(const Json& document, Json shots, std::string label) {
  std::stable_sort(shots.begin(), shots.end(), [](const Json& a, const Json& b) {
    return a.value("start_s", 0.0) < b.value("start_s", 0.0);
  });
  Edit edit;
  edit.label = std::move(label);
  edit.changes.push_back(JsonChange{"/shots", member(document, "shots"), std::move(shots)});
  return edit;
}

Result<Json> pin_list(const Json& document, const PlayerRef& player) {
  auto object = player_json(document, player);
  if (!object) return object.error();
  return (*object)->contains("pins") ? (**object)["pins"] : Json::array();
}

bool same_note(const Json& pin, double time_s, int key) {
  return pin.is_object() && pin.value("key", -1) == key &&
         std::abs(pin.value("time_s", -1e9) - time_s) < 1e-3;
}

// Precondition: pin_list(document, player) succeeded.
Edit pins_edit(const Json& document, const PlayerRef& player, const Json& pins, std::string label) {
  Edit edit;
  edit.label = std::move(label);
  edit.changes.push_back(replace(**player_json(document, player), player.pointer, "pins",
                                 pins.empty() ? std::nullopt : std::optional<Json>(pins)));
  return edit;
}

}  // namespace

Result<Edit> set_variation(const Json& document, const PlayerRef& player, std::string_view field,
                           std::optional<double> value) {
  const bool known = std::any_of(scene::kVariationFields.begin(), scene::kVariationFields.end(),
                                 [&](const scene::VariationField& f) { return f.key == field; });
  if (!known) return Error{"unknown variation parameter \"" + std::string(field) + "\""};
  auto object = player_json(document, player);
  if (!object) return object.error();
  const std::string& pointer = player.pointer;
  Json variation = (*object)->contains("variation") ? (**object)["variation"] : Json::object();
  if (value) {
    variation[std::string(field)] = *value;
  } else {
    variation.erase(std::string(field));
  }
  Edit edit;
  edit.label = "set " + std::string(field) + " of " + player_name(**object, player);
  edit.changes.push_back(
      replace(**object, pointer, "variation",
              variation.empty() ? std::nullopt : std::optional<Json>(variation)));
  return edit;
}

Result<Edit> set_seed(const Json& document, const PlayerRef& player, std::uint64_t seed) {
  auto object = player_json(document, player);
  if (!object) return object.error();
  Edit edit;
  edit.label = "new seed for " + player_name(**object, player);
  edit.changes.push_back(replace(**object, player.pointer, "seed", Json(seed)));
  return edit;
}

std::uint64_t reroll_seed(std::uint64_t current) {
  std::uint64_t z = current + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

Result<Edit> add_breath(const Json& document, const PlayerRef& player, double t_s) {
  auto lists = breath_lists(document, player);
  if (!lists) return lists.error();
  add_breath_to(*lists, t_s);
  return breath_edit(
      *lists, player,
      "add a breath for " + player_name(*lists->player, player) + " at " + seconds(t_s));
}

Result<Edit> delete_breath(const Json& document, const PlayerRef& player, double boundary_s,
                           bool marked_only) {
  auto lists = breath_lists(document, player);
  if (!lists) return lists.error();
  delete_breath_from(*lists, boundary_s, marked_only);
  return breath_edit(
      *lists, player,
      "delete the breath of " + player_name(*lists->player, player) + " at " + seconds(boundary_s));
}

Result<Edit> move_breath(const Json& document, const PlayerRef& player, double from_boundary_s,
                         bool from_marked_only, double to_s) {
  auto lists = breath_lists(document, player);
  if (!lists) return lists.error();
  delete_breath_from(*lists, from_boundary_s, from_marked_only);
  add_breath_to(*lists, to_s);
  return breath_edit(
      *lists, player,
      "move the breath of " + player_name(*lists->player, player) + " to " + seconds(to_s));
}

Result<Edit> add_cue(const Json& document, std::span<const double> current, double t_s) {
  std::vector<double> cues(current.begin(), current.end());
  insert_time(cues, t_s);
  return cue_edit(document, std::move(cues), "add a cue at " + seconds(t_s));
}

Result<Edit> delete_cue(const Json& document, std::span<const double> current, std::size_t index) {
  if (index >= current.size()) return Error{"no cue " + std::to_string(index)};
  std::vector<double> cues(current.begin(), current.end());
  const double t = cues[index];
  cues.erase(cues.begin() + static_cast<std::ptrdiff_t>(index));
  return cue_edit(document, std::move(cues), "delete the cue at " + seconds(t));
}

Result<Edit> move_cue(const Json& document, std::span<const double> current, std::size_t index,
                      double t_s) {
  if (index >= current.size()) return Error{"no cue " + std::to_string(index)};
  std::vector<double> cues(current.begin(), current.end());
  cues[index] = t_s;
  return cue_edit(document, std::move(cues), "move a cue to " + seconds(t_s));
}

Result<Edit> add_expression(const Json& document, const PlayerRef& player,
                            const scene::Expression& expression) {
  auto object = player_json(document, player);
  if (!object) return object.error();
  Json list = (*object)->contains("expressions") ? (**object)["expressions"] : Json::array();
  list.push_back(expression_json(expression));
  Edit edit;
  edit.label = "add \"" + std::string(scene::expression_name(expression.kind)) + "\" for " +
               player_name(**object, player);
  edit.changes.push_back(replace(**object, player.pointer, "expressions", std::move(list)));
  return edit;
}

Result<Edit> delete_expression(const Json& document, const PlayerRef& player,
                               const scene::Expression& expression) {
  auto object = player_json(document, player);
  if (!object) return object.error();
  Json list = (*object)->contains("expressions") ? (**object)["expressions"] : Json::array();
  const auto it = std::find_if(list.begin(), list.end(),
                               [&](const Json& item) { return same_expression(item, expression); });
  if (it == list.end()) return Error{"no such expression"};
  list.erase(it);
  Edit edit;
  edit.label = "delete \"" + std::string(scene::expression_name(expression.kind)) + "\" of " +
               player_name(**object, player);
  edit.changes.push_back(replace(**object, player.pointer, "expressions",
                                 list.empty() ? std::nullopt : std::optional<Json>(list)));
  return edit;
}

Result<Edit> move_expression(const Json& document, const PlayerRef& player,
                             const scene::Expression& expression, double new_start_s) {
  auto object = player_json(document, player);
  if (!object) return object.error();
  Json list = (*object)->contains("expressions") ? (**object)["expressions"] : Json::array();
  const auto it = std::find_if(list.begin(), list.end(),
                               [&](const Json& item) { return same_expression(item, expression); });
  if (it == list.end()) return Error{"no such expression"};
  scene::Expression moved = expression;
  moved.start_s = new_start_s;
  moved.end_s = new_start_s + (expression.end_s - expression.start_s);
  *it = expression_json(moved);
  Edit edit;
  edit.label = "move \"" + std::string(scene::expression_name(expression.kind)) + "\" of " +
               player_name(**object, player) + " to " + seconds(new_start_s);
  edit.changes.push_back(replace(**object, player.pointer, "expressions", std::move(list)));
  return edit;
}

Result<Edit> add_shot(const Json& document, std::string_view camera, double start_s) {
  auto shots = shot_list(document);
  if (!shots) return shots.error();
  Json shot = Json::object();
  shot["camera"] = std::string(camera);
  shot["start_s"] = start_s;
  shots->push_back(shot);
  return shots_edit(document, std::move(*shots),
                    "cut to " + std::string(camera) + " at " + seconds(start_s));
}

Result<Edit> move_shot(const Json& document, std::size_t index, double start_s) {
  auto shots = shot_list(document);
  if (!shots) return shots.error();
  if (index >= shots->size()) return Error{"no shot " + std::to_string(index)};
  if (index == 0) return Error{"the first shot starts at 0 s"};
  (*shots)[index]["start_s"] = start_s;
  return shots_edit(document, std::move(*shots), "move a cut to " + seconds(start_s));
}

Result<Edit> delete_shot(const Json& document, std::size_t index) {
  auto shots = shot_list(document);
  if (!shots) return shots.error();
  if (index >= shots->size()) return Error{"no shot " + std::to_string(index)};
  if (index == 0) return Error{"the first shot cannot be deleted (change its camera instead)"};
  const double t = (*shots)[index].value("start_s", 0.0);
  shots->erase(shots->begin() + static_cast<std::ptrdiff_t>(index));
  return shots_edit(document, std::move(*shots), "delete the cut at " + seconds(t));
}

Result<Edit> pin_finger(const Json& document, const PlayerRef& player, double time_s, int key,
                        int finger) {
  auto pins = pin_list(document, player);
  if (!pins) return pins.error();
  Json pin = Json::object();
  pin["time_s"] = time_s;
  pin["key"] = key;
  pin["finger"] = finger;
  const auto it = std::find_if(pins->begin(), pins->end(),
                               [&](const Json& p) { return same_note(p, time_s, key); });
  if (it != pins->end()) {
    *it = pin;
  } else {
    pins->push_back(pin);
  }
  return pins_edit(document, player, *pins,
                   "pin finger " + std::to_string(finger) + " on key " + std::to_string(key) +
                       " at " + seconds(time_s));
}

Result<Edit> unpin_finger(const Json& document, const PlayerRef& player, double time_s, int key) {
  auto pins = pin_list(document, player);
  if (!pins) return pins.error();
  const auto it = std::find_if(pins->begin(), pins->end(),
                               [&](const Json& p) { return same_note(p, time_s, key); });
  if (it == pins->end())
    return Error{"no pin on key " + std::to_string(key) + " at " + seconds(time_s)};
  pins->erase(it);
  return pins_edit(document, player, *pins,
                   "unpin key " + std::to_string(key) + " at " + seconds(time_s));
}

}  // namespace tutti::editor
