// SPDX-License-Identifier: MIT
#include <tutti/scene/scene.hpp>

#include <algorithm>

#include <tutti/core/splitmix64.hpp>

namespace tutti::scene {

std::size_t Scene::shot_at(double t_s) const {
  // The first shot starting after t_s; the one before it is on screen.
  const auto after = std::upper_bound(shots.begin(), shots.end(), t_s,
                                      [](double t, const Shot& shot) { return t < shot.start_s; });
  if (after == shots.begin()) return 0;
  return static_cast<std::size_t>(after - shots.begin()) - 1;
}

int Scene::find_camera(std::string_view name) const {
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    if (cameras[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::uint64_t derive_seed(std::uint64_t scene_seed, std::uint64_t stream) {
  // The generator's output after `stream` + 1 steps from the scene seed.
  return splitmix64(scene_seed + stream * kSplitmixGamma);
}

std::string_view stance_name(Stance stance) {
  switch (stance) {
    case Stance::standing:
      return "standing";
    case Stance::seated:
      return "seated";
  }
  return "standing";
}

std::string_view expression_name(ExpressionKind kind) {
  switch (kind) {
    case ExpressionKind::strain:
      return "strain";
    case ExpressionKind::relaxed:
      return "relaxed";
  }
  return "strain";
}

}  // namespace tutti::scene
