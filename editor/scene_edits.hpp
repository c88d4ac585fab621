// SPDX-License-Identifier: MIT
#pragma once
// The editor's edits, each built as an Edit (json_edit.hpp) from the document as it is: set a
// variation parameter, re-roll a seed, add / move / delete breath marks, cues, expressions and
// camera cuts, pin a note to a finger. Each list a mark lives in is replaced whole, so undo
// restores it exactly. The builders only describe the change; Document::apply checks that the
// result is a valid scene.
//
// Times are seconds of the music. A breath is named by the boundary it sits at: the onset of the
// note it precedes (the scene's breath marks name "the first note starting at or after t").

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <tutti/core/result.hpp>
#include <tutti/editor/json_edit.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::editor {

// Who an edit is about: where the scene file writes the player (a JSON pointer, "/<key>/2", as
// stage::Seat::player and TimelineLane::player give it), and the player's name as the stage
// shows it (for the undo menu's labels; empty: the name the file gives).
struct PlayerRef {
  std::string pointer;
  std::string name;
};

// Variation fields are scene::kVariationFields keys; nullopt = back to the seed's value.
Result<Edit> set_variation(const Json& document, const PlayerRef& player, std::string_view field,
                           std::optional<double> value);
Result<Edit> set_seed(const Json& document, const PlayerRef& player, std::uint64_t seed);
// The next seed of a re-roll: deterministic (splitmix64 of the current one).
std::uint64_t reroll_seed(std::uint64_t current);

// Breathe at the boundary before the first note at or after t_s (undoes a "remove" there).
Result<Edit> add_breath(const Json& document, const PlayerRef& player, double t_s);
// No breath at boundary_s: its add mark goes, and unless the breath was there only because of
// that mark (`marked_only`), a "remove" mark keeps the rules from breathing there.
Result<Edit> delete_breath(const Json& document, const PlayerRef& player, double boundary_s,
                           bool marked_only = false);
// delete_breath(from_boundary_s, from_marked_only) and add_breath(to_s) as one edit.
Result<Edit> move_breath(const Json& document, const PlayerRef& player, double from_boundary_s,
                         bool from_marked_only, double to_s);

// `current` = the cue times the plan has now (the automatic one when the scene lists none).
Result<Edit> add_cue(const Json& document, std::span<const double> current, double t_s);
Result<Edit> delete_cue(const Json& document, std::span<const double> current, std::size_t index);
Result<Edit> move_cue(const Json& document, std::span<const double> current, std::size_t index,
                      double t_s);

Result<Edit> add_expression(const Json& document, const PlayerRef& player,
                            const scene::Expression& expression);
// Removes the expression equal to `expression` (as the player's expressions have it).
Result<Edit> delete_expression(const Json& document, const PlayerRef& player,
                               const scene::Expression& expression);

// The same span, starting at new_start_s instead (its length kept).
Result<Edit> move_expression(const Json& document, const PlayerRef& player,
                             const scene::Expression& expression, double new_start_s);

// Camera cuts: a shot of `camera` from start_s (a scene without "shots" gets the implicit first
// one written out).
Result<Edit> add_shot(const Json& document, std::string_view camera, double start_s);
Result<Edit> move_shot(const Json& document, std::size_t index, double start_s);
Result<Edit> delete_shot(const Json& document, std::size_t index);

// The player plays the note of `key` at time_s with `finger` (the player's "pins"; replaces a
// pin on that note).
Result<Edit> pin_finger(const Json& document, const PlayerRef& player, double time_s, int key,
                        int finger);
Result<Edit> unpin_finger(const Json& document, const PlayerRef& player, double time_s, int key);

}  // namespace tutti::editor
