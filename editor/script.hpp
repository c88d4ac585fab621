// SPDX-License-Identifier: MIT
#pragma once
// `tutti-editor SCENE --script FILE`: the editor driven by a list of actions, one per line, for
// automation and tests. The actions are the UI's (each edit goes through Session::apply):
//
//   # a comment
//   set-variation "Player 2" sway_amount 0.8      (or "seed" as the value: back to the seed)
//   reroll-seed "Player 2"
//   add-breath "Player 3" 6.0                     breathe before the first note at or after 6 s
//   delete-breath "Player 3" 10.0                 the breath at 10 s goes (an added one, a mark's
//                                                 or the rules'); none near 10 s is an error
//   add-cue 16.0
//   add-expression "Player 1" strain 4 6 [0.8]
//   cut close 12.5                                a camera cut to camera "close" at 12.5 s
//   pin 1.5 64 3                                  the first player whose notes have fingers
//                                                 plays key 64 at 1.5 s with finger 3
//   pin 1.5 64 3 "Player 4"                       ... or the player of that name
//   undo | redo
//   select "Player 3"                             show that player in the inspector
//   seek 12.0 | play | pause | frames 30          the transport; draw 30 frames
//   screenshot out.png
//   save
//   quit                                          refused while there are unsaved edits
//   quit-discarding                               quit, dropping unsaved edits
//
// Players are named as the stage names them (each family's default names included). Names with
// spaces are quoted. Errors are one line: "edit.txt:4: unknown command "frob"".

#include <filesystem>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/editor/session.hpp>

namespace tutti::editor {

struct ScriptCommand {
  int line = 0;
  std::vector<std::string> words;  // words[0] is the action
};

struct Script {
  std::string file;  // for messages
  std::vector<ScriptCommand> commands;
};

// Reads and checks every line (action known, argument count and numbers) before anything runs.
Result<Script> load_script(const std::filesystem::path& path);
Result<Script> parse_script(const std::string& text, const std::string& file_name);

// What the host does for the transport actions (the window, or a test's fake).
class ScriptHost {
 public:
  virtual ~ScriptHost() = default;
  virtual void seek(double t_s) = 0;
  virtual void set_playing(bool playing) = 0;
  virtual void select(const PlayerRef& player) = 0;
  virtual Status draw_frames(int count) = 0;
  virtual Status screenshot(const std::filesystem::path& png) = 0;
};

enum class ScriptStep { next, quit };

// Runs one command. Errors are "FILE:LINE: reason" (an edit's own message after it).
Result<ScriptStep> run_script_command(const Script& script, const ScriptCommand& command,
                                      Session& session, ScriptHost& host);

}  // namespace tutti::editor
