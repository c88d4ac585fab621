// SPDX-License-Identifier: MIT
#pragma once
// A brass instrument as data (content/instruments/<id>.json): how it is named, how it transposes,
// its range, its mechanism (valves or a slide), its open harmonic series, and the fingering chart
// derived from those (physics + the file's overrides), alternates in order of preference.
// Namespace tutti::brass. A new instrument needs only a new data file.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::brass_model {

enum class Mechanism { valves, slide };

constexpr int kMaxValves = 6;  // incl. a thumb valve (double horn) or a trigger (F attachment)

struct ValveSpec {
  std::string name;                // "1", "2", "3", "4", "T" (thumb / trigger)
  double lowers_semitones = 0.0;   // alone; a valve whose "switches_side" is set changes series
  // Double horn's thumb valve: routes the air through a second, shorter set of tubes (B♭ side;
  // lowers_semitones = -5), each valve having its own loop tuned for that side. A trigger (a
  // trombone's F attachment) is not a side switch: it adds one fixed loop.
  bool switches_side = false;
};

// One way to play a written pitch.
struct Fingering {
  std::uint8_t valves = 0;    // bit i = ValveSpec i down (valves; a slide's trigger is a valve)
  std::uint8_t position = 0;  // slide position 1..7 (slide), 0 = no slide
  std::uint8_t partial = 0;   // the harmonic used (1 = pedal tone)
  std::uint8_t rank = 0;      // 0 = the standard fingering, 1, 2, ... = alternates
  float slide_mm = 0.0f;      // slide extension from 1st position, where the note is in tune
  float cents = 0.0f;         // tuning before the player's correction (+ = sharp)
};

struct Instrument {
  std::string id;            // file stem, e.g. "trumpet_bb"
  std::string display_name;  // "B♭ trumpet"
  std::vector<std::string> names;  // lower-case words that identify it in a part name
  std::vector<int> gm_programs;    // General MIDI programs, 0-based (56 = trumpet)
  int transposition_semitones = 0;  // sounding = written + transposition
  int lowest_written = 0;           // playable range, written MIDI keys (inclusive)
  int highest_written = 0;
  Mechanism mechanism = Mechanism::valves;
  std::vector<ValveSpec> valves;  // valves, or the slide's trigger(s)
  double max_slide_speed_mm_per_s = 0.0;  // slide only
  // Slide only: the furthest extension the player's arm reaches (0: any). Further out, the
  // planner takes another position when the note has one.
  double slide_reach_mm = 0.0;
  double slide_length_mm = 0.0;           // slide only: 7th position

  // Added by the data loader (backward compatible): the physics the chart was derived from.
  std::vector<std::string> ambiguous_names;  // identify it only with a GM brass program (56..63)
  std::vector<std::string> not_names;        // a part name containing one of these is not it
  int fundamental_written = 0;  // written MIDI key of partial 1 (pedal), all valves up / 1st pos.
  std::vector<int> partials;    // the partials the player uses (open series), ascending
  double tube_length_mm = 0.0;  // effective tube length, valves up / slide in (see brass_physics)
  int positions = 0;            // slide only: number of positions (7)
  // The one a part gets when its name and program fit several (B♭ among the trumpets: most
  // trumpet parts are played on it) and it states no key.
  bool preferred = false;
  // The generated model that plays it (<model>.glb) and its hold
  // (instruments/holds/<model>.json); empty: "trombone" for a slide, else "trumpet".
  std::string model;
  const std::string& model_name() const;

  int sounding(int written) const { return written + transposition_semitones; }
  int written(int sounding) const { return sounding - transposition_semitones; }
  bool in_range_written(int written) const {
    return written >= lowest_written && written <= highest_written;
  }
  // Fingerings of a written pitch, standard first; empty outside the range.
  std::span<const Fingering> fingerings(int written) const;

  // The chart, flat: fingerings of written pitch p are chart[chart_begin[p - lowest_written] ..
  // chart_begin[p - lowest_written + 1]).
  std::vector<Fingering> chart;
  std::vector<int> chart_begin;
};

// Reads and checks one instrument file, derives its chart. Errors name the file and JSON path.
Result<Instrument> load_instrument(const std::filesystem::path& file);
// content/instruments/<id>.json (content dir: content/content_dir.hpp).
Result<Instrument> load_instrument_by_id(std::string_view id);
// The same from content_dir/instruments.
Result<Instrument> load_instrument_by_id(std::string_view id,
                                         const std::filesystem::path& content_dir);
// Every *.json in content/instruments, sorted by id.
Result<std::vector<Instrument>> load_all_instruments();

// The instrument a score part is written for: its name (words of Instrument::names, e.g.
// "Trumpet in Bb", "Tromba 1", "2 Horns in E"), else its GM program; nullptr = no brass.
// Among several trumpets, the part's transposition picks the one that matches.
const Instrument* detect_instrument(const music::Part& part, std::span<const Instrument> known);

// Human name of a valve combination ("open", "1-3", "1-2-3", "T-2"; side-switching valves
// first, the others in file order); of a slide fingering: "3", "T1" (trigger), with the partial
// when asked ("1-3 (partial 4)").
std::string fingering_name(const Instrument& instrument, const Fingering& fingering,
                           bool with_partial = false);

}  // namespace tutti::brass_model
