// SPDX-License-Identifier: MIT
#include <tutti/live/keyboard_piano.hpp>

#include <algorithm>

namespace tutti::live {
namespace {

// GLFW key codes (glfw3.h): letters are their upper-case ASCII, ';' 59, '\'' 39.
constexpr int kOctaveDown = 'Z';
constexpr int kOctaveUp = 'X';
constexpr int kLowestOctave = -1;
constexpr int kHighestOctave = 2;

struct Mapped {
  int code;
  int semitone;  // from the octave's C
};
constexpr std::array<Mapped, 18> kLayout{{{'A', 0},
                                          {'W', 1},
                                          {'S', 2},
                                          {'E', 3},
                                          {'D', 4},
                                          {'F', 5},
                                          {'T', 6},
                                          {'G', 7},
                                          {'Y', 8},
                                          {'H', 9},
                                          {'U', 10},
                                          {'J', 11},
                                          {'K', 12},
                                          {'O', 13},
                                          {'L', 14},
                                          {'P', 15},
                                          {59, 16},
                                          {39, 17}}};

}  // namespace

std::optional<int> KeyboardPiano::key_of(int code) const {
  for (const Mapped& m : kLayout) {
    if (m.code == code) return 60 + 12 * octave_ + m.semitone;
  }
  return std::nullopt;
}

bool KeyboardPiano::press(int code, double t_s) {
  if (code == kOctaveDown || code == kOctaveUp) {
    octave_ = std::clamp(octave_ + (code == kOctaveUp ? 1 : -1), kLowestOctave, kHighestOctave);
    return true;
  }
  const std::optional<int> key = key_of(code);
  if (!key || code < 0 || code >= static_cast<int>(sounding_.size())) return false;
  int& sounding = sounding_[static_cast<std::size_t>(code)];
  if (sounding != 0) return true;  // already down (a repeat that slipped through)
  sounding = *key + 1;
  queued_.push_back({t_s, *key, 100, true});
  return true;
}

bool KeyboardPiano::release(int code, double t_s) {
  if (code == kOctaveDown || code == kOctaveUp) return true;
  if (!key_of(code) || code < 0 || code >= static_cast<int>(sounding_.size())) return false;
  int& sounding = sounding_[static_cast<std::size_t>(code)];
  if (sounding != 0) queued_.push_back({t_s, sounding - 1, 0, false});
  sounding = 0;
  return true;
}

void KeyboardPiano::poll(double now_s, std::vector<LiveNoteEvent>& out) {
  std::size_t kept = 0;
  for (const LiveNoteEvent& e : queued_) {
    if (e.time_s <= now_s) {
      out.push_back(e);
    } else {
      queued_[kept++] = e;
    }
  }
  queued_.resize(kept);
}

}  // namespace tutti::live
