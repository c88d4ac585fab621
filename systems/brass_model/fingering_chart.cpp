// SPDX-License-Identifier: MIT
#include <tutti/brass_model/fingering_chart.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <span>
#include <tuple>

#include <tutti/brass_model/brass_physics.hpp>
#include <tutti/brass_model/fingering_names.hpp>
#include <tutti/content/json_reader.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::brass_model {
namespace {

struct Candidate {
  Fingering fingering;
  int lowering = 0;      // nominal semitones: the combination's plus the slide's (p − 1)
  int preference = 0;    // index of the valve combination in the preference order
  bool allowed = false;  // by the standard rule for this pitch
};

using Column = std::vector<Candidate>;  // the fingerings of one written pitch

bool down(std::uint8_t mask, std::uint8_t valves) { return (mask & valves) == valves; }

// Preference index of every combination: the file's order, then the rest by mask.
std::vector<int> preference_of(const InstrumentFile& file, std::size_t combinations) {
  std::vector<int> rank(combinations, -1);
  int next = 0;
  for (std::uint8_t mask : file.preference) {
    if (mask < combinations) rank[mask] = next++;
  }
  for (std::size_t mask = 0; mask < combinations; ++mask) {
    if (rank[mask] < 0) rank[mask] = next++;
  }
  return rank;
}

// Every fingering the physics gives, by written pitch (column 0 = lowest_written).
std::vector<Column> candidates(const InstrumentFile& file) {
  const Instrument& inst = file.instrument;
  std::vector<Column> columns(std::size_t(inst.highest_written - inst.lowest_written + 1));
  const std::size_t combinations = std::size_t{1} << inst.valves.size();
  const std::vector<int> preference = preference_of(file, combinations);
  const bool slide = inst.mechanism == Mechanism::slide;
  auto add = [&](int written, const Candidate& c) {
    if (inst.in_range_written(written)) {
      columns[std::size_t(written - inst.lowest_written)].push_back(c);
    }
  };
  for (std::size_t m = 0; m < combinations; ++m) {
    const auto mask = static_cast<std::uint8_t>(m);
    const double lowering = combination_lowering_semitones(inst.valves, mask);
    const int nominal = combination_nominal_semitones(inst.valves, mask);
    for (int partial : inst.partials) {
      if (std::abs(partial_cents(partial)) > file.max_partial_cents) continue;
      // Tuning of the note the chart names, before any correction.
      const double cents = partial_cents(partial) - 100.0 * (lowering - nominal);
      if (std::abs(cents) > file.max_alternate_cents) continue;
      const int open = inst.fundamental_written + partial_nominal_semitones(partial) - nominal;
      Candidate c;
      c.preference = preference[m];
      c.fingering.valves = mask;
      c.fingering.partial = static_cast<std::uint8_t>(partial);
      c.fingering.cents = static_cast<float>(cents);
      if (!slide) {
        c.lowering = nominal;
        add(open, c);
        continue;
      }
      // The slide lengthens the tube the triggers leave; it goes where the note is in tune.
      const double tube_mm = inst.tube_length_mm * std::exp2(lowering / 12.0);
      const double longest = slide_semitones(tube_mm, inst.slide_length_mm);
      for (int position = 1; position <= inst.positions; ++position) {
        const double in_tune = (position - 1) + cents / 100.0;
        const double beyond = 100.0 * std::max(-in_tune, in_tune - longest);
        if (beyond > file.lip_cents) continue;
        c.lowering = nominal + position - 1;
        c.fingering.position = static_cast<std::uint8_t>(position);
        c.fingering.slide_mm = static_cast<float>(
            std::clamp(slide_extension_mm(tube_mm, in_tune), 0.0, inst.slide_length_mm));
        add(open - (position - 1), c);
      }
    }
  }
  return columns;
}

const StandardRule* rule_for(const InstrumentFile& file, int written) {
  for (const StandardRule& rule : file.standard) {
    if (written >= rule.from_written && written <= rule.to_written) return &rule;
  }
  return nullptr;
}

bool allows(const StandardRule* rule, const Fingering& f) {
  if (rule == nullptr) return true;
  if (!rule->partials.empty() && std::find(rule->partials.begin(), rule->partials.end(),
                                           int(f.partial)) == rule->partials.end()) {
    return false;
  }
  return down(f.valves, rule->valves_down) && (f.valves & rule->valves_up) == 0;
}

// Standard first, then the alternates in order of preference.
void order(Column& column) {
  auto standard_key = [](const Candidate& c) {
    return std::make_tuple(!c.allowed, c.lowering, c.preference, c.fingering.partial,
                           c.fingering.position);
  };
  auto alternate_key = [](const Candidate& c) {
    return std::make_tuple(c.preference, std::lround(std::abs(c.fingering.cents) * 10.0f),
                           c.lowering, c.fingering.partial, c.fingering.position);
  };
  if (column.empty()) return;
  auto best = std::min_element(column.begin(), column.end(), [&](const auto& a, const auto& b) {
    return standard_key(a) < standard_key(b);
  });
  std::iter_swap(column.begin(), best);
  std::stable_sort(column.begin() + 1, column.end(), [&](const auto& a, const auto& b) {
    return alternate_key(a) < alternate_key(b);
  });
}

bool same(const Fingering& f, const FingeringRef& ref) {
  return f.valves == ref.valves && f.position == ref.position &&
         (ref.partial == 0 || f.partial == ref.partial);
}

// The file's override for one written pitch. Errors: a named fingering that is not there.
Status apply(const InstrumentFile& file, const Override& o, Column& column) {
  const content::JsonReader reader(file.file);
  const Instrument& inst = file.instrument;
  const std::string pitch = music::pitch_name(o.written);
  for (std::size_t k = 0; k < o.remove.size(); ++k) {
    const auto it = std::find_if(column.begin(), column.end(), [&](const Candidate& c) {
      return same(c.fingering, o.remove[k]);
    });
    if (it == column.end()) {
      return reader.error(o.path + "/remove/" + std::to_string(k),
                          "the rules give no \"" + o.remove[k].text + "\" for " + pitch);
    }
    column.erase(it);
  }
  for (std::size_t k = 0; k < o.add.size(); ++k) {
    const FingeringRef& ref = o.add[k];
    const std::string where = o.path + "/add/" + std::to_string(k);
    if (std::find(inst.partials.begin(), inst.partials.end(), ref.partial) == inst.partials.end()) {
      return reader.error(where + "/partial", "not in /harmonic_series/partials");
    }
    const double lowering = combination_lowering_semitones(inst.valves, ref.valves);
    const int nominal = combination_nominal_semitones(inst.valves, ref.valves);
    const int shift = nominal + std::max(ref.position - 1, 0);
    const int sounds = inst.fundamental_written + partial_nominal_semitones(ref.partial) - shift;
    if (sounds != o.written) {
      return reader.error(where, "\"" + ref.text + "\" on partial " + std::to_string(ref.partial) +
                                     " plays " + music::pitch_name(sounds) + ", not " + pitch);
    }
    if (std::any_of(column.begin(), column.end(),
                    [&](const Candidate& c) { return same(c.fingering, ref); })) {
      return reader.error(where, "\"" + ref.text + "\" is already in the chart for " + pitch);
    }
    Candidate c;
    c.fingering.valves = ref.valves;
    c.fingering.position = static_cast<std::uint8_t>(ref.position);
    c.fingering.partial = static_cast<std::uint8_t>(ref.partial);
    c.fingering.cents =
        static_cast<float>(partial_cents(ref.partial) - 100.0 * (lowering - nominal));
    if (inst.mechanism == Mechanism::slide) {
      const double tube_mm = inst.tube_length_mm * std::exp2(lowering / 12.0);
      const double in_tune = (ref.position - 1) + c.fingering.cents / 100.0;
      c.fingering.slide_mm = static_cast<float>(
          std::clamp(slide_extension_mm(tube_mm, in_tune), 0.0, inst.slide_length_mm));
    }
    column.push_back(c);  // an added fingering is an alternate unless named the standard
  }
  if (o.has_standard) {
    const auto it = std::find_if(column.begin(), column.end(),
                                 [&](const Candidate& c) { return same(c.fingering, o.standard); });
    if (it == column.end()) {
      return reader.error(o.path + "/standard",
                          "the chart has no \"" + o.standard.text + "\" for " + pitch);
    }
    std::rotate(column.begin(), it, it + 1);
  }
  return Status::success();
}

}  // namespace

Status derive_chart(InstrumentFile& file) {
  Instrument& inst = file.instrument;
  const content::JsonReader reader(file.file);
  std::vector<Column> columns = candidates(file);
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const int written = inst.lowest_written + int(i);
    Column& column = columns[i];
    if (column.empty()) {
      return reader.error("/range", "no fingering plays written " + music::pitch_name(written) +
                                        " (check the range, partials and tolerances)");
    }
    const StandardRule* rule = rule_for(file, written);
    for (Candidate& c : column) c.allowed = allows(rule, c.fingering);
    if (std::none_of(column.begin(), column.end(), [](const Candidate& c) { return c.allowed; })) {
      return reader.error(rule->path,
                          "allows no fingering of written " + music::pitch_name(written));
    }
    order(column);
  }
  for (const Override& o : file.overrides) {
    if (auto ok = apply(file, o, columns[std::size_t(o.written - inst.lowest_written)]); !ok) {
      return ok;
    }
  }
  inst.chart.clear();
  inst.chart_begin.clear();
  for (Column& column : columns) {
    if (column.empty()) {
      return reader.error(
          "/overrides", "leave written " +
                            music::pitch_name(inst.lowest_written + int(inst.chart_begin.size())) +
                            " without a fingering");
    }
    inst.chart_begin.push_back(int(inst.chart.size()));
    for (std::size_t r = 0; r < column.size(); ++r) {
      Fingering f = column[r].fingering;
      f.rank = static_cast<std::uint8_t>(std::min<std::size_t>(r, 255));
      inst.chart.push_back(f);
    }
  }
  inst.chart_begin.push_back(int(inst.chart.size()));
  return Status::success();
}

}  // namespace tutti::brass_model
