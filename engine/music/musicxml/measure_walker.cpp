// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/measure_walker.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string_view>

#include <tutti/music/musicxml/fingering_text.hpp>
#include <tutti/music/musicxml/grace_placement.hpp>
#include <tutti/music/musicxml/notation_values.hpp>
#include <tutti/music/musicxml/tick_resolution.hpp>
#include <tutti/music/musicxml/xml_text_values.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::music::musicxml {

namespace {

constexpr double kMaxBpm = 10000.0;

bool named(pugi::xml_node node, const char* name) { return std::strcmp(node.name(), name) == 0; }

// "part P1 measure 3" for messages; measures without a number are counted ("measure #3").
std::string part_and_measure(const PartLayout& part, std::size_t slot) {
  std::string where =
      "part " + (part.info.id.empty() ? std::string("(no id)") : one_line(part.info.id));
  if (slot < part.measures.size()) {
    const MeasureSlot& measure = part.measures[slot];
    const std::string_view number = measure.measure.attribute("number").as_string();
    where += number.empty() ? " measure #" + std::to_string(measure.index + 1)
                            : " measure " + one_line(number, 32);
  }
  return where;
}

struct PendingGrace {
  Note note;
  bool joins_chord = false;  // <grace/><chord/>: sounds with the grace before it
  bool steal_previous = false;
  std::optional<double> steal_percent;
};

class PartWalker {
 public:
  PartWalker(const PartLayout& part, const WalkSettings& settings)
      : part_(part), settings_(settings) {}

  Result<PartTimeline> run() {
    std::int64_t own_start = 0;
    for (std::size_t i = 0; i < part_.measures.size(); ++i) {
      slot_ = i;
      const MeasureSlot& measure = part_.measures[i];
      const std::int64_t start =
          settings_.measure_starts.empty() ? own_start : settings_.measure_starts[measure.index];
      if (Status walked = walk_measure(measure, start); !walked) return walked.error();
      const std::int64_t length = measure_end_ - start;
      timeline_.measure_lengths.emplace_back(measure.index, length);
      own_start = start + length;
      if (own_start > kMaxTicks) return fail("the music runs past 2^50 ticks");
    }
    timeline_.end_ticks = own_start;
    finish_part(own_start);
    return std::move(timeline_);
  }

 private:
  // --- errors -----------------------------------------------------------------------------

  Error fail(const std::string& reason) const {
    return Error{settings_.source + ": " + part_and_measure(part_, slot_) + ": " + reason};
  }

  // --- time -------------------------------------------------------------------------------

  // A <duration>-like element (in divisions) as ticks; `owner` names the element it belongs to.
  Result<std::int64_t> ticks_of(pugi::xml_node duration, std::string_view owner) const {
    const std::string what =
        owner == "note" ? "<duration>" : "<duration> of <" + std::string(owner) + ">";
    if (!duration) return fail("<" + std::string(owner) + "> has no <duration>");
    const auto value = parse_decimal(trimmed_text(duration));
    if (!value) return fail(what + " is not a number");
    if (*value < 0.0) return fail(what + " is negative");
    const auto ticks = divisions_to_ticks(*value, divisions_, settings_.ticks_per_quarter);
    if (!ticks) return fail(what + " is absurdly long");
    return *ticks;
  }

  Status advance(std::int64_t ticks) {
    if (ticks > kMaxTicks - position_) return fail("the music runs past 2^50 ticks");
    position_ += ticks;
    measure_end_ = std::max(measure_end_, position_);
    return Status::success();
  }

  // --- measures ---------------------------------------------------------------------------

  Status walk_measure(const MeasureSlot& slot, std::int64_t start) {
    measure_start_ = start;
    position_ = start;
    measure_end_ = start;
    has_chord_anchor_ = false;
    if (!slot.content) return Status::success();
    for (pugi::xml_node child : slot.content.children()) {
      Status status;
      if (named(child, "note")) {
        status = note(child);
      } else if (named(child, "backup")) {
        status = backup(child);
      } else if (named(child, "forward")) {
        status = forward(child);
      } else if (named(child, "attributes")) {
        status = attributes(child);
      } else if (named(child, "direction")) {
        direction(child);
      } else if (named(child, "sound")) {
        sound(child, position_, /*pedal_marks_present=*/false);
      }
      if (!status) return status;
    }
    return Status::success();
  }

  Status backup(pugi::xml_node element) {
    auto ticks = ticks_of(element.child("duration"), "backup");
    if (!ticks) return ticks.error();
    // Real files do this (11b of the MusicXML test suite backs up 384 divisions in a measure of
    // 4): the cursor stops at the start of the measure, which is what the writer meant.
    position_ -= std::min(*ticks, position_ - measure_start_);
    has_chord_anchor_ = false;
    return Status::success();
  }

  Status forward(pugi::xml_node element) {
    auto ticks = ticks_of(element.child("duration"), "forward");
    if (!ticks) return ticks.error();
    has_chord_anchor_ = false;
    return advance(*ticks);
  }

  // --- attributes -------------------------------------------------------------------------

  Status attributes(pugi::xml_node element) {
    if (pugi::xml_node divisions = element.child("divisions")) {
      const auto value = parse_decimal(trimmed_text(divisions));
      if (!value || *value <= 0.0) return fail("<divisions> must be a positive number");
      divisions_ = *value;
    }
    // <transpose> comes after <key> in the element, but the key is written transposed.
    for (pugi::xml_node transpose : element.children("transpose")) {
      const std::string_view staff = transpose.attribute("number").as_string();
      if (!staff.empty() && staff != "1") continue;  // one transposition per part: staff 1's
      const auto chromatic = parse_decimal(trimmed_text(transpose.child("chromatic")));
      const auto octaves = parse_integer(trimmed_text(transpose.child("octave-change")));
      if (!chromatic || std::abs(*chromatic) > 48.0) continue;
      const std::int64_t octave_change = octaves ? std::clamp<std::int64_t>(*octaves, -4, 4) : 0;
      transpose_ = static_cast<int>(std::lround(*chromatic)) + static_cast<int>(octave_change) * 12;
      if (!timeline_.first_transpose) timeline_.first_transpose = transpose_;
      break;
    }
    for (pugi::xml_node key : element.children("key")) key_signature(key);
    for (pugi::xml_node time : element.children("time")) time_signature(time);
    if (const auto staves = parse_integer(trimmed_text(element.child("staves")))) {
      timeline_.staves =
          std::max(timeline_.staves, static_cast<int>(std::clamp<std::int64_t>(*staves, 1, 64)));
    }
    return Status::success();
  }

  void key_signature(pugi::xml_node key) {
    const std::string_view staff = key.attribute("number").as_string();
    if (!staff.empty() && staff != "1") return;  // the score keeps one key: staff 1's
    const auto fifths = parse_integer(trimmed_text(key.child("fifths")));
    if (!fifths || *fifths < -7 || *fifths > 7) return;  // non-traditional or theoretical keys
    KeySignature signature;
    signature.tick = position_;
    signature.fifths = concert_fifths(static_cast<int>(*fifths), transpose_);
    signature.minor = trimmed_text(key.child("mode")) == "minor";
    timeline_.key_signatures.push_back(signature);
  }

  void time_signature(pugi::xml_node time) {
    const auto fraction = time_signature_fraction(time);
    if (!fraction) return;
    TimeSignature signature;
    signature.tick = position_;
    signature.numerator = fraction->first;
    signature.denominator = fraction->second;
    timeline_.time_signatures.push_back(signature);
  }

  // --- directions -------------------------------------------------------------------------

  void direction(pugi::xml_node element) {
    std::int64_t tick = position_;
    const pugi::xml_node offset = element.child("offset");
    if (offset && offset.attribute("sound").as_bool()) {
      if (const auto value = parse_decimal(trimmed_text(offset))) {
        if (const auto ticks =
                divisions_to_ticks(std::abs(*value), divisions_, settings_.ticks_per_quarter)) {
          tick = std::clamp<std::int64_t>(*value < 0 ? tick - *ticks : tick + *ticks, 0, kMaxTicks);
        }
      }
    }
    bool pedal_marks = false;
    bool sound_tempo = false;
    bool sound_dynamics = false;
    for (pugi::xml_node sound_element : element.children("sound")) {
      sound_tempo = sound_tempo || sound_element.attribute("tempo");
      sound_dynamics = sound_dynamics || sound_element.attribute("dynamics");
    }
    for (pugi::xml_node type : element.children("direction-type")) {
      for (pugi::xml_node pedal : type.children("pedal")) {
        pedal_marks = true;
        pedal_mark(pedal.attribute("type").as_string(), tick);
      }
      if (!sound_tempo) {
        if (const auto bpm = metronome_bpm(type.child("metronome"))) tempo(tick, *bpm);
      }
      if (!sound_dynamics) {
        for (pugi::xml_node mark : type.child("dynamics").children()) {
          if (const auto velocity = velocity_of_dynamics_mark(mark.name())) velocity_ = *velocity;
        }
      }
    }
    for (pugi::xml_node sound_element : element.children("sound")) {
      sound(sound_element, tick, pedal_marks);
    }
  }

  void sound(pugi::xml_node element, std::int64_t tick, bool pedal_marks_present) {
    if (const auto bpm = parse_decimal(element.attribute("tempo").as_string())) tempo(tick, *bpm);
    if (const auto velocity = velocity_from_percent(element.attribute("dynamics").as_string())) {
      velocity_ = *velocity;
    }
    if (pugi::xml_attribute damper = element.attribute("damper-pedal");
        damper && !pedal_marks_present) {
      const std::string_view value = damper.as_string();
      const auto amount = parse_decimal(value);
      const bool down = value == "yes" || (amount && *amount > 0.0);
      pedal_mark(down ? "start" : "stop", tick);
    }
  }

  void tempo(std::int64_t tick, double bpm) {
    if (!(bpm > 0.0) || bpm > kMaxBpm) return;
    timeline_.tempos.emplace_back(tick, 60'000'000.0 / bpm);
  }

  void pedal_mark(std::string_view type, std::int64_t tick) {
    if (type == "start" || type == "change") {
      lift_pedal(tick);  // a start while down acts as a change
      pedal_down_since_ = tick;
    } else if (type == "stop") {
      lift_pedal(tick);
    }
    // continue, resume, discontinue: no change; sostenuto is a different pedal.
  }

  void lift_pedal(std::int64_t tick) {
    if (!pedal_down_since_) return;
    if (tick > *pedal_down_since_) {
      PedalSpan span;
      span.onset_ticks = *pedal_down_since_;
      span.offset_ticks = tick;
      timeline_.pedal_spans.push_back(span);
    }
    pedal_down_since_.reset();
  }

  // --- notes ------------------------------------------------------------------------------

  Status note(pugi::xml_node element) {
    const auto ordinal = settings_.ordinals.find(element.internal_object());
    const int source_index = ordinal == settings_.ordinals.end() ? -1 : ordinal->second;
    const bool grace = element.child("grace");
    const bool chord = element.child("chord");

    std::int64_t duration = 0;
    std::int64_t onset = position_;
    if (!grace) {
      auto ticks = ticks_of(element.child("duration"), "note");
      if (!ticks) return ticks.error();
      duration = *ticks;
      if (chord && has_chord_anchor_) {
        onset = chord_anchor_;
      } else {
        onset = position_;
        if (Status moved = advance(duration); !moved) return moved;
        chord_anchor_ = onset;
        has_chord_anchor_ = true;
        chord_shift_ = 0;
      }
    }
    if (element.child("cue")) return Status::success();  // printed small, not played

    const int voice = voice_of(element);
    if (element.child("rest")) {
      if (!grace && !chord) place_graces(voice, onset, duration, /*host_is_note=*/false);
      return Status::success();
    }
    auto pitch = sounding_pitch(element);
    if (!pitch) return pitch.error();
    if (*pitch < 0) return Status::success();  // outside MIDI, or an unplayable percussion note

    Note note;
    note.pitch = *pitch;
    note.voice = voice;
    note.staff = staff_of(element);
    note.velocity = velocity_;
    if (const auto velocity = velocity_from_percent(element.attribute("dynamics").as_string())) {
      note.velocity = *velocity;
    }
    note.grace = grace;
    note.source_index = source_index;
    read_fingering(element, note);
    timeline_.staves = std::max(timeline_.staves, note.staff);

    if (grace) {
      queue_grace(element, note, chord, voice);
      return Status::success();
    }
    if (!chord) chord_shift_ = place_graces(voice, onset, duration, /*host_is_note=*/true);
    note.onset_ticks = onset + std::min(chord_shift_, duration);
    note.offset_ticks = onset + duration;
    TieMarkedNote marked{note, false, false};
    read_ties(element, marked);
    last_note_of_voice_[voice] = timeline_.notes.size();
    timeline_.notes.push_back(marked);
    return Status::success();
  }

  static int voice_of(pugi::xml_node element) {
    const auto voice = parse_integer(trimmed_text(element.child("voice")));
    return voice && *voice > 0 && *voice < 1000 ? static_cast<int>(*voice) : 0;
  }

  static int staff_of(pugi::xml_node element) {
    const auto staff = parse_integer(trimmed_text(element.child("staff")));
    return staff && *staff > 0 && *staff <= 64 ? static_cast<int>(*staff) : 0;
  }

  // The sounding MIDI key, or -1 when the note cannot sound on a MIDI key.
  Result<int> sounding_pitch(pugi::xml_node element) {
    if (pugi::xml_node pitch = element.child("pitch")) {
      auto written =
          midi_key_of(pitch.child("step"), pitch.child("alter"), pitch.child("octave"), "pitch");
      if (!written) return written.error();
      if (*written < 0) return -1;
      const int sounding = *written + transpose_;
      return sounding >= 0 && sounding <= 127 ? sounding : -1;
    }
    if (pugi::xml_node unpitched = element.child("unpitched")) {
      timeline_.unpitched = true;
      const int key =
          unpitched_key(part_.info, element.child("instrument").attribute("id").as_string());
      if (key >= 0) return key;
      if (!unpitched.child("display-step")) return -1;
      return midi_key_of(unpitched.child("display-step"), {}, unpitched.child("display-octave"),
                         "unpitched");
    }
    return -1;  // neither pitch nor rest: nothing to play
  }

  Result<int> midi_key_of(pugi::xml_node step, pugi::xml_node alter, pugi::xml_node octave,
                          const char* owner) const {
    const std::string_view step_text = trimmed_text(step);
    if (step_text.size() != 1 || step_text[0] < 'A' || step_text[0] > 'G') {
      return fail(std::string("<") + owner + "> step must be one of A-G");
    }
    const auto octave_value = parse_integer(trimmed_text(octave));
    if (!octave_value) return fail(std::string("<") + owner + "> octave is not a whole number");
    double alter_value = 0.0;
    if (alter) {
      const auto parsed = parse_decimal(trimmed_text(alter));
      if (!parsed) return fail(std::string("<") + owner + "> <alter> is not a number");
      alter_value = *parsed;
    }
    if (std::abs(alter_value) > 4.0 || *octave_value < -2 || *octave_value > 10) return -1;
    // Microtones (-0.5, 1.5) round to the nearest semitone.
    const auto key = midi_key(step_text[0], static_cast<int>(std::lround(alter_value)),
                              static_cast<int>(*octave_value));
    return key ? *key : -1;
  }

  // The first plain <fingering> with a finger; a substitution comes from its own text ("3-1")
  // or from a <fingering substitution="yes">. Alternate fingerings are ignored.
  static void read_fingering(pugi::xml_node element, Note& note) {
    int substitute = 0;
    for (pugi::xml_node notations : element.children("notations")) {
      for (pugi::xml_node technical : notations.children("technical")) {
        for (pugi::xml_node fingering : technical.children("fingering")) {
          if (fingering.attribute("alternate").as_bool()) continue;
          const auto mark = parse_fingering_text(fingering.text().get());
          if (!mark) continue;
          if (fingering.attribute("substitution").as_bool()) {
            if (substitute == 0) substitute = mark->finger;
          } else if (note.finger == 0) {
            note.finger = mark->finger;
            note.finger_substitute = mark->substitute;
          }
        }
      }
    }
    if (note.finger != 0 && note.finger_substitute == 0) note.finger_substitute = substitute;
  }

  // <tie> is the sound; when a file only has the notation <tied>, that is used instead.
  static void read_ties(pugi::xml_node element, TieMarkedNote& marked) {
    auto mark = [&](std::string_view type) {
      if (type == "start" || type == "continue") marked.tie_start = true;
      if (type == "stop" || type == "continue") marked.tie_stop = true;
    };
    bool any_tie = false;
    for (pugi::xml_node tie : element.children("tie")) {
      any_tie = true;
      mark(tie.attribute("type").as_string());
    }
    if (any_tie) return;
    for (pugi::xml_node notations : element.children("notations")) {
      for (pugi::xml_node tied : notations.children("tied")) {
        mark(tied.attribute("type").as_string());
      }
    }
  }

  // --- grace notes (policy in grace_placement.hpp) ----------------------------------------

  void queue_grace(pugi::xml_node element, const Note& note, bool chord, int voice) {
    const pugi::xml_node grace = element.child("grace");
    PendingGrace pending;
    pending.note = note;
    pending.joins_chord = chord && !pending_graces_[voice].empty();
    if (pugi::xml_attribute previous = grace.attribute("steal-time-previous")) {
      pending.steal_previous = true;
      pending.steal_percent = parse_decimal(previous.as_string());
    } else if (pugi::xml_attribute following = grace.attribute("steal-time-following")) {
      pending.steal_percent = parse_decimal(following.as_string());
    }
    pending_graces_[voice].push_back(pending);
  }

  // Places the graces waiting in `voice` before a note (or rest) at `host_onset`; returns how
  // far that note's onset moves to let on-beat graces sound first. Leading graces marked
  // steal-time-previous are after-graces of the previous note instead.
  std::int64_t place_graces(int voice, std::int64_t host_onset, std::int64_t host_ticks,
                            bool host_is_note) {
    std::vector<PendingGrace> run = take_pending_graces(voice);
    std::size_t after_graces = 0;
    while (after_graces < run.size() && (run[after_graces].steal_previous ||
                                         (after_graces > 0 && run[after_graces].joins_chord))) {
      ++after_graces;
    }
    if (after_graces > 0 &&
        place_before_beat(voice, std::span(run).first(after_graces), host_onset)) {
      run.erase(run.begin(), run.begin() + static_cast<std::ptrdiff_t>(after_graces));
    }
    if (run.empty()) return 0;
    const std::int64_t total = grace_run_ticks(
        slot_count(run), host_ticks, run.front().steal_percent, settings_.ticks_per_quarter);
    emit_graces(run, host_onset, total);
    return host_is_note ? total : 0;
  }

  std::vector<PendingGrace> take_pending_graces(int voice) {
    std::vector<PendingGrace> run;
    auto waiting = pending_graces_.find(voice);
    if (waiting != pending_graces_.end()) {
      run = std::move(waiting->second);
      pending_graces_.erase(waiting);
    }
    return run;
  }

  static std::int64_t slot_count(std::span<const PendingGrace> run) {
    return static_cast<std::int64_t>(std::count_if(
        run.begin(), run.end(), [](const PendingGrace& g) { return !g.joins_chord; }));
  }

  // Ends the graces where the voice's previous note ends (no later than `limit`), cutting that
  // note short. False when the voice has no previous note to steal from.
  bool place_before_beat(int voice, std::span<const PendingGrace> run, std::int64_t limit) {
    auto last = last_note_of_voice_.find(voice);
    if (last == last_note_of_voice_.end()) return false;
    const Note& previous = timeline_.notes[last->second].note;
    const std::int64_t end = std::min(previous.offset_ticks, std::max(limit, previous.onset_ticks));
    const std::int64_t wanted =
        grace_run_ticks(slot_count(run), previous.offset_ticks - previous.onset_ticks,
                        run.front().steal_percent, settings_.ticks_per_quarter);
    const std::int64_t start = std::max(end - wanted, previous.onset_ticks);
    trim_chord_ending(last->second, start);
    emit_graces(run, start, end - start);
    return true;
  }

  void emit_graces(std::span<const PendingGrace> run, std::int64_t start, std::int64_t total) {
    const std::int64_t slots = slot_count(run);
    std::int64_t slot = -1;
    for (const PendingGrace& grace : run) {
      if (!grace.joins_chord || slot < 0) ++slot;
      TieMarkedNote placed{grace.note, false, false};
      placed.note.onset_ticks = grace_slot_start(start, total, slots, slot);
      placed.note.offset_ticks = grace_slot_start(start, total, slots, slot + 1);
      timeline_.notes.push_back(placed);
    }
  }

  // Cuts the chord that ends with note `last` (the notes of its voice sharing its onset; a
  // chord's notes are adjacent in the timeline) so that it ends by `end`.
  void trim_chord_ending(std::size_t last, std::int64_t end) {
    const Note anchor = timeline_.notes[last].note;
    for (std::size_t i = last + 1; i-- > 0;) {
      Note& note = timeline_.notes[i].note;
      if (note.grace) continue;
      if (note.voice != anchor.voice || note.onset_ticks != anchor.onset_ticks) break;
      note.offset_ticks = std::min(note.offset_ticks, end);
    }
  }

  void finish_part(std::int64_t end) {
    // Graces with no note after them in their voice end the voice's last note (after-graces);
    // in a voice with no note at all they follow the end of the part.
    std::vector<int> voices;
    for (const auto& [voice, run] : pending_graces_) voices.push_back(voice);
    for (const int voice : voices) {
      const std::vector<PendingGrace> run = take_pending_graces(voice);
      if (run.empty() || place_before_beat(voice, run, end)) continue;
      emit_graces(run, end, slot_count(run) * std::max(settings_.ticks_per_quarter / 8, 1));
    }
    lift_pedal(end);
  }

  const PartLayout& part_;
  const WalkSettings& settings_;
  PartTimeline timeline_;

  std::size_t slot_ = 0;  // position in part_.measures of the measure being walked
  std::int64_t measure_start_ = 0;
  std::int64_t measure_end_ = 0;
  std::int64_t position_ = 0;
  double divisions_ = 1.0;  // MusicXML requires <divisions> before durations; 1 if a file forgets

  bool has_chord_anchor_ = false;
  std::int64_t chord_anchor_ = 0;  // onset of the note that <chord/> notes join
  std::int64_t chord_shift_ = 0;   // how far on-beat graces moved that note

  int velocity_ = kDefaultVelocity;
  int transpose_ = 0;
  std::optional<std::int64_t> pedal_down_since_;
  std::map<int, std::vector<PendingGrace>> pending_graces_;
  std::map<int, std::size_t> last_note_of_voice_;  // index into timeline_.notes
};

}  // namespace

Result<std::vector<double>> collect_divisions(const std::vector<PartLayout>& parts,
                                              const std::string& source) {
  std::set<double> distinct;
  for (const PartLayout& part : parts) {
    for (std::size_t i = 0; i < part.measures.size(); ++i) {
      if (!part.measures[i].content) continue;
      for (pugi::xml_node attributes : part.measures[i].content.children("attributes")) {
        const pugi::xml_node divisions = attributes.child("divisions");
        if (!divisions) continue;
        const auto value = parse_decimal(trimmed_text(divisions));
        if (!value || *value <= 0.0) {
          return Error{source + ": " + part_and_measure(part, i) +
                       ": <divisions> must be a positive number"};
        }
        distinct.insert(*value);
      }
    }
  }
  return std::vector<double>(distinct.begin(), distinct.end());
}

Result<PartTimeline> walk_part(const PartLayout& part, const WalkSettings& settings) {
  return PartWalker(part, settings).run();
}

}  // namespace tutti::music::musicxml
