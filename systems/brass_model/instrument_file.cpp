// SPDX-License-Identifier: MIT
#include <tutti/brass_model/instrument_file.hpp>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include <tutti/brass_model/brass_physics.hpp>
#include <tutti/brass_model/fingering_names.hpp>
#include <tutti/content/json_reader.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::brass_model {
namespace {

using nlohmann::json;

std::string at(std::string_view path, std::string_view key) {
  return std::string(path) + "/" + std::string(key);
}
std::string at(std::string_view path, std::size_t index) {
  return std::string(path) + "/" + std::to_string(index);
}

// Typed reads with the file's error format; every function returns the first problem.
class Fields {
 public:
  explicit Fields(const content::JsonReader& reader) : reader_(reader) {}

  Error error(std::string_view path, std::string_view reason) const {
    return reader_.error(path, reason);
  }
  Status keys(const json& object, std::string_view path,
              std::initializer_list<std::string_view> allowed) const {
    return reader_.check_keys(object, path, allowed);
  }

  Result<const json*> required(const json& object, std::string_view path, const char* key) const {
    if (!object.contains(key)) return error(at(path, key), "missing");
    return &object.at(key);
  }

  Result<std::string> text(const json& value, std::string_view path) const {
    if (!value.is_string()) return error(path, "expected a string");
    return value.get<std::string>();
  }

  Result<int> integer(const json& value, std::string_view path, int lo, int hi) const {
    if (!value.is_number_integer()) return error(path, "expected a whole number");
    const auto number = value.get<std::int64_t>();
    if (number < lo || number > hi) {
      return error(path, "must be in " + std::to_string(lo) + ".." + std::to_string(hi));
    }
    return static_cast<int>(number);
  }

  Result<double> number(const json& value, std::string_view path, double lo, double hi) const {
    if (!value.is_number()) return error(path, "expected a number");
    const double number = value.get<double>();
    if (!std::isfinite(number) || number < lo || number > hi) {
      return error(path, "must be a number in " + trimmed(lo) + ".." + trimmed(hi));
    }
    return number;
  }

  Result<int> pitch(const json& value, std::string_view path) const {
    if (!value.is_string()) return error(path, "expected a pitch name such as \"F#3\"");
    auto key = music::parse_pitch_name(value.get<std::string>());
    if (!key) return error(path, "\"" + value.get<std::string>() + "\" is not a pitch name");
    return *key;
  }

  Result<const json*> array(const json& value, std::string_view path) const {
    if (!value.is_array()) return error(path, "expected an array");
    return &value;
  }

 private:
  static std::string trimmed(double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  }
  const content::JsonReader& reader_;
};

bool is_phrase(const std::string& s) {
  if (s.empty() || s.front() == ' ' || s.back() == ' ') return false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const bool letter = (c >= 'a' && c <= 'z') || c >= 0x80;
    const bool space = c == ' ' && s[i + 1] != ' ';
    if (!letter && !space) return false;
  }
  return true;
}

Result<std::vector<std::string>> phrases(const Fields& f, const json& doc, const char* key,
                                         bool required) {
  std::vector<std::string> out;
  const std::string path = at("", key);
  if (!doc.contains(key)) {
    if (required) return f.error(path, "missing");
    return out;
  }
  auto list = f.array(doc.at(key), path);
  if (!list) return list.error();
  if (required && (*list)->empty()) return f.error(path, "needs at least one name");
  for (std::size_t i = 0; i < (*list)->size(); ++i) {
    auto name = f.text((**list)[i], at(path, i));
    if (!name) return name.error();
    if (!is_phrase(*name)) {
      return f.error(at(path, i), "expected lower-case words separated by single spaces");
    }
    out.push_back(*name);
  }
  return out;
}

Result<std::vector<ValveSpec>> valve_list(const Fields& f, const json& value,
                                          const std::string& path, bool trigger) {
  auto list = f.array(value, path);
  if (!list) return list.error();
  if ((*list)->size() > std::size_t(kMaxValves)) {
    return f.error(path, "at most " + std::to_string(kMaxValves) + " valves");
  }
  std::vector<ValveSpec> valves;
  for (std::size_t i = 0; i < (*list)->size(); ++i) {
    const json& item = (**list)[i];
    const std::string where = at(path, i);
    if (auto ok = f.keys(item, where, {"name", "lowers_semitones", "switches_side"}); !ok) {
      return ok.error();
    }
    ValveSpec v;
    auto name_value = f.required(item, where, "name");
    if (!name_value) return name_value.error();
    auto name = f.text(**name_value, at(where, "name"));
    if (!name) return name.error();
    const bool bad_char = std::any_of(name->begin(), name->end(), [&](char c) {
      return c == '-' || c == ' ' || (trigger && std::isdigit(static_cast<unsigned char>(c)));
    });
    if (name->empty() || *name == "open" || bad_char) {
      return f.error(at(where, "name"), trigger ? "expected a name without '-', spaces or digits"
                                                : "expected a name without '-' or spaces");
    }
    for (const ValveSpec& other : valves) {
      if (other.name == *name) return f.error(at(where, "name"), "repeats \"" + *name + "\"");
    }
    v.name = *name;
    auto lowers_value = f.required(item, where, "lowers_semitones");
    if (!lowers_value) return lowers_value.error();
    auto lowers = f.number(**lowers_value, at(where, "lowers_semitones"), -12.0, 12.0);
    if (!lowers) return lowers.error();
    if (*lowers == 0.0) return f.error(at(where, "lowers_semitones"), "must not be 0");
    v.lowers_semitones = *lowers;
    if (item.contains("switches_side")) {
      if (!item.at("switches_side").is_boolean()) {
        return f.error(at(where, "switches_side"), "expected true or false");
      }
      v.switches_side = item.at("switches_side").get<bool>();
      if (v.switches_side && trigger) {
        return f.error(at(where, "switches_side"), "a slide's trigger cannot switch sides");
      }
    }
    valves.push_back(std::move(v));
  }
  return valves;
}

Status read_mechanism(const Fields& f, const json& doc, Instrument& inst) {
  auto mechanism = f.required(doc, "", "mechanism");
  if (!mechanism) return mechanism.error();
  const json& m = **mechanism;
  if (!m.is_object()) return f.error("/mechanism", "expected an object");
  auto kind_value = f.required(m, "/mechanism", "kind");
  if (!kind_value) return kind_value.error();
  auto kind = f.text(**kind_value, "/mechanism/kind");
  if (!kind) return kind.error();
  if (*kind == "valves") {
    inst.mechanism = Mechanism::valves;
    if (auto ok = f.keys(m, "/mechanism", {"kind", "valves"}); !ok) return ok;
    auto list = f.required(m, "/mechanism", "valves");
    if (!list) return list.error();
    auto valves = valve_list(f, **list, "/mechanism/valves", false);
    if (!valves) return valves.error();
    if (valves->empty()) return f.error("/mechanism/valves", "needs at least one valve");
    inst.valves = std::move(*valves);
    return Status::success();
  }
  if (*kind != "slide") return f.error("/mechanism/kind", "expected \"valves\" or \"slide\"");
  inst.mechanism = Mechanism::slide;
  if (auto ok = f.keys(m, "/mechanism",
                       {"kind", "positions", "max_speed_mm_per_s", "reach_mm", "trigger"});
      !ok) {
    return ok;
  }
  auto positions_value = f.required(m, "/mechanism", "positions");
  if (!positions_value) return positions_value.error();
  auto positions = f.integer(**positions_value, "/mechanism/positions", 2, 12);
  if (!positions) return positions.error();
  inst.positions = *positions;
  auto speed_value = f.required(m, "/mechanism", "max_speed_mm_per_s");
  if (!speed_value) return speed_value.error();
  auto speed = f.number(**speed_value, "/mechanism/max_speed_mm_per_s", 1.0, 1e5);
  if (!speed) return speed.error();
  inst.max_slide_speed_mm_per_s = *speed;
  if (m.contains("reach_mm")) {
    auto reach = f.number(m.at("reach_mm"), "/mechanism/reach_mm", 1.0, 1e4);
    if (!reach) return reach.error();
    inst.slide_reach_mm = *reach;
  }
  if (m.contains("trigger")) {
    auto triggers = valve_list(f, m.at("trigger"), "/mechanism/trigger", true);
    if (!triggers) return triggers.error();
    inst.valves = std::move(*triggers);
  }
  return Status::success();
}

Status read_series(const Fields& f, const json& doc, InstrumentFile& out) {
  Instrument& inst = out.instrument;
  auto series = f.required(doc, "", "harmonic_series");
  if (!series) return series.error();
  const json& s = **series;
  const std::string path = "/harmonic_series";
  if (auto ok = f.keys(s, path, {"fundamental", "partials", "max_partial_cents", "tube_length_mm"});
      !ok) {
    return ok;
  }
  auto fundamental_value = f.required(s, path, "fundamental");
  if (!fundamental_value) return fundamental_value.error();
  auto fundamental = f.pitch(**fundamental_value, at(path, "fundamental"));
  if (!fundamental) return fundamental.error();
  inst.fundamental_written = *fundamental;
  auto partials_value = f.required(s, path, "partials");
  if (!partials_value) return partials_value.error();
  auto partials = f.array(**partials_value, at(path, "partials"));
  if (!partials) return partials.error();
  if ((*partials)->empty()) return f.error(at(path, "partials"), "needs at least one partial");
  for (std::size_t i = 0; i < (*partials)->size(); ++i) {
    auto n = f.integer((**partials)[i], at(at(path, "partials"), i), 1, 32);
    if (!n) return n.error();
    if (!inst.partials.empty() && *n <= inst.partials.back()) {
      return f.error(at(at(path, "partials"), i), "partials must be in ascending order");
    }
    inst.partials.push_back(*n);
  }
  if (s.contains("max_partial_cents")) {
    auto cents = f.number(s.at("max_partial_cents"), at(path, "max_partial_cents"), 0.0, 50.0);
    if (!cents) return cents.error();
    out.max_partial_cents = *cents;
  }
  inst.tube_length_mm = acoustic_length_mm(inst.fundamental_written + inst.transposition_semitones);
  if (s.contains("tube_length_mm")) {
    auto length = f.number(s.at("tube_length_mm"), at(path, "tube_length_mm"), 100.0, 20000.0);
    if (!length) return length.error();
    inst.tube_length_mm = *length;
  }
  if (inst.mechanism == Mechanism::slide) {
    inst.slide_length_mm = slide_extension_mm(inst.tube_length_mm, inst.positions - 1);
  }
  return Status::success();
}

// A fingering's name for this instrument ("1-3", or "T1" on a slide).
Result<FingeringRef> fingering_ref(const Fields& f, const Instrument& inst, const json& value,
                                   const std::string& path) {
  auto text = f.text(value, path);
  if (!text) return text.error();
  FingeringRef ref;
  ref.text = *text;
  if (inst.mechanism == Mechanism::valves) {
    auto mask = parse_combination(inst.valves, *text);
    if (!mask)
      return f.error(path, "\"" + *text + "\" is not a combination of this instrument's valves");
    ref.valves = *mask;
    return ref;
  }
  auto slide = parse_slide_fingering(inst.valves, *text);
  if (!slide || slide->position < 1 || slide->position > inst.positions) {
    return f.error(path, "\"" + *text + "\" is not a slide position of this instrument (\"3\", \"" +
                             (inst.valves.empty() ? std::string() : inst.valves[0].name) + "1\")");
  }
  ref.valves = slide->valves;
  ref.position = slide->position;
  return ref;
}

Result<std::uint8_t> valve_names(const Fields& f, const Instrument& inst, const json& value,
                                 const std::string& path) {
  auto list = f.array(value, path);
  if (!list) return list.error();
  std::uint8_t mask = 0;
  for (std::size_t i = 0; i < (*list)->size(); ++i) {
    auto name = f.text((**list)[i], at(path, i));
    if (!name) return name.error();
    auto one = parse_combination(inst.valves, *name);
    if (!one || *one == 0 || (*one & (*one - 1)) != 0) {
      return f.error(at(path, i), "\"" + *name + "\" is not one of the valves");
    }
    mask = static_cast<std::uint8_t>(mask | *one);
  }
  return mask;
}

Status read_conventions(const Fields& f, const json& doc, InstrumentFile& out) {
  const Instrument& inst = out.instrument;
  if (!doc.contains("conventions")) return Status::success();
  const json& c = doc.at("conventions");
  const std::string path = "/conventions";
  if (auto ok = f.keys(c, path,
                       {"combination_preference", "standard", "max_alternate_cents", "lip_cents"});
      !ok) {
    return ok;
  }
  if (c.contains("max_alternate_cents")) {
    auto cents = f.number(c.at("max_alternate_cents"), at(path, "max_alternate_cents"), 0, 100);
    if (!cents) return cents.error();
    out.max_alternate_cents = *cents;
  }
  if (c.contains("lip_cents")) {
    auto cents = f.number(c.at("lip_cents"), at(path, "lip_cents"), 0, 50);
    if (!cents) return cents.error();
    out.lip_cents = *cents;
  }
  if (c.contains("combination_preference")) {
    const std::string where = at(path, "combination_preference");
    auto list = f.array(c.at("combination_preference"), where);
    if (!list) return list.error();
    for (std::size_t i = 0; i < (*list)->size(); ++i) {
      auto name = f.text((**list)[i], at(where, i));
      if (!name) return name.error();
      auto mask = parse_combination(inst.valves, *name);
      if (!mask)
        return f.error(at(where, i), "\"" + *name + "\" is not a combination of the valves");
      if (std::find(out.preference.begin(), out.preference.end(), *mask) != out.preference.end()) {
        return f.error(at(where, i), "\"" + *name + "\" is listed twice");
      }
      out.preference.push_back(*mask);
    }
  }
  if (c.contains("standard")) {
    const std::string where = at(path, "standard");
    auto list = f.array(c.at("standard"), where);
    if (!list) return list.error();
    for (std::size_t i = 0; i < (*list)->size(); ++i) {
      const json& item = (**list)[i];
      StandardRule rule;
      rule.path = at(where, i);
      if (auto ok = f.keys(item, rule.path,
                           {"from", "to", "partials", "valves_down", "valves_up", "reason"});
          !ok) {
        return ok;
      }
      if (item.contains("from")) {
        auto from = f.pitch(item.at("from"), at(rule.path, "from"));
        if (!from) return from.error();
        rule.from_written = *from;
      }
      if (item.contains("to")) {
        auto to = f.pitch(item.at("to"), at(rule.path, "to"));
        if (!to) return to.error();
        rule.to_written = *to;
      }
      if (rule.from_written > rule.to_written) {
        return f.error(at(rule.path, "to"), "must not be below \"from\"");
      }
      if (item.contains("partials")) {
        auto partials = f.array(item.at("partials"), at(rule.path, "partials"));
        if (!partials) return partials.error();
        for (std::size_t k = 0; k < (*partials)->size(); ++k) {
          auto n = f.integer((**partials)[k], at(at(rule.path, "partials"), k), 1, 32);
          if (!n) return n.error();
          if (std::find(inst.partials.begin(), inst.partials.end(), *n) == inst.partials.end()) {
            return f.error(
                at(at(rule.path, "partials"), k),
                "partial " + std::to_string(*n) + " is not in /harmonic_series/partials");
          }
          rule.partials.push_back(*n);
        }
      }
      for (const char* key : {"valves_down", "valves_up"}) {
        if (!item.contains(key)) continue;
        auto mask = valve_names(f, inst, item.at(key), at(rule.path, key));
        if (!mask) return mask.error();
        (std::string_view(key) == "valves_down" ? rule.valves_down : rule.valves_up) = *mask;
      }
      if ((rule.valves_down & rule.valves_up) != 0) {
        return f.error(at(rule.path, "valves_up"), "a valve cannot be both down and up");
      }
      out.standard.push_back(std::move(rule));
    }
  }
  return Status::success();
}

Status read_overrides(const Fields& f, const json& doc, InstrumentFile& out) {
  const Instrument& inst = out.instrument;
  if (!doc.contains("overrides")) return Status::success();
  auto list = f.array(doc.at("overrides"), "/overrides");
  if (!list) return list.error();
  for (std::size_t i = 0; i < (*list)->size(); ++i) {
    const json& item = (**list)[i];
    Override o;
    o.path = at("/overrides", i);
    if (auto ok = f.keys(item, o.path, {"written", "standard", "add", "remove", "reason"}); !ok) {
      return ok;
    }
    auto written_value = f.required(item, o.path, "written");
    if (!written_value) return written_value.error();
    auto written = f.pitch(**written_value, at(o.path, "written"));
    if (!written) return written.error();
    if (!inst.in_range_written(*written)) {
      return f.error(at(o.path, "written"), "outside the range in /range");
    }
    o.written = *written;
    if (!item.contains("standard") && !item.contains("add") && !item.contains("remove")) {
      return f.error(o.path, "needs \"standard\", \"add\" or \"remove\"");
    }
    if (item.contains("standard")) {
      auto ref = fingering_ref(f, inst, item.at("standard"), at(o.path, "standard"));
      if (!ref) return ref.error();
      o.has_standard = true;
      o.standard = *ref;
    }
    if (item.contains("remove")) {
      const std::string where = at(o.path, "remove");
      auto removes = f.array(item.at("remove"), where);
      if (!removes) return removes.error();
      for (std::size_t k = 0; k < (*removes)->size(); ++k) {
        auto ref = fingering_ref(f, inst, (**removes)[k], at(where, k));
        if (!ref) return ref.error();
        o.remove.push_back(*ref);
      }
    }
    if (item.contains("add")) {
      const std::string where = at(o.path, "add");
      auto adds = f.array(item.at("add"), where);
      if (!adds) return adds.error();
      for (std::size_t k = 0; k < (*adds)->size(); ++k) {
        const json& add = (**adds)[k];
        const std::string one = at(where, k);
        if (auto ok = f.keys(add, one, {"fingering", "partial"}); !ok) return ok.error();
        auto name = f.required(add, one, "fingering");
        if (!name) return name.error();
        auto ref = fingering_ref(f, inst, **name, at(one, "fingering"));
        if (!ref) return ref.error();
        auto partial_value = f.required(add, one, "partial");
        if (!partial_value) return partial_value.error();
        auto partial = f.integer(**partial_value, at(one, "partial"), 1, 32);
        if (!partial) return partial.error();
        ref->partial = *partial;
        o.add.push_back(*ref);
      }
    }
    out.overrides.push_back(std::move(o));
  }
  return Status::success();
}

}  // namespace

Result<InstrumentFile> parse_instrument_file(const json& doc, const std::string& file,
                                             const std::string& expected_id) {
  const content::JsonReader reader(file);
  const Fields f(reader);
  if (auto ok = f.keys(doc, "",
                       {"description", "sources", "id", "display_name", "names", "ambiguous_names",
                        "not_names", "preferred", "model", "gm_programs", "transposition_semitones", "range",
                        "mechanism", "harmonic_series", "conventions", "overrides"});
      !ok) {
    return ok.error();
  }
  InstrumentFile out;
  out.file = file;
  Instrument& inst = out.instrument;

  if (doc.contains("description")) {
    if (auto d = f.text(doc.at("description"), "/description"); !d) return d.error();
  }
  if (doc.contains("sources")) {
    auto sources = f.array(doc.at("sources"), "/sources");
    if (!sources) return sources.error();
    for (std::size_t i = 0; i < (*sources)->size(); ++i) {
      if (auto s = f.text((**sources)[i], at("/sources", i)); !s) return s.error();
    }
  }

  auto id_value = f.required(doc, "", "id");
  if (!id_value) return id_value.error();
  auto id = f.text(**id_value, "/id");
  if (!id) return id.error();
  const bool id_ok = !id->empty() && std::all_of(id->begin(), id->end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
  if (!id_ok) return f.error("/id", "expected lower-case letters, digits and '_'");
  if (!expected_id.empty() && *id != expected_id) {
    return f.error("/id", "\"" + *id + "\" differs from the file name \"" + expected_id + "\"");
  }
  inst.id = *id;

  auto display_value = f.required(doc, "", "display_name");
  if (!display_value) return display_value.error();
  auto display = f.text(**display_value, "/display_name");
  if (!display) return display.error();
  if (display->empty()) return f.error("/display_name", "must not be empty");
  inst.display_name = *display;

  auto names = phrases(f, doc, "names", true);
  if (!names) return names.error();
  inst.names = std::move(*names);
  auto ambiguous = phrases(f, doc, "ambiguous_names", false);
  if (!ambiguous) return ambiguous.error();
  inst.ambiguous_names = std::move(*ambiguous);
  auto not_names = phrases(f, doc, "not_names", false);
  if (!not_names) return not_names.error();
  inst.not_names = std::move(*not_names);

  if (doc.contains("preferred")) {
    if (!doc.at("preferred").is_boolean()) return f.error("/preferred", "expected true or false");
    inst.preferred = doc.at("preferred").get<bool>();
  }

  if (doc.contains("model")) {
    auto model = f.text(doc.at("model"), "/model");
    if (!model) return model.error();
    const bool model_ok = !model->empty() && std::all_of(model->begin(), model->end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    if (!model_ok) return f.error("/model", "expected lower-case letters, digits and '_'");
    inst.model = *model;
  }

  auto programs_value = f.required(doc, "", "gm_programs");
  if (!programs_value) return programs_value.error();
  auto programs = f.array(**programs_value, "/gm_programs");
  if (!programs) return programs.error();
  for (std::size_t i = 0; i < (*programs)->size(); ++i) {
    auto program = f.integer((**programs)[i], at("/gm_programs", i), 0, 127);
    if (!program) return program.error();
    if (std::find(inst.gm_programs.begin(), inst.gm_programs.end(), *program) !=
        inst.gm_programs.end()) {
      return f.error(at("/gm_programs", i), "listed twice");
    }
    inst.gm_programs.push_back(*program);
  }

  auto transposition_value = f.required(doc, "", "transposition_semitones");
  if (!transposition_value) return transposition_value.error();
  auto transposition = f.integer(**transposition_value, "/transposition_semitones", -36, 36);
  if (!transposition) return transposition.error();
  inst.transposition_semitones = *transposition;

  auto range_value = f.required(doc, "", "range");
  if (!range_value) return range_value.error();
  if (auto ok = f.keys(**range_value, "/range", {"lowest", "highest"}); !ok) return ok.error();
  for (const char* key : {"lowest", "highest"}) {
    auto value = f.required(**range_value, "/range", key);
    if (!value) return value.error();
    auto key_pitch = f.pitch(**value, at("/range", key));
    if (!key_pitch) return key_pitch.error();
    (std::string_view(key) == "lowest" ? inst.lowest_written : inst.highest_written) = *key_pitch;
  }
  if (inst.lowest_written > inst.highest_written) {
    return f.error("/range/highest", "must not be below /range/lowest");
  }
  const int lowest_sounding = inst.sounding(inst.lowest_written);
  const int highest_sounding = inst.sounding(inst.highest_written);
  if (lowest_sounding < 0 || highest_sounding > 127) {
    return f.error("/range", "sounds outside MIDI keys 0..127 after transposition");
  }

  if (auto ok = read_mechanism(f, doc, inst); !ok) return ok.error();
  if (auto ok = read_series(f, doc, out); !ok) return ok.error();
  if (auto ok = read_conventions(f, doc, out); !ok) return ok.error();
  if (auto ok = read_overrides(f, doc, out); !ok) return ok.error();
  return out;
}

}  // namespace tutti::brass_model
