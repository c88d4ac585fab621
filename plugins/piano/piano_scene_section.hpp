// SPDX-License-Identifier: MIT
#pragma once
// The keyboard family's section of a scene file: "pianists", an array of keyboard players, or
// "pianist", one object (the format before two pianos could be written; still read). Format:
// scene/README.md. Each names the parts they play (a part has one player), a keyboard
// instrument of content/piano/instruments.json, a hand size of hands.json, a bench position,
// optionally a style of styles.json, finger pins, a character and user hands. Unnamed players
// are called for their instrument ("pianist", "pianist 2", "organist"); two benches stand at
// least 1.4 m apart. Fills keyboard_players(scene) (keyboard_players.hpp).

#include <tutti/scene/scene_section.hpp>

namespace tutti::piano {

class PianoSceneSection final : public scene::SceneSection {
 public:
  std::string_view family() const override { return "piano"; }
  std::vector<std::string_view> keys() const override { return {"pianists", "pianist"}; }
  Status read(const nlohmann::json& document, const scene::SectionContext& context,
              scene::Scene& scene) const override;
};

}  // namespace tutti::piano
