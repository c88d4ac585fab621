// SPDX-License-Identifier: MIT
#pragma once
// The computer keyboard as a piano (the layout of most music programs' "typing keyboard"):
//
//    W E   T Y U   O P          black keys  C# D#  F# G# A#  C# D#
//   A S D F G H J K L ; '       white keys  C  D  E  F  G  A  B  C  D  E  F
//   Z  X                        octave down / up (C3 .. C6 for the A key; starts at C4)
//
// Key codes are GLFW's (GLFW_KEY_A = 'A' ...), taken as plain ints so the mapping is tested
// without a window. A key released after an octave change releases the note it started.
// Auto-repeat must not be passed in (GLFW_REPEAT): a held key is one note.

#include <array>
#include <optional>
#include <vector>

#include <tutti/live/live_note_event.hpp>

namespace tutti::live {

class KeyboardPiano final : public LiveNoteSource {
 public:
  // The MIDI key a code plays at the current octave (nullopt: not a piano key).
  std::optional<int> key_of(int code) const;
  // A key went down / up at t_s. Returns true when the code belongs to the piano (a note or an
  // octave key): the caller does not bind it to anything else.
  bool press(int code, double t_s);
  bool release(int code, double t_s);
  int octave_shift() const { return octave_; }  // -1 .. +2 octaves from C4

  void poll(double now_s, std::vector<LiveNoteEvent>& out) override;
  std::string name() const override { return "computer keyboard"; }

 private:
  int octave_ = 0;
  std::array<int, 512> sounding_{};  // per code: the MIDI key it started + 1, 0 = none
  std::vector<LiveNoteEvent> queued_;
};

}  // namespace tutti::live
