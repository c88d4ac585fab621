#include <tutti/ecs/schedule.hpp>

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

void Schedule::add(Phase phase, std::string name, System system) {
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
  phases_[index].push_back(Entry{std::move(name), std::move(system)});
}

void Schedule::run(World& world, const FrameTime& frame) {
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
  for (const auto& phase : phases_) {
    for (const Entry& entry : phase) entry.system(world, frame);
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
