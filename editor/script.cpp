// SPDX-License-Identifier: MIT
#include <tutti/editor/script.hpp>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include <tutti/components/performer.hpp>
#include <tutti/core/did_you_mean.hpp>

namespace tutti::editor {
namespace {

struct Action {
  int min_args = 0;
  int max_args = 0;
  const char* usage = "";
};

const std::map<std::string, Action>& actions() {
  static const std::map<std::string, Action> table{
      {"set-variation", {3, 3, "set-variation PERFORMER FIELD VALUE|seed"}},
      {"reroll-seed", {1, 1, "reroll-seed PERFORMER"}},
      {"add-breath", {2, 2, "add-breath PERFORMER TIME"}},
      {"delete-breath", {2, 2, "delete-breath PERFORMER TIME"}},
      {"add-cue", {1, 1, "add-cue TIME"}},
      {"add-expression", {4, 5, "add-expression PERFORMER strain|relaxed START END [AMOUNT]"}},
      {"cut", {2, 2, "cut CAMERA TIME"}},
      {"pin", {3, 4, "pin TIME KEY FINGER [PERFORMER]"}},
      {"select", {1, 1, "select PERFORMER"}},
      {"undo", {0, 0, "undo"}},
      {"redo", {0, 0, "redo"}},
      {"seek", {1, 1, "seek TIME"}},
      {"play", {0, 0, "play"}},
      {"pause", {0, 0, "pause"}},
      {"frames", {1, 1, "frames N"}},
      {"screenshot", {1, 1, "screenshot FILE.png"}},
      {"save", {0, 0, "save"}},
      {"quit", {0, 0, "quit"}},
      {"quit-discarding", {0, 0, "quit-discarding"}},
  };
  return table;
}

Result<std::vector<std::string>> split(const std::string& line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
      ++i;
      continue;
    }
    if (line[i] == '#') break;
    std::string word;
    if (line[i] == '"') {
      const std::size_t end = line.find('"', i + 1);
      if (end == std::string::npos) return Error{"unclosed quote"};
      word = line.substr(i + 1, end - i - 1);
      i = end + 1;
    } else {
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
        word += line[i++];
      }
    }
    words.push_back(word);
  }
  return words;
}

bool parse_number(const std::string& word, double& out) {
  if (word.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(word.c_str(), &end);
  return errno == 0 && end == word.c_str() + word.size() && std::isfinite(out);
}

Error at(const Script& script, const ScriptCommand& command, const std::string& why) {
  return Error{script.file + ":" + std::to_string(command.line) + ": " + why};
}

double number(const ScriptCommand& command, std::size_t i) {
  double value = 0.0;
  parse_number(command.words[i], value);  // checked by parse_script
  return value;
}

// The player of that name (as the stage names them: every family's, in the stage's order).
Result<PlayerRef> performer(const Script& script, const ScriptCommand& command,
                            const Session& session, const std::string& name) {
  const ecs::World& world = session.stage().world();
  std::string names;
  for (const ecs::Entity entity : session.stage().performers()) {
    const auto* about = world.try_get<components::Performer>(entity);
    const auto* seat = world.try_get<stage::Seat>(entity);
    if (about == nullptr || seat == nullptr) continue;
    if (about->name == name) return PlayerRef{seat->player, about->name};
    names += (names.empty() ? "" : ", ") + about->name;
  }
  return at(script, command, "no performer \"" + name + "\" (performers: " + names + ")");
}

// The timeline's lane of a player.
const TimelineLane* lane_of(const Session& session, const PlayerRef& player) {
  for (const TimelineLane& lane : session.timeline().lanes) {
    if (lane.player == player.pointer) return &lane;
  }
  return nullptr;
}

// The current seed of a player (as planned: the file's, or the one derived from the scene's).
std::uint64_t seed_of(const Session& session, const PlayerRef& player) {
  const ecs::World& world = session.stage().world();
  for (const ecs::Entity entity : session.stage().performers()) {
    const auto* seat = world.try_get<stage::Seat>(entity);
    const auto* about = world.try_get<components::Performer>(entity);
    if (seat != nullptr && about != nullptr && seat->player == player.pointer) return about->seed;
  }
  return 0;
}

// Which words must be numbers, per action (indices into words).
std::vector<std::size_t> numeric_words(const std::string& action, std::size_t count) {
  if (action == "add-breath" || action == "delete-breath") return {2};
  if (action == "add-cue" || action == "seek" || action == "frames") return {1};
  if (action == "add-expression")
    return count > 5 ? std::vector<std::size_t>{3, 4, 5} : std::vector<std::size_t>{3, 4};
  if (action == "cut") return {2};
  if (action == "pin") return {1, 2, 3};
  return {};
}

}  // namespace

Result<Script> parse_script(const std::string& text, const std::string& file_name) {
  Script script;
  script.file = file_name;
  std::istringstream in(text);
  std::string line;
  for (int number_of_line = 1; std::getline(in, line); ++number_of_line) {
    auto words = split(line);
    ScriptCommand command;
    command.line = number_of_line;
    if (!words) return at(script, command, words.error().message);
    if (words->empty()) continue;
    command.words = std::move(*words);
    const auto action = actions().find(command.words[0]);
    if (action == actions().end()) {
      std::vector<std::string_view> names;
      for (const auto& [name, unused] : actions()) names.push_back(name);
      return at(script, command,
                "unknown command \"" + command.words[0] + "\"" +
                    did_you_mean(command.words[0], names));
    }
    const int args = static_cast<int>(command.words.size()) - 1;
    if (args < action->second.min_args || args > action->second.max_args) {
      return at(script, command, std::string("usage: ") + action->second.usage);
    }
    for (std::size_t i : numeric_words(command.words[0], command.words.size())) {
      double value = 0.0;
      if (!parse_number(command.words[i], value)) {
        return at(
            script, command,
            "\"" + command.words[i] + "\" is not a number (usage: " + action->second.usage + ")");
      }
    }
    if (command.words[0] == "set-variation" && command.words[3] != "seed") {
      double value = 0.0;
      if (!parse_number(command.words[3], value)) {
        return at(script, command, "\"" + command.words[3] + "\" is not a number or \"seed\"");
      }
    }
    script.commands.push_back(std::move(command));
  }
  return script;
}

Result<Script> load_script(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path.string() + ": no such file"};
  std::stringstream text;
  text << in.rdbuf();
  return parse_script(text.str(), path.filename().string());
}

Result<ScriptStep> run_script_command(const Script& script, const ScriptCommand& command,
                                      Session& session, ScriptHost& host) {
  const std::string& action = command.words[0];
  const Json& json = session.document().json();
  auto edit_result = [&](Status s) -> Result<ScriptStep> {
    if (!s) return at(script, command, s.error().message);
    return ScriptStep::next;
  };
  auto who = [&](std::size_t i) -> Result<PlayerRef> {
    return performer(script, command, session, command.words[i]);
  };
  if (action == "set-variation") {
    auto player = who(1);
    if (!player) return player.error();
    std::optional<double> value;
    if (command.words[3] != "seed") value = number(command, 3);
    return edit_result(session.apply(set_variation(json, *player, command.words[2], value)));
  }
  if (action == "reroll-seed") {
    auto player = who(1);
    if (!player) return player.error();
    return edit_result(
        session.apply(set_seed(json, *player, reroll_seed(seed_of(session, *player)))));
  }
  if (action == "add-breath" || action == "delete-breath" || action == "add-expression") {
    auto player = who(1);
    if (!player) return player.error();
    const TimelineLane* lane = lane_of(session, *player);
    if (action != "add-expression" && (lane == nullptr || !lane->breathes)) {
      return at(script, command,
                command.words[1] + " takes no breath marks (their family plans no breaths)");
    }
    if (action == "add-expression" && (lane == nullptr || !lane->expressive)) {
      return at(script, command,
                command.words[1] + " takes no expressions (their family has none)");
    }
    if (action == "add-breath") {
      return edit_result(session.apply(
          add_breath(json, *player, session.breath_boundary(*player, number(command, 2)))));
    }
    if (action == "delete-breath") {
      // The breath at that time — added, from a mark or from the rules — not the next boundary.
      auto breath = session.breath_near(*player, number(command, 2));
      if (!breath) return at(script, command, breath.error().message);
      return edit_result(
          session.apply(delete_breath(json, *player, breath->boundary_s, breath->marked)));
    }
    scene::Expression e;
    if (command.words[2] == "strain") {
      e.kind = scene::ExpressionKind::strain;
    } else if (command.words[2] == "relaxed") {
      e.kind = scene::ExpressionKind::relaxed;
    } else {
      return at(script, command, "an expression is \"strain\" or \"relaxed\"");
    }
    e.start_s = number(command, 3);
    e.end_s = number(command, 4);
    if (command.words.size() > 5) e.amount = number(command, 5);
    return edit_result(session.apply(add_expression(json, *player, e)));
  }
  if (action == "add-cue") {
    return edit_result(session.apply(add_cue(json, session.timeline().cues_s, number(command, 1))));
  }
  if (action == "cut") {
    return edit_result(session.apply(add_shot(json, command.words[1], number(command, 2))));
  }
  if (action == "pin") {
    // The player named, or the first whose notes have fingers.
    std::optional<PlayerRef> player;
    if (command.words.size() > 4) {
      auto named = who(4);
      if (!named) return named.error();
      const TimelineLane* lane = lane_of(session, *named);
      if (lane == nullptr || !lane->fingered) {
        return at(script, command, command.words[4] + " plays no notes by fingers");
      }
      player = *named;
    } else {
      for (const TimelineLane& lane : session.timeline().lanes) {
        if (lane.fingered) {
          player = PlayerRef{lane.player, {}};
          break;
        }
      }
      if (!player) return at(script, command, "no player in the scene plays notes by fingers");
    }
    return edit_result(session.apply(pin_finger(json, *player, number(command, 1),
                                                static_cast<int>(number(command, 2)),
                                                static_cast<int>(number(command, 3)))));
  }
  if (action == "select") {
    auto player = who(1);
    if (!player) return player.error();
    host.select(*player);
    return ScriptStep::next;
  }
  if (action == "undo") return edit_result(session.undo());
  if (action == "redo") return edit_result(session.redo());
  if (action == "seek") {
    host.seek(number(command, 1));
    return ScriptStep::next;
  }
  if (action == "play" || action == "pause") {
    host.set_playing(action == "play");
    return ScriptStep::next;
  }
  if (action == "frames") {
    const double count = number(command, 1);
    if (count < 0 || count > 100000) return at(script, command, "frames: 0..100000");
    return edit_result(host.draw_frames(static_cast<int>(count)));
  }
  if (action == "screenshot") return edit_result(host.screenshot(command.words[1]));
  if (action == "save") return edit_result(session.document().save());
  if (action == "quit") {
    if (session.document().dirty()) {
      return at(script, command, "unsaved changes (save first, or quit-discarding)");
    }
    session.document().discard_autosave();
    return ScriptStep::quit;
  }
  if (action == "quit-discarding") {
    session.document().discard_autosave();
    return ScriptStep::quit;
  }
  return at(script, command, "unknown command \"" + action + "\"");
}

}  // namespace tutti::editor
