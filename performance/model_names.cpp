// SPDX-License-Identifier: MIT
#include <tutti/performance/model_names.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <tutti/components/performer.hpp>

namespace tutti::performance {
namespace {

std::string stem_of(const std::string& file) { return std::filesystem::path(file).stem().string(); }

}  // namespace

std::vector<std::string> clip_names(const stage::Stage& stage) {
  std::vector<std::string> names;
  const ecs::World& world = stage.world();
  for (ecs::Entity performer : stage.performers()) {
    const auto* about = world.try_get<components::Performer>(performer);
    const auto* seat = world.try_get<stage::Seat>(performer);
    std::string name = about != nullptr ? about->name : std::string();
    if (std::find(names.begin(), names.end(), name) != names.end() && seat != nullptr) {
      name += " (" + seat->family + ")";
    }
    names.push_back(std::move(name));
  }
  return names;
}

std::vector<InstanceLabel> label_instances(const stage::Stage& stage) {
  const std::vector<std::string> clips = clip_names(stage);
  const auto clip_of = [&](ecs::Entity performer) {
    for (std::size_t i = 0; i < stage.performers().size(); ++i) {
      if (stage.performers()[i] == performer) return clips[i];
    }
    return std::string();
  };
  const std::size_t count = stage.instances().size();
  std::vector<InstanceLabel> labels(count);
  std::vector<bool> named(count, false);
  for (std::size_t i = 0; i < count; ++i) {
    const stage::PlacedModel& placed = stage.placed(i);
    if (placed.performer.is_null()) continue;
    const std::string clip = clip_of(placed.performer);
    std::string name = placed.label;
    if (placed.after_performer) name = placed.label.empty() ? clip : clip + " " + placed.label;
    labels[i] = {std::move(name), clip};
    named[i] = true;
  }
  std::set<std::string> taken;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (named[i]) taken.insert(labels[i].name);
  }
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (named[i]) continue;
    const std::string stem = stem_of(stage.model_files()[stage.placed(i).model]);
    std::string name;
    do {
      name = stem + " " + std::to_string(++counts[stem]);
    } while (taken.count(name) != 0);
    taken.insert(name);
    labels[i].name = name;
  }
  return labels;
}

std::string whole_scene_clip_name(const stage::Stage& stage) {
  const std::vector<std::string> clips = clip_names(stage);
  const bool taken = std::find(clips.begin(), clips.end(), "scene") != clips.end();
  return taken ? "scene (all)" : "scene";
}

}  // namespace tutti::performance
