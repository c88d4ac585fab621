// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/score_parts.hpp>

#include <cstring>
#include <string_view>
#include <unordered_map>

#include <tutti/music/musicxml/xml_text_values.hpp>

namespace tutti::music::musicxml {

namespace {

// A 1-based MIDI number in [1, max] as 0-based, or -1.
int zero_based(pugi::xml_node element, int max) {
  const auto value = parse_integer(trimmed_text(element));
  if (!value || *value < 1 || *value > max) return -1;
  return static_cast<int>(*value - 1);
}

PartInfo read_score_part(pugi::xml_node score_part) {
  PartInfo info;
  info.id = score_part.attribute("id").as_string();
  info.name = std::string(trimmed_text(score_part.child("part-name")));
  bool first_instrument = true;
  for (pugi::xml_node midi : score_part.children("midi-instrument")) {
    if (first_instrument) {
      // Several instruments in one part share its staff; the first one speaks for the part.
      const int channel = zero_based(midi.child("midi-channel"), 16);
      const int program = zero_based(midi.child("midi-program"), 128);
      if (channel >= 0) info.channel = channel;
      if (program >= 0) info.program = program;
      first_instrument = false;
    }
    const int key = zero_based(midi.child("midi-unpitched"), 128);
    if (key >= 0) info.unpitched_keys.emplace_back(midi.attribute("id").as_string(), key);
  }
  return info;
}

std::vector<PartInfo> read_part_list(pugi::xml_node root) {
  std::vector<PartInfo> infos;
  for (pugi::xml_node score_part : root.child("part-list").children("score-part")) {
    infos.push_back(read_score_part(score_part));
  }
  return infos;
}

// Position of each id in `infos` (the first one when ids repeat). A map, not a search per
// part, so a file with thousands of parts costs no more than it is long.
std::unordered_map<std::string, std::size_t> index_by_id(const std::vector<PartInfo>& infos) {
  std::unordered_map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < infos.size(); ++i) index.emplace(infos[i].id, i);
  return index;
}

std::vector<PartLayout> layout_partwise(pugi::xml_node root, const std::vector<PartInfo>& infos) {
  const auto info_index = index_by_id(infos);
  std::vector<PartLayout> parts;
  for (pugi::xml_node part : root.children("part")) {
    PartLayout layout;
    const char* id = part.attribute("id").as_string();
    if (auto known = info_index.find(id); *id != '\0' && known != info_index.end()) {
      layout.info = infos[known->second];
    } else if (parts.size() < infos.size()) {
      layout.info = infos[parts.size()];
      if (*id != '\0') layout.info.id = id;
    } else {
      layout.info.id = id;
    }
    for (pugi::xml_node measure : part.children("measure")) {
      layout.measures.push_back(MeasureSlot{measure, measure, layout.measures.size()});
    }
    parts.push_back(std::move(layout));
  }
  return parts;
}

std::vector<PartLayout> layout_timewise(pugi::xml_node root, const std::vector<PartInfo>& infos) {
  std::vector<PartLayout> parts;
  for (const PartInfo& info : infos) parts.push_back(PartLayout{info, {}});
  auto known = index_by_id(infos);
  auto part_index = [&](const char* id) {
    auto [it, added] = known.emplace(id, parts.size());
    if (added) {
      PartLayout extra;
      extra.info.id = id;
      parts.push_back(std::move(extra));
    }
    return it->second;
  };
  std::size_t index = 0;
  for (pugi::xml_node measure : root.children("measure")) {
    for (pugi::xml_node part : measure.children("part")) {
      PartLayout& layout = parts[part_index(part.attribute("id").as_string())];
      if (!layout.measures.empty() && layout.measures.back().index == index) continue;  // twice
      layout.measures.push_back(MeasureSlot{measure, part, index});
    }
    ++index;
  }
  return parts;
}

}  // namespace

std::vector<PartLayout> layout_parts(pugi::xml_node root) {
  const std::vector<PartInfo> infos = read_part_list(root);
  if (std::strcmp(root.name(), "score-timewise") == 0) return layout_timewise(root, infos);
  return layout_partwise(root, infos);
}

int unpitched_key(const PartInfo& part, const char* instrument_id) {
  if (part.unpitched_keys.empty()) return -1;
  for (const auto& [id, key] : part.unpitched_keys) {
    if (id == instrument_id) return key;
  }
  return part.unpitched_keys.front().second;
}

}  // namespace tutti::music::musicxml
