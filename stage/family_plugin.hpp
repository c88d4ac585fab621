// SPDX-License-Identifier: MIT
#pragma once
// An instrument family as a plugin (Bevy's Plugin): everything about one family in one place.
// A family reads its section of the scene file (scene_section.hpp), adds its systems to the
// schedule's phases and, for a scene, plans its performers, spawns their entities and binds
// their models (StageBuilder). The stage knows families only through this interface; the list of
// families a program uses is a small file of its own (tutti::performance's default_families()).

#include <string_view>

#include <tutti/core/result.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/scene/scene_section.hpp>

namespace tutti::stage {

class StageBuilder;

class FamilyPlugin {
 public:
  virtual ~FamilyPlugin() = default;

  // Seat::family of its performers.
  virtual std::string_view name() const = 0;

  // Its section of the scene file: the top-level keys its players are written under. The
  // loader hands the document to it (scene::LoadOptions::sections).
  virtual const scene::SceneSection& scene_section() const = 0;

  // Adds the family's systems to their phases. Called once for every stage, whether or not the
  // scene has performers of the family (their systems then find nothing to do).
  virtual void add_systems(ecs::Schedule& schedule) const = 0;

  // Loads the family's content, plans the scene's performers of the family (or shares the plans
  // of builder.previous() whose inputs did not change), spawns their entities and places and
  // binds their models.
  virtual Status build(StageBuilder& builder) const = 0;
};

}  // namespace tutti::stage
