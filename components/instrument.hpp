// SPDX-License-Identifier: MIT
#pragma once
// The instrument a performer plays (an entity of its own, linked to the performer): which one,
// by the id of its data file (content/instruments/<id>.json), and who holds it.

#include <string>

#include <tutti/ecs/entity.hpp>

namespace tutti::components {

struct Instrument {
  std::string id;                             // "trumpet_bb", "trombone_tenor", "piano", ...
  ecs::Entity performer = ecs::Entity::null;  // who plays it
};

}  // namespace tutti::components
