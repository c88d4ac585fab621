// SPDX-License-Identifier: MIT
#pragma once
// The editor's edits, each built as an Edit (json_edit.hpp) from the document as it is: set a
// variation parameter, re-roll a seed, add / move / delete breath marks, cues, expressions and
// camera cuts, pin a piano finger. Each list a mark lives in is replaced whole, so undo restores
// it exactly. The builders only describe the change; Document::apply checks that the result is a
// valid scene.
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

// Who an edit is about: a brass performer (index into brass_players(scene)) or a pianist (pianist
// true, performer an index into keyboard_players(scene)).
struct PlayerRef {
  bool pianist = false;
  std::size_t performer = 0;
};

// Variation fields are scene::kVariationFields keys; nullopt = back to the seed's value.
Result<Edit> set_variation(const Json& document, PlayerRef player, std::string_view field,
                           std::optional<double> value);
Result<Edit> set_seed(const Json& document, PlayerRef player, std::uint64_t seed);
// The next seed of a re-roll: deterministic (splitmix64 of the current one).
std::uint64_t reroll_seed(std::uint64_t current);

// Breathe at the boundary before the first note at or after t_s (undoes a "remove" there).
Result<Edit> add_breath(const Json& document, std::size_t performer, double t_s);
// No breath at boundary_s: its add mark goes, and unless the breath was there only because of
// that mark (`marked_only`), a "remove" mark keeps the rules from breathing there.
Result<Edit> delete_breath(const Json& document, std::size_t performer, double boundary_s,
                           bool marked_only = false);
// delete_breath(from_boundary_s, from_marked_only) and add_breath(to_s) as one edit.
Result<Edit> move_breath(const Json& document, std::size_t performer, double from_boundary_s,
                         bool from_marked_only, double to_s);

// `current` = the cue times the plan has now (the automatic one when the scene lists none).
Result<Edit> add_cue(const Json& document, std::span<const double> current, double t_s);
Result<Edit> delete_cue(const Json& document, std::span<const double> current, std::size_t index);
Result<Edit> move_cue(const Json& document, std::span<const double> current, std::size_t index,
                      double t_s);

Result<Edit> add_expression(const Json& document, std::size_t performer,
                            const scene::Expression& expression);
// Removes the expression equal to `expression` (as the brass player's expressions have it).
Result<Edit> delete_expression(const Json& document, std::size_t performer,
                               const scene::Expression& expression);

// The same span, starting at new_start_s instead (its length kept).
Result<Edit> move_expression(const Json& document, std::size_t performer,
                             const scene::Expression& expression, double new_start_s);

// Camera cuts: a shot of `camera` from start_s (a scene without "shots" gets the implicit first
// one written out).
Result<Edit> add_shot(const Json& document, std::string_view camera, double start_s);
Result<Edit> move_shot(const Json& document, std::size_t index, double start_s);
Result<Edit> delete_shot(const Json& document, std::size_t index);

// Pianist `pianist` (index into keyboard_players(scene)) plays the note of `key` at time_s with
// `finger` (replaces a pin on that note).
Result<Edit> pin_finger(const Json& document, double time_s, int key, int finger,
                        std::size_t pianist = 0);
Result<Edit> unpin_finger(const Json& document, double time_s, int key, std::size_t pianist = 0);

}  // namespace tutti::editor
