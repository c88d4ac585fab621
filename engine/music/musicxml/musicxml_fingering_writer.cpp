// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/musicxml_fingering_writer.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <pugixml.hpp>
#include <string_view>
#include <vector>

#include <tutti/core/file_io.hpp>
#include <tutti/music/musicxml/musicxml_document.hpp>
#include <tutti/music/musicxml/note_element_order.hpp>
#include <tutti/music/musicxml/source_preserving_serializer.hpp>
#include <tutti/music/musicxml/xml_source_range.hpp>

namespace tutti::music {

namespace {

using musicxml::ByteRange;

// The document is parsed so that every node keeps its source text: whitespace-only text is
// kept, and entities, line ends and attribute whitespace are left as written (no parse_escapes,
// parse_eol or parse_wconv_attribute). Edited notes are written back with their original tags
// (source_preserving_serializer.hpp); only the whole-document fallback goes through pugixml's
// serializer, with format_raw | format_no_escapes so raw values stay raw.
constexpr unsigned int kParseFlags =
    (pugi::parse_full | pugi::parse_ws_pcdata) &
    ~(pugi::parse_escapes | pugi::parse_eol | pugi::parse_wconv_attribute);
constexpr unsigned int kFormatFlags = pugi::format_raw | pugi::format_no_escapes;

struct FingerMark {
  int finger = 0;
  int substitute = 0;
};

struct StringWriter : pugi::xml_writer {
  std::string text;
  void write(const void* data, std::size_t size) override {
    text.append(static_cast<const char*>(data), size);
  }
};

bool is_fingering(pugi::xml_node node) {
  return node.type() == pugi::node_element && std::strcmp(node.name(), "fingering") == 0;
}

std::vector<pugi::xml_node> fingerings_of(pugi::xml_node note) {
  std::vector<pugi::xml_node> found;
  for (pugi::xml_node notations : note.children("notations")) {
    for (pugi::xml_node technical : notations.children("technical")) {
      for (pugi::xml_node child : technical.children()) {
        if (is_fingering(child)) found.push_back(child);
      }
    }
  }
  return found;
}

void set_text(pugi::xml_node element, int number) {
  while (element.first_child()) element.remove_child(element.first_child());
  element.append_child(pugi::node_pcdata).set_value(std::to_string(number).c_str());
}

// Puts the finger on the note: the existing main <fingering> is rewritten in place (keeping its
// placement attributes), otherwise a new one goes into the first <technical> of the first
// <notations>, creating those where the schema puts them. A previous substitution mark is
// replaced by the new one, if any.
void mark_note(pugi::xml_node note, const FingerMark& mark) {
  pugi::xml_node main;
  for (pugi::xml_node fingering : fingerings_of(note)) {
    const bool substitution = fingering.attribute("substitution").as_bool();
    const bool alternate = fingering.attribute("alternate").as_bool();
    if (substitution) {
      musicxml::remove_element_and_indent(fingering);
    } else if (!alternate && !main) {
      main = fingering;
    }
  }
  if (!main) {
    pugi::xml_node notations = note.child("notations");
    if (!notations) {
      notations = musicxml::insert_element_in_order(note, "notations",
                                                    musicxml::kNoteChildrenAfterNotations);
    }
    pugi::xml_node technical = notations.child("technical");
    if (!technical) technical = musicxml::insert_element_in_order(notations, "technical");
    main = musicxml::insert_element_in_order(technical, "fingering");
  }
  set_text(main, mark.finger);
  if (mark.substitute != 0) {
    pugi::xml_node substitute = musicxml::insert_element_after(main, "fingering");
    substitute.append_attribute("substitution").set_value("yes");
    set_text(substitute, mark.substitute);
  }
}

Result<std::map<int, FingerMark>> marks_by_note(const Score& fingered, std::size_t note_count,
                                                const std::string& source) {
  std::map<int, FingerMark> marks;
  for (const Note& note : fingered.notes) {
    if (note.finger == 0 || note.source_index < 0) continue;
    if (static_cast<std::size_t>(note.source_index) >= note_count) {
      return Error{source + ": a note refers to <note> #" + std::to_string(note.source_index) +
                   " but the document has " + std::to_string(note_count) +
                   " (the score was not read from this file?)"};
    }
    if (note.finger < 1 || note.finger > 5 || note.finger_substitute < 0 ||
        note.finger_substitute > 5) {
      return Error{source + ": <note> #" + std::to_string(note.source_index) + " has finger " +
                   std::to_string(note.finger) + "/" + std::to_string(note.finger_substitute) +
                   " (fingers are 1-5)"};
    }
    marks[note.source_index] = FingerMark{note.finger, note.finger_substitute};
  }
  return marks;
}

// Replaces each edited <note> in the original text by its serialization; every byte outside
// those notes is the original's.
std::optional<std::string> splice_notes(const std::string& text,
                                        const std::vector<pugi::xml_node>& edited,
                                        const std::vector<ByteRange>& ranges) {
  std::string out;
  out.reserve(text.size() + edited.size() * 80);
  std::size_t copied = 0;
  for (std::size_t i = 0; i < edited.size(); ++i) {
    if (ranges[i].begin < copied) return std::nullopt;  // overlapping ranges: not notes after all
    out.append(text, copied, ranges[i].begin - copied);
    out += musicxml::serialize_keeping_source(text, edited[i]);
    copied = ranges[i].end;
  }
  out.append(text, copied, std::string::npos);
  return out;
}

bool starts_with_bom(const std::string& text) {
  return text.size() >= 2 && ((static_cast<unsigned char>(text[0]) == 0xEF &&
                               static_cast<unsigned char>(text[1]) == 0xBB) ||
                              (static_cast<unsigned char>(text[0]) == 0xFF &&
                               static_cast<unsigned char>(text[1]) == 0xFE) ||
                              (static_cast<unsigned char>(text[0]) == 0xFE &&
                               static_cast<unsigned char>(text[1]) == 0xFF));
}

// For the whole-document fallback: attribute values are kept raw and pugixml prints them between
// double quotes; one written between single quotes may contain '"', which must then be escaped.
void escape_double_quotes(pugi::xml_node element) {
  for (pugi::xml_attribute attribute : element.attributes()) {
    std::string_view value = attribute.value();
    if (value.find('"') == std::string_view::npos) continue;
    std::string escaped;
    for (const char c : value) escaped += c == '"' ? std::string("&quot;") : std::string(1, c);
    attribute.set_value(escaped.c_str());
  }
}

void escape_double_quotes_in_tree(pugi::xml_node root) {
  struct Walker : pugi::xml_tree_walker {
    bool for_each(pugi::xml_node& node) override {
      if (node.type() == pugi::node_element) escape_double_quotes(node);
      return true;
    }
  } walker;
  escape_double_quotes(root);
  root.traverse(walker);
}

}  // namespace

Result<std::string> add_fingering_marks(std::span<const std::uint8_t> original,
                                        const std::string& source_name, const Score& fingered) {
  auto text = musicxml::musicxml_text(original, source_name);
  if (!text) return text.error();
  pugi::xml_document doc;
  pugi::xml_encoding encoding = pugi::encoding_auto;
  if (Status parsed = musicxml::parse_musicxml(*text, kParseFlags, doc, source_name, &encoding);
      !parsed) {
    return parsed.error();
  }
  const std::vector<pugi::xml_node> notes = musicxml::note_elements(doc);
  auto marks = marks_by_note(fingered, notes.size(), source_name);
  if (!marks) return marks.error();
  if (marks->empty()) return std::move(*text);

  struct Edit {
    pugi::xml_node note;
    FingerMark mark;
    std::optional<ByteRange> range;
  };
  // Byte ranges first, while every node still carries its source text. Offsets are byte
  // offsets of `text` only when pugixml did not convert the encoding.
  std::vector<Edit> edits;
  for (const auto& [index, mark] : *marks) {
    const pugi::xml_node note = notes[static_cast<std::size_t>(index)];
    edits.push_back(Edit{note, mark,
                         encoding == pugi::encoding_utf8
                             ? musicxml::element_source_range(*text, note)
                             : std::nullopt});
  }
  for (Edit& edit : edits) mark_note(edit.note, edit.mark);

  std::optional<std::string> annotated;
  if (std::all_of(edits.begin(), edits.end(), [](const Edit& e) { return e.range.has_value(); })) {
    std::vector<pugi::xml_node> edited;
    std::vector<ByteRange> ranges;
    for (const Edit& edit : edits) {
      edited.push_back(edit.note);
      ranges.push_back(*edit.range);
    }
    annotated = splice_notes(*text, edited, ranges);
  }
  if (!annotated) {
    // UTF-16 or Latin-1 input (or a note that could not be located): the whole document is
    // serialized in its own encoding. Whitespace outside the root element is lost then.
    escape_double_quotes_in_tree(doc);
    StringWriter writer;
    doc.save(writer, "", kFormatFlags | (starts_with_bom(*text) ? pugi::format_write_bom : 0u),
             encoding);
    annotated = std::move(writer.text);
  }

  // Safety net: the result must still be the same score, note for note.
  pugi::xml_document check;
  if (!check.load_buffer(annotated->data(), annotated->size()) ||
      musicxml::note_elements(check).size() != notes.size()) {
    return Error{source_name + ": internal error: adding fingering broke the document"};
  }
  return std::move(*annotated);
}

Status write_musicxml_with_fingering(const std::filesystem::path& original,
                                     const std::filesystem::path& output, const Score& fingered) {
  auto bytes = read_file_bytes(original);
  if (!bytes) return bytes.error();
  auto annotated = add_fingering_marks(*bytes, original.string(), fingered);
  if (!annotated) return annotated.error();
  return write_file_atomically(output, *annotated);
}

}  // namespace tutti::music
