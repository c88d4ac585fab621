// SPDX-License-Identifier: MIT
#pragma once
// A scene drafted from a piece of music alone (`tutti scene new`, `tutti render PIECE.mid`): each
// family in turn (default_families(): brass, then keyboards) takes the parts it plays, by name
// or General MIDI program, and drafts its players, their cameras and camera groups
// (stage/family_draft.hpp); the families sit side by side in their seating order (the
// keyboards at the origin, the brass arc to their right); a wide camera frames everyone, and the
// shot list cuts, every few bars, to the group playing the most notes there. Parts no family
// plays are left out with a note naming them.
//
// The result is a scene document (scene/README.md), so what `tutti scene new` writes and what
// `tutti render PIECE.mid` plays are the same scene. Deterministic: the same score gives the same
// document.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/stage/family_plugin.hpp>

namespace tutti::performance {

struct DraftedScene {
  nlohmann::ordered_json document;  // keys in the order scene/README.md lists them
  // One line each, for the user: parts not played and why.
  std::vector<std::string> notes;
};

// `music_reference`: the "music" entry as written (relative to the scene file's folder, or
// absolute). Error when no part is one tutti plays, naming the parts.
Result<DraftedScene> draft_scene(const music::Score& score,
                                 const std::filesystem::path& music_reference);
// The same with these families, in this order.
Result<DraftedScene> draft_scene(const music::Score& score,
                                 const std::filesystem::path& music_reference,
                                 std::span<const stage::FamilyPlugin* const> families);

// The document as the hand-written scenes look: an object per line where it fits in 100
// characters, number lists on one line.
std::string format_scene_document(const nlohmann::ordered_json& document);

// The "music" entry for a scene written to `scene_file` that plays `music_file`: relative to the
// scene's folder when both are on one tree, else absolute.
std::filesystem::path music_reference_from(const std::filesystem::path& scene_file,
                                           const std::filesystem::path& music_file);

// A scene file, or a piece of music with the scene drafted for it (`tutti render PIECE.mid`, the C
// API's tutti_open), read with the default families' sections (scene_load_options(content_dir)):
// the drafted scene's notes (parts not played) go to `notes` when given.
Result<scene::Scene> load_scene_or_music(const std::filesystem::path& file,
                                         const std::filesystem::path& content_dir = {},
                                         std::vector<std::string>* notes = nullptr);

// True for a file name tutti reads as music (.mid, .midi, .kar, .musicxml, .xml, .mxl, .txt PIG)
// rather than as a scene (.json).
bool is_music_file(const std::filesystem::path& path);

}  // namespace tutti::performance
