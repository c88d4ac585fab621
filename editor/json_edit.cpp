// SPDX-License-Identifier: MIT
#include <tutti/editor/json_edit.hpp>

#include <charconv>
#include <nlohmann/json.hpp>

namespace tutti::editor {
namespace {

Error stale(const JsonChange& change, const std::string& why) {
  return Error{"edit at " + change.pointer + ": " + why};
}

// The parent container and the last reference token of `pointer`.
struct Target {
  Json* parent = nullptr;
  std::string key;
};

Result<Target> locate(Json& document, const JsonChange& change) {
  if (change.pointer.empty() || change.pointer.front() != '/') {
    return stale(change, "not a JSON pointer to a member");
  }
  Json::json_pointer pointer;
  try {
    pointer = Json::json_pointer(change.pointer);
  } catch (const nlohmann::json::exception& e) {
    return stale(change, e.what());
  }
  Target target;
  target.key = pointer.back();
  const Json::json_pointer parent = pointer.parent_pointer();
  if (!document.contains(parent)) return stale(change, "its parent does not exist");
  target.parent = &document[parent];
  if (!target.parent->is_object() && !target.parent->is_array()) {
    return stale(change, "its parent is neither an object nor an array");
  }
  return target;
}

Result<std::size_t> index_of(const JsonChange& change, const std::string& key, std::size_t limit) {
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
  if (ec != std::errc() || end != key.data() + key.size() || index > limit) {
    return stale(change, "array index out of range");
  }
  return index;
}

Status apply_one(Json& document, const JsonChange& change, const std::optional<Json>& from,
                 const std::optional<Json>& to) {
  auto target = locate(document, change);
  if (!target) return target.error();
  Json& parent = *target->parent;
  if (parent.is_object()) {
    const auto it = parent.find(target->key);
    const bool exists = it != parent.end();
    if (exists != from.has_value() || (exists && !same_json(*it, *from))) {
      return stale(change, "the document no longer has what the edit expects there");
    }
    if (to) {
      parent[target->key] = *to;
    } else {
      parent.erase(target->key);
    }
    return Status::success();
  }
  const std::size_t size = parent.size();
  auto index = index_of(change, target->key, from ? size - (size > 0 ? 1 : 0) : size);
  if (!index) return index.error();
  if (from && (size == 0 || !same_json(parent[*index], *from))) {
    return stale(change, "the document no longer has what the edit expects there");
  }
  if (from && to) {
    parent[*index] = *to;
  } else if (to) {
    parent.insert(parent.begin() + static_cast<std::ptrdiff_t>(*index), *to);
  } else if (from) {
    parent.erase(parent.begin() + static_cast<std::ptrdiff_t>(*index));
  }
  return Status::success();
}

}  // namespace

bool same_json(const Json& a, const Json& b) {
  return nlohmann::json::parse(a.dump()) == nlohmann::json::parse(b.dump());
}

Status apply_edit(Json& document, const Edit& edit) {
  Json working = document;
  for (const JsonChange& change : edit.changes) {
    if (Status s = apply_one(working, change, change.before, change.after); !s) return s;
  }
  document = std::move(working);
  return Status::success();
}

Status revert_edit(Json& document, const Edit& edit) {
  Json working = document;
  for (auto it = edit.changes.rbegin(); it != edit.changes.rend(); ++it) {
    if (Status s = apply_one(working, *it, it->after, it->before); !s) return s;
  }
  document = std::move(working);
  return Status::success();
}

}  // namespace tutti::editor
