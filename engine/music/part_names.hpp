// SPDX-License-Identifier: MIT
#pragma once
// Reading a part's name for the instrument it names ("2 Trumpets in D", "Corni", "Electric
// Piano"): its lower-case words, and the longest of an instrument's name phrases found in them.
// Shared by the families that recognise their parts (brass, keyboards) and `scene new`.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tutti::music {

// Lower-case words of a part name: runs of letters (bytes >= 0x80 count as letters, so "hörner"
// and "b♭" stay whole); digits, spaces and punctuation separate ("Trumpet1" is "trumpet").
std::vector<std::string> part_name_words(std::string_view text);

// Whether `phrase` ("trumpet", "english horn") occurs as consecutive words of `words`; its last
// word also matches with an English plural ending ("horns", "trumpets").
bool has_phrase(const std::vector<std::string>& words, const std::vector<std::string>& phrase);

// Words of the longest of `phrases` (each split by part_name_words) found in `words`; 0 = none.
std::size_t longest_phrase(const std::vector<std::string>& words,
                           std::span<const std::string> phrases);

}  // namespace tutti::music
