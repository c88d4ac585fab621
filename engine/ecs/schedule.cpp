// SPDX-License-Identifier: MIT
#include <tutti/ecs/schedule.hpp>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <utility>

namespace tutti::ecs {

std::string_view phase_name(Phase phase) noexcept {
  switch (phase) {
    case Phase::sync:
      return "sync";
    case Phase::evaluate:
      return "evaluate";
    case Phase::express:
      return "express";
    case Phase::pose:
      return "pose";
  }
  return "unknown";
}

void Schedule::add(Phase phase, std::string name, System system, Access access) {
  const auto index = static_cast<std::size_t>(phase);
  if (index >= kPhaseCount) {
    throw std::invalid_argument("ecs: system '" + name + "': no phase numbered " +
                                std::to_string(index));
  }
  if (name.empty()) throw std::invalid_argument("ecs: a system needs a name");
  if (!system) throw std::invalid_argument("ecs: system '" + name + "' has no function");
  if (contains(name)) {
    throw std::invalid_argument("ecs: a system named '" + name + "' is already scheduled");
  }
  if (runs_.load() > 0) {
    throw std::logic_error("ecs: cannot add system '" + name + "' while the schedule runs");
  }
  phases_[index].push_back(Entry{std::move(name), std::move(system), std::move(access)});
}

namespace {

// A world's schedule run in progress (a resource of that world): a system that runs the
// schedule on its own world again is a wiring bug.
struct ScheduleRunning {
  bool running = false;
};

}  // namespace

void Schedule::run(World& world, const FrameTime& frame, Phase last) const {
  struct Running {
    std::atomic<int>& runs;
    bool& flag;
    Running(std::atomic<int>& r, bool& f) : runs(r), flag(f) {
      if (flag) throw std::logic_error("ecs: Schedule::run called from one of its own systems");
      flag = true;
      ++runs;
    }
    ~Running() {
      flag = false;
      --runs;
    }
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;
  };
  ScheduleRunning* in_world = world.resource<ScheduleRunning>();
  if (in_world == nullptr) in_world = &world.set_resource(ScheduleRunning{});
  const Running running(runs_, in_world->running);
  world.set_resource<FrameTime>(frame);
  const auto end = std::min(static_cast<std::size_t>(last) + 1, kPhaseCount);
  for (std::size_t p = 0; p < end; ++p) {
    // A copy: a system that writes the resource changes the next phase's time, not its own.
    const FrameTime now = *world.resource<FrameTime>();
    for (const Entry& entry : phases_[p]) entry.system(world, now);
    world.flush();
  }
}

std::string Schedule::describe() const {
  std::string text;
  for (std::size_t i = 0; i < kPhaseCount; ++i) {
    if (phases_[i].empty()) continue;
    text += phase_name(static_cast<Phase>(i));
    text += ": ";
    for (std::size_t k = 0; k < phases_[i].size(); ++k) {
      if (k != 0) text += ", ";
      text += phases_[i][k].name;
    }
    text += '\n';
  }
  return text;
}

std::string Schedule::describe_access() const {
  std::size_t width = 0;
  for (const auto& phase : phases_) {
    for (const Entry& entry : phase) width = std::max(width, entry.name.size());
  }
  const auto list = [](const std::vector<ComponentRef>& components) {
    std::string text;
    for (std::size_t k = 0; k < components.size(); ++k) {
      text += (k != 0 ? ", " : "") + components[k].name + (components[k].own_entities ? " (own)" : "");
    }
    return text;
  };
  const auto names = [](const std::vector<std::string>& systems) {
    std::string text;
    for (std::size_t k = 0; k < systems.size(); ++k) text += (k != 0 ? ", " : "") + systems[k];
    return text;
  };
  std::string text;
  for (std::size_t i = 0; i < kPhaseCount; ++i) {
    if (phases_[i].empty()) continue;
    text += phase_name(static_cast<Phase>(i));
    text += '\n';
    for (const Entry& entry : phases_[i]) {
      std::string line = "  " + entry.name;
      if (!entry.access.reads.empty() || !entry.access.writes.empty()) {
        line.resize(2 + width + 2, ' ');
        if (!entry.access.reads.empty()) line += "reads " + list(entry.access.reads);
        if (!entry.access.writes.empty()) {
          line += (entry.access.reads.empty() ? "" : "; ") + std::string("writes ") +
                  list(entry.access.writes);
        }
      }
      if (!entry.access.after.empty()) line += "; after " + names(entry.access.after);
      if (!entry.access.before.empty()) line += "; before " + names(entry.access.before);
      text += line + '\n';
    }
  }
  return text;
}

std::vector<std::string> Schedule::check() const {
  std::vector<std::string> problems;
  for (std::size_t p = 0; p < kPhaseCount; ++p) {
    const std::vector<Entry>& systems = phases_[p];
    const std::string phase(phase_name(static_cast<Phase>(p)));
    const auto position = [&](const std::string& name) -> std::ptrdiff_t {
      for (std::size_t k = 0; k < systems.size(); ++k) {
        if (systems[k].name == name) return static_cast<std::ptrdiff_t>(k);
      }
      return -1;
    };
    // Whether systems[a] is declared to run before systems[b].
    const auto declared_before = [&](std::size_t a, std::size_t b) {
      const auto& named = [](const std::vector<std::string>& list, const std::string& name) {
        return std::find(list.begin(), list.end(), name) != list.end();
      };
      return named(systems[a].access.before, systems[b].name) ||
             named(systems[b].access.after, systems[a].name);
    };
    for (std::size_t k = 0; k < systems.size(); ++k) {
      const Entry& entry = systems[k];
      for (const auto& [list, word] : {std::pair{&entry.access.after, "after"},
                                      std::pair{&entry.access.before, "before"}}) {
        for (const std::string& other : *list) {
          const std::ptrdiff_t at = position(other);
          if (at < 0) {
            problems.push_back(phase + ": " + entry.name + " runs " + word + " '" + other +
                               "', no system of its phase");
          } else if ((std::string_view(word) == "after") != (at < static_cast<std::ptrdiff_t>(k))) {
            problems.push_back(phase + ": " + entry.name + " runs " + word + " " + other +
                               ", but was added " + (at < static_cast<std::ptrdiff_t>(k) ? "after" : "before") +
                               " it");
          }
        }
      }
    }
    for (std::size_t a = 0; a < systems.size(); ++a) {
      for (std::size_t b = a + 1; b < systems.size(); ++b) {
        if (declared_before(a, b) || declared_before(b, a)) continue;
        for (const ComponentRef& one : systems[a].access.writes) {
          for (const ComponentRef& other : systems[b].access.writes) {
            if (one.type != other.type || (one.own_entities && other.own_entities)) continue;
            problems.push_back(phase + ": " + systems[a].name + " and " + systems[b].name +
                               " both write " + one.name + ", and neither runs after the other");
          }
        }
      }
    }
  }
  return problems;
}

std::size_t Schedule::size() const noexcept {
  std::size_t count = 0;
  for (const auto& phase : phases_) count += phase.size();
  return count;
}

bool Schedule::contains(std::string_view name) const noexcept {
  for (const auto& phase : phases_) {
    for (const Entry& entry : phase) {
      if (entry.name == name) return true;
    }
  }
  return false;
}

}  // namespace tutti::ecs
