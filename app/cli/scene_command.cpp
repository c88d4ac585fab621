// SPDX-License-Identifier: MIT
#include <tutti/cli/scene_command.hpp>

#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include <tutti/brass/brass_players.hpp>
#include <tutti/core/exit_codes.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

namespace tutti::cli {
namespace {

// ", a pianist", ", a pianist, an organist", ... (each keyboard player by name, article first).
std::string keyboard_player_names(const scene::Scene& scene) {
  std::string out;
  for (const piano::KeyboardPlayer& p : piano::keyboard_players(scene)) {
    const bool vowel = !p.name.empty() && std::string_view("aeiou").find(p.name.front()) !=
                                              std::string_view::npos;
    out += std::string(vowel ? ", an " : ", a ") + p.name;
  }
  return out;
}

}  // namespace

int run_scene(const SceneOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (o.action != "new") {
    return fail(Error{"scene " + o.action + ": unknown action (the one there is: new)"});
  }
  if (o.output.extension() != ".json") {
    return fail(Error{o.output.string() + ": the scene file must be a .json file"});
  }
  std::error_code ec;
  if (std::filesystem::exists(o.output, ec) && !o.force) {
    return fail(Error{o.output.string() + ": already exists (--force replaces it)"});
  }
  auto score = music::load_score(o.piece);
  if (!score) return fail(score.error());
  auto drafted =
      performance::draft_scene(*score, performance::music_reference_from(o.output, o.piece));
  if (!drafted) return fail(drafted.error());
  // What is written must load as `tutti render` loads it, parts included.
  const std::filesystem::path folder = std::filesystem::absolute(o.output).parent_path();
  auto scene = scene::parse_scene(nlohmann::json::parse(drafted->document.dump()),
                                  o.output.filename().string(), folder,
                                  performance::scene_load_options());
  if (!scene) return fail(Error{"internal: the drafted scene does not load: " +
                                    scene.error().message,
                                ErrorCode::internal});
  if (Status parts = scene::check_scene_parts(*scene, {&*score, 1}); !parts) {
    return fail(Error{"internal: " + parts.error().message, ErrorCode::internal});
  }
  if (Status written = write_file_atomically(
          o.output, performance::format_scene_document(drafted->document));
      !written) {
    return fail(written.error());
  }
  for (const std::string& note : drafted->notes) err << "note: " << note << "\n";
  const std::size_t brass = brass::brass_players(*scene).size();
  out << "scene: wrote " << o.output.string() << " (" << brass << " brass player"
      << (brass == 1 ? "" : "s") << keyboard_player_names(*scene) << ", "
      << scene->cameras.size() << " cameras, " << scene->shots.size() << " shots)\n";
  return kExitOk;
}

void register_scene_command(Commands& commands) {
  auto options = std::make_shared<SceneOptions>();
  Command& command = commands.add(
      "scene",
      "Make a scene from a piece: `tutti scene new PIECE -o scene.json` gives the piano parts to "
      "the pianist and each brass part its players, seated by section, with cameras and cuts");
  command.option("ACTION", options->action, "new").required();
  command.option("PIECE", options->piece, "MIDI or MusicXML file").required();
  command.option("-o,--output", options->output, "the scene file to write (.json)").required();
  command.flag("--force", options->force, "replace an existing scene file");
  command.on_run([options](std::ostream& out, std::ostream& err) {
    return run_scene(*options, out, err);
  });
}

}  // namespace tutti::cli
