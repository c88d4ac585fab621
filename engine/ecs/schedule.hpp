// SPDX-License-Identifier: MIT
#pragma once
// The frame loop as data: systems are plain functions run in fixed, named phases, so the order in
// which the engine plans, syncs, evaluates, expresses, poses and renders is visible in one place
// (describe()) instead of being implied by call sites.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/ecs/world.hpp>

namespace tutti::ecs {

// The time a frame shows. Also a World resource: Schedule::run puts the requested time there,
// the sync phase may replace it (the offline frame clock, the live audio clock), and every later
// phase is given what the sync phase left.
struct FrameTime {
  double t_s = 0.0;   // time since the start of playback
  double dt_s = 0.0;  // time since the previous frame
};

// In run order.
enum class Phase : std::uint8_t { plan, sync, evaluate, express, pose, render };
inline constexpr std::size_t kPhaseCount = 6;

// "plan", "sync", ...; "unknown" for a value outside the enum.
[[nodiscard]] std::string_view phase_name(Phase phase) noexcept;

using System = std::function<void(World&, const FrameTime&)>;

// What a system reads and writes, by component (or resource) name: shown by describe(), so the
// frame's data flow can be read off a running schedule (`tutti info --schedule`).
struct Access {
  std::vector<std::string> reads;
  std::vector<std::string> writes;
};

class Schedule {
 public:
  // Appends a system to a phase; systems of a phase run in the order they were added.
  // Names identify systems across all phases, so a duplicate is a wiring bug and is rejected:
  // throws std::invalid_argument if name is empty or taken, system is empty or phase is not a
  // Phase; std::logic_error if called from a running system. Nothing is added on a throw.
  void add(Phase phase, std::string name, System system, Access access = {});

  // Runs every phase in enum order up to and including `last` (a consumer runs what it needs:
  // the sound only needs `evaluate`, a picture `pose`) and flushes world's deferred commands
  // after each phase, so a phase sees the structural changes the previous ones queued. The
  // world's FrameTime resource is set to `frame` first; the systems of each phase are given the
  // FrameTime resource as the phase starts (the sync phase may have replaced it). An exception
  // from a system or a command propagates and skips the rest of the frame; commands still queued
  // stay queued.
  void run(World& world, const FrameTime& frame, Phase last = Phase::render);

  // One line per non-empty phase, in run order, each ending in '\n':
  // "sync: audio_clock\nevaluate: hand_pose, bow\n". Empty string for an empty schedule.
  [[nodiscard]] std::string describe() const;
  // Each non-empty phase on a line, then each of its systems on its own line with what it
  // reads and writes:
  // "evaluate\n  hand_pose    reads Hand  writes Finger\n".
  [[nodiscard]] std::string describe_access() const;

  [[nodiscard]] std::size_t size() const noexcept;
  [[nodiscard]] bool contains(std::string_view name) const noexcept;

 private:
  struct Entry {
    std::string name;
    System system;
    Access access;
  };

  std::array<std::vector<Entry>, kPhaseCount> phases_;
  bool running_ = false;
};

}  // namespace tutti::ecs
