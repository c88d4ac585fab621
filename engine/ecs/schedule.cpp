// SPDX-License-Identifier: MIT
#include <tutti/ecs/schedule.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace tutti::ecs {

std::string_view phase_name(Phase phase) noexcept {
  switch (phase) {
    case Phase::plan:
      return "plan";
    case Phase::sync:
      return "sync";
    case Phase::evaluate:
      return "evaluate";
    case Phase::express:
      return "express";
    case Phase::pose:
      return "pose";
    case Phase::render:
      return "render";
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
  if (running_) {
    throw std::logic_error("ecs: cannot add system '" + name + "' while the schedule runs");
  }
  phases_[index].push_back(Entry{std::move(name), std::move(system), std::move(access)});
}

void Schedule::run(World& world, const FrameTime& frame, Phase last) {
  struct Running {
    bool& flag;
    explicit Running(bool& f) : flag(f) {
      if (flag) throw std::logic_error("ecs: Schedule::run called from one of its own systems");
      flag = true;
    }
    ~Running() { flag = false; }
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;
  };
  const Running running(running_);
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
  const auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k) text += (k != 0 ? ", " : "") + names[k];
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
      text += line + '\n';
    }
  }
  return text;
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
