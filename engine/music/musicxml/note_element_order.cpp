// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/note_element_order.hpp>

#include <algorithm>

namespace tutti::music::musicxml {

namespace {

// The whitespace-only text right before `node` (its indentation), or an empty node.
pugi::xml_node indentation_before(pugi::xml_node node) {
  const pugi::xml_node previous = node.previous_sibling();
  if (previous.type() != pugi::node_pcdata) return {};
  const std::string_view text = previous.value();
  const bool blank = std::all_of(text.begin(), text.end(), [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
  });
  return blank && !text.empty() ? previous : pugi::xml_node{};
}

pugi::xml_node last_element_child(pugi::xml_node parent) {
  for (pugi::xml_node child = parent.last_child(); child; child = child.previous_sibling()) {
    if (child.type() == pugi::node_element) return child;
  }
  return {};
}

}  // namespace

pugi::xml_node insert_element_in_order(pugi::xml_node parent, const char* name,
                                       std::span<const std::string_view> followers) {
  for (pugi::xml_node child : parent.children()) {
    if (child.type() != pugi::node_element ||
        std::find(followers.begin(), followers.end(), std::string_view(child.name())) ==
            followers.end()) {
      continue;
    }
    // ...indent <follower>  ->  ...indent <new>indent <follower>
    const pugi::xml_node indent = indentation_before(child);
    pugi::xml_node inserted = parent.insert_child_before(name, child);
    if (indent) parent.insert_child_before(pugi::node_pcdata, child).set_value(indent.value());
    return inserted;
  }
  if (const pugi::xml_node last = last_element_child(parent))
    return insert_element_after(last, name);
  return parent.append_child(name);
}

pugi::xml_node insert_element_after(pugi::xml_node sibling, const char* name) {
  // indent <sibling>...  ->  indent <sibling>indent <new>...
  pugi::xml_node parent = sibling.parent();
  pugi::xml_node anchor = sibling;
  if (const pugi::xml_node indent = indentation_before(sibling)) {
    anchor = parent.insert_child_after(pugi::node_pcdata, sibling);
    anchor.set_value(indent.value());
  }
  return parent.insert_child_after(name, anchor);
}

void remove_element_and_indent(pugi::xml_node element) {
  pugi::xml_node parent = element.parent();
  if (const pugi::xml_node indent = indentation_before(element)) parent.remove_child(indent);
  parent.remove_child(element);
}

}  // namespace tutti::music::musicxml
