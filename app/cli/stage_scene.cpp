#include <tutti/cli/stage_scene.hpp>

#include <tutti/music/load_score.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::app {

Result<scene::Scene> load_scene_or_music(const std::filesystem::path& file,
                                         std::vector<std::string>* notes) {
  if (!performance::is_music_file(file)) return scene::load_scene(file);
  auto score = music::load_score(file);
  if (!score) return score.error();
  auto drafted = performance::draft_scene(*score, std::filesystem::absolute(file));
  if (!drafted) return drafted.error();
  if (notes != nullptr) *notes = drafted->notes;
  return scene::parse_scene(nlohmann::json::parse(drafted->document.dump()), file.filename().string(),
                            std::filesystem::current_path());
}

Result<std::unique_ptr<stage::Stage>> stage_scene_file(const std::filesystem::path& scene_file,
                                                       const std::filesystem::path& assets) {
  auto scene = load_scene_or_music(scene_file);
  if (!scene) return scene.error();
  stage::StageOptions options;
  options.asset_dir = assets;
  auto staged = performance::build_stage(*scene, options);
  if (!staged) return Error{scene->source + ": " + staged.error().message, staged.error().code};
  return std::move(*staged);
}

}  // namespace tutti::app
