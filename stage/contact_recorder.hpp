// SPDX-License-Identifier: MIT
#pragma once
// Contacts as data: where each performer's body touches their instrument, and when. Fed the
// posed stage frame after frame, the recorder joins each touch (touching.hpp) that lasts over
// consecutive frames into a span, and gives each span the touching point in the touched node's
// frame: the mean, over the span's frames, of where the body node was in that frame. A host can
// pin a hand to a key with it, or check that its import keeps the contact.
//
// Contacts come out in a fixed order (performer, body model, body node, instrument model,
// instrument node, by spawn order), their spans in time: the same frames give the same bytes.

#include <cstddef>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include <tutti/ecs/entity.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage {

struct ContactSpan {
  double from_s = 0.0;  // the first and last frame's time that saw the touch
  double to_s = 0.0;
  glm::dvec3 part_point_m{0.0};  // the touching point in the part node's frame (metres)
  int midi = -1;                 // the pitch the contact stops, else -1
};

struct Contact {
  ecs::Entity performer = ecs::Entity::null;
  std::size_t body_instance = 0;  // index into Stage::instances()
  int body_node = -1;             // a node of that instance's model
  std::size_t part_instance = 0;
  int part_node = -1;
  std::vector<ContactSpan> spans;
};

class ContactRecorder {
 public:
  // Reads every performer's Touching after `stage` was posed (Phase::pose) for the frame at
  // `at_s`. Frames must come in time order; a touch missing from a frame ends its span.
  void record(const Stage& stage, double at_s) { record(stage, stage.world(), at_s); }
  // The same for a frame posed in a context's world (Stage::run(context, ...)).
  void record(const Stage& stage, const ecs::World& world, double at_s);
  // The contacts recorded so far, open spans closed at the last frame.
  std::vector<Contact> contacts() const;

 private:
  // performer, body model, body node, part model, part node (entity indices: spawn order).
  using Key = std::tuple<std::uint32_t, std::uint32_t, int, std::uint32_t, int>;
  struct Open {
    Contact contact;
    bool open = false;       // a span is being recorded
    std::size_t frames = 0;  // in the open span
    glm::dvec3 point_sum{0.0};
    std::size_t seen_frame = 0;  // the last frame that saw the touch
  };
  void close(Open& entry) const;

  std::map<Key, Open> contacts_;
  std::size_t frame_ = 0;
};

}  // namespace tutti::stage
