// SPDX-License-Identifier: MIT
#pragma once
// The brass family's section of a scene file: "performers", an array of brass players (format:
// plugins/brass/README.md). Each names an instrument of content/instruments/, a score part and voice,
// a place and stance, at most one lead, and optionally a character, a user instrument model
// (trumpets and trombones), expression controls and performance marks. Fills
// brass_players(scene) (brass_players.hpp).

#include <tutti/brass/brass_asset_kinds.hpp>
#include <tutti/scene/scene_section.hpp>

namespace tutti::brass {

class BrassSceneSection final : public scene::SceneSection {
 public:
  std::string_view family() const override { return "brass"; }
  std::vector<std::string_view> keys() const override { return {"performers"}; }
  std::span<const scene::AssetKind> asset_kinds() const override { return kBrassAssetKinds; }
  Status read(const nlohmann::json& document, const scene::SectionContext& context,
              scene::Scene& scene) const override;
};

}  // namespace tutti::brass
