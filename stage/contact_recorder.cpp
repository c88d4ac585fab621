// SPDX-License-Identifier: MIT
#include <tutti/stage/contact_recorder.hpp>

#include <algorithm>

#include <tutti/stage/touching.hpp>

namespace tutti::stage {
namespace {

// A node's world matrix: the instance's root, then the parent chain down to the node.
glm::mat4 node_world(const PlacedModel& placed, int node) {
  glm::mat4 world(1.0f);
  for (int n = node; n >= 0; n = placed.asset->nodes[static_cast<std::size_t>(n)].parent) {
    world = model::to_matrix(placed.pose.local[static_cast<std::size_t>(n)]) * world;
  }
  return placed.root * world;
}

bool valid_node(const PlacedModel& placed, int node) {
  return placed.asset != nullptr && node >= 0 &&
         static_cast<std::size_t>(node) < placed.asset->nodes.size() &&
         static_cast<std::size_t>(node) < placed.pose.local.size();
}

}  // namespace

void ContactRecorder::close(Open& entry) const {
  if (!entry.open) return;
  entry.contact.spans.back().part_point_m = entry.point_sum / static_cast<double>(entry.frames);
  entry.open = false;
}

void ContactRecorder::record(const Stage& stage, const ecs::World& world, double at_s) {
  ++frame_;
  const std::vector<ecs::Entity>& instances = stage.instances();
  const auto instance_of = [&instances](ecs::Entity entity) {
    return static_cast<std::size_t>(std::find(instances.begin(), instances.end(), entity) -
                                    instances.begin());
  };
  for (const ecs::Entity performer : stage.performers()) {
    const auto* touching = world.try_get<Touching>(performer);
    if (touching == nullptr) continue;
    for (const Touch& touch : touching->now()) {
      const auto* body = world.try_get<PlacedModel>(touch.body);
      const auto* part = world.try_get<PlacedModel>(touch.part);
      if (body == nullptr || part == nullptr || !valid_node(*body, touch.body_node) ||
          !valid_node(*part, touch.part_node)) {
        continue;
      }
      const Key key{performer.index, touch.body.index, touch.body_node, touch.part.index,
                    touch.part_node};
      auto [it, added] = contacts_.try_emplace(key);
      Open& entry = it->second;
      if (added) {
        entry.contact.performer = performer;
        entry.contact.body_instance = instance_of(touch.body);
        entry.contact.body_node = touch.body_node;
        entry.contact.part_instance = instance_of(touch.part);
        entry.contact.part_node = touch.part_node;
      }
      const glm::mat4 body_world = node_world(*body, touch.body_node);
      const glm::mat4 part_world = node_world(*part, touch.part_node);
      const glm::dvec3 point(glm::inverse(part_world) * body_world[3]);
      const bool continues = entry.open && entry.seen_frame + 1 == frame_ &&
                             entry.contact.spans.back().midi == touch.midi;
      if (continues) {
        entry.contact.spans.back().to_s = at_s;
        entry.point_sum += point;
        ++entry.frames;
      } else {
        close(entry);
        entry.contact.spans.push_back({at_s, at_s, point, touch.midi});
        entry.open = true;
        entry.point_sum = point;
        entry.frames = 1;
      }
      entry.seen_frame = frame_;
    }
  }
  for (auto& [key, entry] : contacts_) {
    if (entry.open && entry.seen_frame != frame_) close(entry);
  }
}

std::vector<Contact> ContactRecorder::contacts() const {
  std::vector<Contact> out;
  out.reserve(contacts_.size());
  for (const auto& [key, entry] : contacts_) {
    Open closed = entry;
    close(closed);
    out.push_back(std::move(closed.contact));
  }
  return out;
}

}  // namespace tutti::stage
