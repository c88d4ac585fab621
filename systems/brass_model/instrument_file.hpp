// SPDX-License-Identifier: MIT
#pragma once
// One content/instruments/<id>.json as read and checked, before the chart is derived: the
// instrument's identity, range, mechanism and open series (already in `instrument`, whose chart
// is still empty) plus the conventions and overrides that the derivation applies
// (fingering_chart.hpp). Format: content/instruments/README.md.

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/core/result.hpp>

namespace tutti::brass_model {

// A fingering named in the file ("1-3", "T1"), optionally on a given partial (0 = any).
struct FingeringRef {
  std::uint8_t valves = 0;
  int position = 0;  // slide only
  int partial = 0;
  std::string text;  // as written, for messages
};

// How the standard fingering is chosen for written pitches from..to: only on these partials
// (empty = any), with these valves down and these up.
struct StandardRule {
  int from_written = 0;
  int to_written = 127;
  std::vector<int> partials;
  std::uint8_t valves_down = 0;
  std::uint8_t valves_up = 0;
  std::string path;  // JSON path, for messages
};

// A convention that differs from what the physics gives, for one written pitch.
struct Override {
  int written = 0;
  bool has_standard = false;
  FingeringRef standard;             // becomes the standard fingering
  std::vector<FingeringRef> add;     // listed although the rules leave them out (needs partial)
  std::vector<FingeringRef> remove;  // not listed although the rules give them
  std::string path;
};

struct InstrumentFile {
  Instrument instrument;              // everything but the chart
  std::string file;                   // as given, for messages
  double max_partial_cents = 25.0;    // partials further from equal temperament are not used
  double max_alternate_cents = 60.0;  // fingerings further out of tune are not listed
  double lip_cents = 0.0;             // slide: how far the lips bend a note past the slide's ends
  std::vector<std::uint8_t> preference;  // valve/trigger combinations, most preferred first
  std::vector<StandardRule> standard;
  std::vector<Override> overrides;
};

// Parses and checks the document. `file` names it in errors ("<file>: /range/lowest: ...");
// `expected_id` (the file stem) must equal "id" when not empty.
Result<InstrumentFile> parse_instrument_file(const nlohmann::json& document,
                                             const std::string& file,
                                             const std::string& expected_id);

}  // namespace tutti::brass_model
