// SPDX-License-Identifier: MIT
#pragma once
// The performance marks of a scene file (breath marks, expressions, finger pins, cues): the
// editor's timeline edits, read as strictly as the rest of the scene; the families' sections read
// their players' marks with these.

#include <nlohmann/json_fwd.hpp>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/scene/json_fields.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::scene {

// "breaths": {"add": [t, ...], "remove": [t, ...]} and "expressions": [{...}] of a performer.
Status parse_performer_marks(const FieldReader& reader, const nlohmann::json& performer,
                             const std::string& path, Performer& out);
// "pins": [{"time_s": t, "key": k, "finger": f}, ...] of the pianist.
Status parse_finger_pins(const FieldReader& reader, const nlohmann::json& pianist,
                         const std::string& path, std::vector<FingerPin>& out);
// "cues": [t, ...] at the top level (absent: automatic).
Status parse_cues(const FieldReader& reader, const nlohmann::json& document,
                  std::optional<std::vector<double>>& out);

}  // namespace tutti::scene
