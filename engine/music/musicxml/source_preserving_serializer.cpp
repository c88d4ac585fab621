// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/source_preserving_serializer.hpp>

#include <tutti/music/musicxml/xml_source_range.hpp>
#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {

// "<x a='1'/>" -> "<x a='1'>", for an originally empty element that has children now.
std::string_view open_form(std::string_view self_closing_tag) {
  std::string_view tag = self_closing_tag.substr(0, self_closing_tag.size() - 2);  // drop "/>"
  while (!tag.empty() && is_xml_space(tag.back())) tag.remove_suffix(1);
  return tag;
}

void write_new_start_tag(std::string& out, pugi::xml_node element) {
  out += '<';
  out += element.name();
  for (pugi::xml_attribute attribute : element.attributes()) {
    out += ' ';
    out += attribute.name();
    out += "=\"";
    out += attribute.value();  // only this module's own values ("yes"): nothing to escape
    out += '"';
  }
}

void write_node(std::string& out, std::string_view text, pugi::xml_node node) {
  switch (node.type()) {
    case pugi::node_element: {
      const auto original = source_start_tag(text, node);
      const bool self_closing =
          original && original->size() >= 2 && original->substr(original->size() - 2) == "/>";
      if (!node.first_child()) {
        if (original && self_closing) {
          out += *original;
        } else if (original) {
          out += *original;
          out += "</";
          out += node.name();
          out += '>';
        } else {
          write_new_start_tag(out, node);
          out += "/>";
        }
        return;
      }
      if (original) {
        if (self_closing) {
          out += open_form(*original);
          out += '>';
        } else {
          out += *original;
        }
      } else {
        write_new_start_tag(out, node);
        out += '>';
      }
      for (pugi::xml_node child : node.children()) write_node(out, text, child);
      out += "</";
      out += node.name();
      out += '>';
      return;
    }
    case pugi::node_pcdata:
      out += node.value();
      return;
    case pugi::node_cdata:
      out += "<![CDATA[";
      out += node.value();
      out += "]]>";
      return;
    case pugi::node_comment:
      out += "<!--";
      out += node.value();
      out += "-->";
      return;
    case pugi::node_pi:
      out += "<?";
      out += node.name();
      if (*node.value() != '\0') {
        out += ' ';
        out += node.value();
      }
      out += "?>";
      return;
    default:
      return;  // declarations and doctypes do not occur inside elements
  }
}

}  // namespace

std::string serialize_keeping_source(std::string_view text, pugi::xml_node node) {
  std::string out;
  write_node(out, text, node);
  return out;
}

}  // namespace tutti::music::musicxml
