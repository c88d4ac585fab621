// SPDX-License-Identifier: MIT
#pragma once
// Component on a performer entity: where the performer's body touches their instrument this
// frame. Each family's pose system (Phase::pose) rewrites it after posing its models: a finger on
// its key, a fingertip on a valve button, a palm on a slide's grip, the lips on a
// mouthpiece. The contact recorder (contact_recorder.hpp) turns the frames' touches into
// contacts with time spans; the glTF export and the C API read those.
//
// Fixed capacity, so that posing stays allocation-free: a family touches with at most two hands'
// fingers and palms and the lips.

#include <array>
#include <cstddef>
#include <span>

#include <tutti/ecs/entity.hpp>

namespace tutti::stage {

struct Touch {
  ecs::Entity body = ecs::Entity::null;  // PlacedModel touching: a body or a hand model
  int body_node = -1;                    // its node at the touching point (a fingertip, the lips)
  ecs::Entity part = ecs::Entity::null;  // PlacedModel touched: the instrument
  int part_node = -1;                    // its node touched (a key, a valve button, a grip)
  int midi = -1;                         // the pitch this touch stops (a key's), else -1
};

class Touching {
 public:
  static constexpr std::size_t kMax = 16;

  void clear() { count_ = 0; }
  // Adds a touch with valid nodes; one past kMax, or with a missing node, is dropped.
  void add(const Touch& touch) {
    if (count_ >= kMax || touch.body.is_null() || touch.part.is_null() || touch.body_node < 0 ||
        touch.part_node < 0) {
      return;
    }
    touches_[count_++] = touch;
  }
  std::span<const Touch> now() const { return {touches_.data(), count_}; }

 private:
  std::array<Touch, kMax> touches_{};
  std::size_t count_ = 0;
};

}  // namespace tutti::stage
