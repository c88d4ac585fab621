// SPDX-License-Identifier: MIT
#pragma once
// The names a staged scene's performers and models go by outside tutti (a host engine's nodes,
// the clips and nodes of `tutti export`): each performer's name ("pianist (piano)" when an
// earlier performer has the same name), each model's ("Trumpet 1", "Trumpet 1 trumpet", "piano",
// "pianist hand_r", scenery "chair 1", "music_stand 2").

#include <string>
#include <vector>

#include <tutti/stage/stage.hpp>

namespace tutti::performance {

// One per Stage::performers(), in that order: the performer's name, followed by " (<family>)" when
// an earlier performer has the same name.
std::vector<std::string> clip_names(const stage::Stage& stage);

// One placed model's name and the clip (performer) it belongs to ("" for scenery).
struct InstanceLabel {
  std::string name;  // unique among the stage's models
  std::string performer;
};
// One per Stage::instances(), in that order.
std::vector<InstanceLabel> label_instances(const stage::Stage& stage);

// The name of a whole-scene clip: "scene", or "scene (all)" when a performer is called "scene".
std::string whole_scene_clip_name(const stage::Stage& stage);

}  // namespace tutti::performance
