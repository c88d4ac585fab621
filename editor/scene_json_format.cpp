// SPDX-License-Identifier: MIT
#include <tutti/editor/scene_json_format.hpp>

#include <algorithm>

namespace tutti::editor {
namespace {

// A leaf value (see leafish) this short goes on one line.
constexpr std::size_t kInlineWidth = 88;

std::string inline_form(const Json& value) {
  if (value.is_object()) {
    std::string out = "{";
    bool first = true;
    for (const auto& [key, item] : value.items()) {
      out += first ? "" : ", ";
      out += Json(key).dump() + ": " + inline_form(item);
      first = false;
    }
    return out + "}";
  }
  if (value.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < value.size(); ++i) {
      out += (i == 0 ? "" : ", ") + inline_form(value[i]);
    }
    return out + "]";
  }
  return value.dump();
}

bool all_scalars(const Json& value) {
  return std::none_of(value.begin(), value.end(), [](const Json& v) { return v.is_structured(); });
}

// Arrays of scalars, and objects whose members are scalars or arrays of scalars, may go on one
// line; an array of objects puts each on its own line.
bool leafish(const Json& value) {
  if (value.is_array()) return all_scalars(value);
  if (!value.is_object()) return true;
  return std::all_of(value.begin(), value.end(), [](const Json& v) {
    return !v.is_structured() || (v.is_array() && all_scalars(v));
  });
}

void write(const Json& value, int indent, std::string& out) {
  const std::string inner(static_cast<std::size_t>(indent + 2), ' ');
  const std::string outer(static_cast<std::size_t>(indent), ' ');
  if (indent > 0 && leafish(value)) {
    const std::string flat = inline_form(value);
    if (flat.size() + static_cast<std::size_t>(indent) <= kInlineWidth) {
      out += flat;
      return;
    }
  }
  if (value.is_object() && !value.empty()) {
    out += "{\n";
    std::size_t i = 0;
    for (const auto& [key, item] : value.items()) {
      out += inner + Json(key).dump() + ": ";
      write(item, indent + 2, out);
      out += ++i < value.size() ? ",\n" : "\n";
    }
    out += outer + "}";
    return;
  }
  if (value.is_array() && !value.empty()) {
    out += "[\n";
    for (std::size_t i = 0; i < value.size(); ++i) {
      out += inner;
      write(value[i], indent + 2, out);
      out += i + 1 < value.size() ? ",\n" : "\n";
    }
    out += outer + "]";
    return;
  }
  out += value.dump();
}

}  // namespace

std::string format_scene_json(const Json& document) {
  std::string out;
  write(document, 0, out);
  out += "\n";
  return out;
}

}  // namespace tutti::editor
