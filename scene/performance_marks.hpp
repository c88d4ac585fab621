// SPDX-License-Identifier: MIT
#pragma once
// The performance marks of a scene file (breath marks, expressions, cues): the editor's timeline
// edits, read as strictly as the rest of the scene; the families' sections read their players'
// marks with these (and their own marks within the same time range).

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/scene/json_fields.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::scene {

// The range every time of a mark is in, seconds (as output.start_s).
inline constexpr double kEarliestMark_s = -60.0;
inline constexpr double kLatestMark_s = 86400.0;

// "breaths": {"add": [t, ...], "remove": [t, ...]} and "expressions": [{...}] of a player (each
// absent: left unchanged). Expressions end up in start order.
Status parse_performer_marks(const FieldReader& reader, const nlohmann::json& performer,
                             const std::string& path, BreathMarks& breath_marks,
                             std::vector<Expression>& expressions);
// "cues": [t, ...] at the top level (absent: automatic).
Status parse_cues(const FieldReader& reader, const nlohmann::json& document,
                  std::optional<std::vector<double>>& out);

}  // namespace tutti::scene
