// SPDX-License-Identifier: MIT
#pragma once
// Step 3 of reading a Standard MIDI File: turn the decoded events of every track into the Score
// model. What the events mean:
//  - note-on with velocity > 0 starts a note; note-off, or note-on with velocity 0, ends the
//    oldest sounding note of that track, channel and key (first in, first out). Notes still
//    sounding when their track ends end there.
//  - One Part per (track, channel) that has notes: id "track<T>-ch<C>" (both 0-based, like
//    Part::track and Part::channel), named after the track's name (or else its instrument name)
//    meta event; a track with notes on several channels gets " (ch N)" appended, N 1-based as
//    sequencers show it. Channel 9 (0-based, "channel 10") is percussion.
//  - Part::program is the program in effect on the part's channel at its first note. Programs
//    belong to the channel, not the track, so a program change in any track counts; at equal
//    ticks the part's own track wins, then the later event in the file.
//  - Controller 64 (sustain) >= 64 presses the pedal, < 64 lifts it; spans go to the part of the
//    same track and channel, or, when that track has no notes on the channel, to the first part
//    (lowest track) on that channel. A pedal still down at the end of its track is lifted there.
//  - Tempo, time and key signatures feed the tempo map and the signature lists wherever they
//    occur; text meta events (0x01-0x0F) become Score::texts.
// Meta events shorter than their fixed size, tempo 0, time signatures 0/x or with a denominator
// beyond 2^10, and key signatures beyond 7 sharps or flats are rejected as malformed.

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include <tutti/music/midi/smf_chunks.hpp>
#include <tutti/music/midi/smf_events.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music::midi_detail {

class MidiScoreBuilder final : public SmfEventHandler {
 public:
  MidiScoreBuilder(const SmfHeader& header, const std::string& source);

  // The events that follow belong to the track with this 0-based index, whose tick 0 lies at
  // `start_tick` on the score's timeline (not 0 only for format 2, whose tracks play in turn).
  void begin_track(int track_index, std::int64_t start_tick);
  std::string on_event(const SmfEvent& event) override;
  // The current track ends at `end_tick` (score timeline): held notes and pedals end there.
  void end_track(std::int64_t end_tick);

  // Forms the parts, attaches notes and pedals to them and finalizes. `end_ticks` is the tick
  // of the last event of any track.
  Score finish(std::int64_t end_ticks) &&;

 private:
  struct ProgramChange {
    int channel = 0;
    std::int64_t tick = 0;
    int track = 0;
    std::size_t order = 0;  // position in the file, to break ties
    int program = 0;
  };
  struct HeldPedal {
    int track = 0;
    int channel = 0;
    std::int64_t onset = 0;
    std::int64_t offset = 0;
  };

  void on_channel_event(const SmfEvent& event, std::int64_t tick);
  std::string on_meta_event(const SmfEvent& event, std::int64_t tick);
  void start_note(int channel, int key, int velocity, std::int64_t tick);
  void end_note(int channel, int key, int release_velocity, std::int64_t tick);
  void set_pedal(int channel, bool down, std::int64_t tick);
  int program_at(int track, int channel, std::int64_t tick) const;

  Score score_;
  // Parallel to score_.notes until finish(): the track each note came from.
  std::vector<int> note_tracks_;
  std::vector<std::string> track_names_;       // by track index; first name event wins
  std::vector<std::string> instrument_names_;  // by track index
  std::vector<ProgramChange> program_changes_;
  std::vector<HeldPedal> pedals_;
  int note_ons_ = 0;

  // State of the current track.
  int track_ = 0;
  std::int64_t start_tick_ = 0;
  std::map<int, std::deque<std::size_t>> sounding_;  // channel * 128 + key -> note indices, FIFO
  std::int64_t pedal_down_since_[16] = {};
  bool pedal_down_[16] = {};
};

}  // namespace tutti::music::midi_detail
