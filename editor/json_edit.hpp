// SPDX-License-Identifier: MIT
#pragma once
// Edits of a scene document as data: each JsonChange says what is at one JSON pointer before and
// after, so an edit can be applied and reverted exactly (undo / redo), and kept in a history.
// "Absent" (nullopt) before = the value is created (an array element is inserted at that index,
// shifting the later ones); absent after = it is removed (an array element is erased).
//
// ordered_json keeps the keys in the order the user wrote them, so a saved file differs from the
// opened one only where it was edited.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::editor {

using Json = nlohmann::ordered_json;

struct JsonChange {
  std::string pointer;  // RFC 6901, e.g. "/performers/0/variation/sway_amount"
  std::optional<Json> before;
  std::optional<Json> after;
};

struct Edit {
  std::string label;  // for the undo menu: "set sway_amount of Lead"
  std::vector<JsonChange> changes;
};

// Equal as JSON values, whatever the order of object keys (ordered_json's == minds the order; an
// undone key removal puts the key back at the end).
bool same_json(const Json& a, const Json& b);

// Applies every change in order; all or nothing (on an error `document` is left as it was).
// An error names the change: a `before` that does not match the document is a stale edit.
Status apply_edit(Json& document, const Edit& edit);
// Undoes an applied edit: the inverse changes in reverse order; all or nothing.
Status revert_edit(Json& document, const Edit& edit);

}  // namespace tutti::editor
