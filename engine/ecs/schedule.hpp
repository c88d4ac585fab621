// SPDX-License-Identifier: MIT
#pragma once
// The frame loop as data: systems are plain functions run in fixed, named phases, so the order in
// which the engine plans, syncs, evaluates, expresses, poses and renders is visible in one place
// (describe()) instead of being implied by call sites.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/ecs/type_index.hpp>
#include <tutti/ecs/world.hpp>

namespace tutti::ecs {

// The time a frame shows. Also a World resource: Schedule::run puts the requested time there,
// the sync phase may replace it (the offline frame clock, the live audio clock), and every later
// phase is given what the sync phase left.
struct FrameTime {
  double t_s = 0.0;   // time since the start of playback
  double dt_s = 0.0;  // time since the previous frame
};

// In run order. Planning happens offline, before the first frame (each family's plan), and
// drawing after the frame, from what pose left (the renderer, the exporter, the C API): neither
// is a phase of the frame.
enum class Phase : std::uint8_t { sync, evaluate, express, pose };
inline constexpr std::size_t kPhaseCount = 4;

// "sync", "evaluate", ...; "unknown" for a value outside the enum.
[[nodiscard]] std::string_view phase_name(Phase phase) noexcept;

using System = std::function<void(World&, const FrameTime&)>;

namespace detail {
// A type's own name, without its namespaces ("Finger" for tutti::components::Finger), read from
// the compiler's signature of this function (GCC and Clang spell it "[with T = ...]" or
// "[T = ...]").
template <typename T>
[[nodiscard]] constexpr std::string_view type_name() noexcept {
  std::string_view signature = __PRETTY_FUNCTION__;
  const auto start = signature.find("T = ");
  if (start == std::string_view::npos) return "?";
  signature.remove_prefix(start + 4);
  signature = signature.substr(0, signature.find_first_of(";]"));
  if (const auto colons = signature.rfind("::"); colons != std::string_view::npos) {
    signature.remove_prefix(colons + 2);
  }
  return signature;
}
}  // namespace detail

// A component (or resource) type a system reads or writes: its number (type_index.hpp) and name.
struct ComponentRef {
  std::size_t type = 0;
  std::string name;
  // Written only on the entities of the system's own family (its performers' models): two such
  // writers of one type do not conflict; one with a writer of all its entities does.
  bool own_entities = false;

  template <typename T>
  [[nodiscard]] static ComponentRef of(bool own = false) {
    return {type_index<T>(), std::string(detail::type_name<T>()), own};
  }
};

template <typename... Ts>
struct Reads {};
template <typename... Ts>
struct Writes {};
// Writes only on the system's own family's entities (ComponentRef::own_entities).
template <typename... Ts>
struct WritesOwn {};

// What a system reads and writes, as component types, and the systems of its phase it must run
// after or before (by name). Shown by describe_access() (`tutti info --schedule`); check() fails
// on two writers of one component in a phase that nothing orders.
struct Access {
  std::vector<ComponentRef> reads;
  std::vector<ComponentRef> writes;
  std::vector<std::string> after;
  std::vector<std::string> before;

  template <typename... Ts>
  Access& read(Reads<Ts...> = {}) {
    (reads.push_back(ComponentRef::of<Ts>()), ...);
    return *this;
  }
  template <typename... Ts>
  Access& write(Writes<Ts...> = {}) {
    (writes.push_back(ComponentRef::of<Ts>()), ...);
    return *this;
  }
  template <typename... Ts>
  Access& write(WritesOwn<Ts...>) {
    (writes.push_back(ComponentRef::of<Ts>(true)), ...);
    return *this;
  }
  Access& runs_after(std::string system) {
    after.push_back(std::move(system));
    return *this;
  }
  Access& runs_before(std::string system) {
    before.push_back(std::move(system));
    return *this;
  }
};

// access(Reads<A, B>{}, Writes<C>{}): the usual declaration in one expression.
template <typename... R, typename W>
[[nodiscard]] Access access(Reads<R...> reads, W writes) {
  Access a;
  a.read(reads);
  a.write(writes);
  return a;
}

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
  //
  // Const, and safe on different worlds from different threads at once (each caller its own
  // World::copy): the systems share only what the components point at.
  void run(World& world, const FrameTime& frame, Phase last = Phase::pose) const;

  // One line per non-empty phase, in run order, each ending in '\n':
  // "sync: audio_clock\nevaluate: hand_pose, bow\n". Empty string for an empty schedule.
  [[nodiscard]] std::string describe() const;
  // Each non-empty phase on a line, then each of its systems on its own line with what it
  // reads and writes:
  // "evaluate\n  hand_pose    reads Hand  writes Finger\n".
  [[nodiscard]] std::string describe_access() const;

  // What is wrong with the declared order, one line each (empty: nothing): two systems of a phase
  // writing one component type with neither declared after the other (two writers of only their
  // own family's entities aside), a `runs_after`/`runs_before` naming no system of its phase, or
  // one that contradicts the order systems were added in (they run in that order).
  [[nodiscard]] std::vector<std::string> check() const;

  [[nodiscard]] std::size_t size() const noexcept;
  [[nodiscard]] bool contains(std::string_view name) const noexcept;

 private:
  struct Entry {
    std::string name;
    System system;
    Access access;
  };

  std::array<std::vector<Entry>, kPhaseCount> phases_;
  mutable std::atomic<int> runs_{0};  // runs in progress on any world (add() waits for none)
};

}  // namespace tutti::ecs
