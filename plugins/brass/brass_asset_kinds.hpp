// SPDX-License-Identifier: MIT
#pragma once
// The kinds of asset mapping file the brass family takes for a user's instrument model
// ("instrument_model" of a brass player; roles in plugins/brass/README.md), registered with the
// scene loader by its section (BrassSceneSection::asset_kinds).

#include <array>
#include <span>
#include <string_view>

#include <tutti/scene/asset_mapping.hpp>

namespace tutti::brass {

// Three valves (trumpets, cornets, flugelhorns).
inline constexpr std::array<std::string_view, 6> kTrumpetRoles{
    "valve_1", "valve_2", "valve_3", "mouthpiece", "grip_left", "grip_right"};
inline constexpr std::array<std::string_view, 4> kTrumpetRequiredRoles{"valve_1", "valve_2",
                                                                       "valve_3", "mouthpiece"};
// A slide (trombones).
inline constexpr std::array<std::string_view, 5> kTromboneRoles{
    "slide", "bell_section", "mouthpiece", "grip_left", "grip_right"};
inline constexpr std::array<std::string_view, 2> kTromboneRequiredRoles{"slide", "mouthpiece"};

inline constexpr std::array<scene::AssetKind, 2> kBrassAssetKinds{
    scene::AssetKind{"trumpet", kTrumpetRoles, kTrumpetRequiredRoles, {}, false},
    scene::AssetKind{"trombone", kTromboneRoles, kTromboneRequiredRoles, {}, false}};

inline const scene::AssetKind& trumpet_kind() { return kBrassAssetKinds[0]; }
inline const scene::AssetKind& trombone_kind() { return kBrassAssetKinds[1]; }

}  // namespace tutti::brass
