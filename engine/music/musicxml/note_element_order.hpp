// SPDX-License-Identifier: MIT
#pragma once
// Inserting elements into an existing MusicXML element where the schema wants them, with the
// surrounding indentation copied so a pretty-printed file stays pretty.
//
// MusicXML 4.0 <note> content model, in order: grace/cue, chord, pitch|unpitched|rest,
// duration, tie, instrument, footnote, level, voice, type, dot, accidental, time-modification,
// stem, notehead, notehead-text, staff, beam, notations, lyric, play, listen. So <notations>
// goes before the first <lyric>/<play>/<listen>, else last. Inside <notations> and
// <technical> the order is free.

#include <array>
#include <pugixml.hpp>
#include <span>
#include <string_view>

namespace tutti::music::musicxml {

inline constexpr std::array<std::string_view, 3> kNoteChildrenAfterNotations = {"lyric", "play",
                                                                                "listen"};

// A new child element `name` of `parent`, before the first child element named in `followers`
// or else after the last child element.
pugi::xml_node insert_element_in_order(pugi::xml_node parent, const char* name,
                                       std::span<const std::string_view> followers = {});

// A new element `name` right after `sibling`.
pugi::xml_node insert_element_after(pugi::xml_node sibling, const char* name);

// Removes `element` together with the indentation before it.
void remove_element_and_indent(pugi::xml_node element);

}  // namespace tutti::music::musicxml
