// SPDX-License-Identifier: MIT
#include <tutti/editor/document.hpp>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include <tutti/editor/atomic_file.hpp>
#include <tutti/editor/scene_json_format.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

namespace tutti::editor {
namespace {

namespace fs = std::filesystem;

const std::string kNothing;

Result<Json> read_json(const fs::path& path) {
  // read_scene_json gives the loader's one-line errors; parse again ordered to keep key order.
  auto checked = scene::read_scene_json(path);
  if (!checked) return checked.error();
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  try {
    return Json::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    return Error{path.filename().string() + ": not valid JSON"};
  }
}

}  // namespace

fs::path Document::autosave_path(const fs::path& scene_path) {
  return scene_path.parent_path() / ("." + scene_path.filename().string() + ".autosave");
}

Result<scene::Scene> Document::parse(const Json& json) const {
  return scene::parse_scene(nlohmann::json::parse(json.dump()), path_.filename().string(),
                            path_.parent_path(), performance::scene_load_options());
}

Result<Document> Document::open(const fs::path& path) {
  Document document;
  document.path_ = fs::absolute(path);
  auto json = read_json(document.path_);
  if (!json) return json.error();
  auto scene = document.parse(*json);
  if (!scene) return scene.error();
  document.json_ = std::move(*json);
  document.saved_json_ = document.json_;
  document.autosaved_json_ = document.json_;
  document.scene_ = std::move(*scene);
  const fs::path side = autosave_path(document.path_);
  std::error_code ec;
  if (fs::exists(side, ec)) {
    auto autosaved = read_json(side);
    const bool newer = fs::last_write_time(side, ec) >= fs::last_write_time(document.path_, ec);
    document.autosave_available_ = autosaved && newer && !same_json(*autosaved, document.json_);
  }
  return document;
}

Status Document::apply(Edit edit, bool coalesce, const Check& accept) {
  Json next = json_;
  if (Status s = apply_edit(next, edit); !s) return s;
  auto scene = parse(next);
  if (!scene) return scene.error();
  if (accept) {
    if (Status s = accept(*scene); !s) return s;
  }
  bool merged = false;
  if (coalesce && !undo_.empty() && undo_.back().label == edit.label &&
      undo_.back().changes.size() == edit.changes.size()) {
    Edit& last = undo_.back();
    merged = true;
    for (std::size_t i = 0; i < edit.changes.size(); ++i) {
      merged = merged && last.changes[i].pointer == edit.changes[i].pointer;
    }
    if (merged) {
      for (std::size_t i = 0; i < edit.changes.size(); ++i) {
        last.changes[i].after = edit.changes[i].after;
      }
    }
  }
  json_ = std::move(next);
  scene_ = std::move(*scene);
  if (!merged) undo_.push_back(std::move(edit));
  redo_.clear();
  ++revision_;
  return Status::success();
}

const std::string& Document::undo_label() const {
  return undo_.empty() ? kNothing : undo_.back().label;
}
const std::string& Document::redo_label() const {
  return redo_.empty() ? kNothing : redo_.back().label;
}

Status Document::undo(const Check& accept) {
  if (undo_.empty()) return Error{"nothing to undo"};
  Json previous = json_;
  if (Status s = revert_edit(previous, undo_.back()); !s) return s;
  auto scene = parse(previous);
  if (!scene) return scene.error();
  if (accept) {
    if (Status s = accept(*scene); !s) return s;
  }
  json_ = std::move(previous);
  scene_ = std::move(*scene);
  redo_.push_back(std::move(undo_.back()));
  undo_.pop_back();
  ++revision_;
  return Status::success();
}

Status Document::redo(const Check& accept) {
  if (redo_.empty()) return Error{"nothing to redo"};
  Json next = json_;
  if (Status s = apply_edit(next, redo_.back()); !s) return s;
  auto scene = parse(next);
  if (!scene) return scene.error();
  if (accept) {
    if (Status s = accept(*scene); !s) return s;
  }
  json_ = std::move(next);
  scene_ = std::move(*scene);
  undo_.push_back(std::move(redo_.back()));
  redo_.pop_back();
  ++revision_;
  return Status::success();
}

Status Document::save() {
  AtomicWriteOptions options;
  options.pause_before_rename_ms = save_pause_ms_;
  if (Status s = write_file_atomically(path_, format_scene_json(json_), options); !s) return s;
  saved_json_ = json_;
  autosaved_json_ = json_;
  discard_autosave();
  autosave_available_ = false;
  return Status::success();
}

Status Document::autosave() {
  if (!dirty()) {
    discard_autosave();
    autosaved_json_ = json_;
    return Status::success();
  }
  if (same_json(json_, autosaved_json_)) return Status::success();
  const fs::path side = autosave_path(path_);
  if (Status s = write_file_atomically(side, format_scene_json(json_), {.keep_backup = false});
      !s) {
    return s;
  }
  autosaved_json_ = json_;
  return Status::success();
}

void Document::discard_autosave() const {
  std::error_code ec;
  fs::remove(autosave_path(path_), ec);
}

Status Document::recover_autosave(const Check& accept) {
  auto autosaved = read_json(autosave_path(path_));
  if (!autosaved) return autosaved.error();
  Edit edit;
  edit.label = "recover unsaved changes";
  // One change of the whole document: "/" is not a member pointer, so replace key by key.
  for (const auto& [key, value] : json_.items()) {
    if (!autosaved->contains(key)) edit.changes.push_back({"/" + key, value, std::nullopt});
  }
  for (const auto& [key, value] : autosaved->items()) {
    if (!json_.contains(key)) {
      edit.changes.push_back({"/" + key, std::nullopt, value});
    } else if (!same_json(json_[key], value)) {
      edit.changes.push_back({"/" + key, json_[key], value});
    }
  }
  if (Status s = apply(std::move(edit), false, accept); !s) return s;
  autosave_available_ = false;
  return Status::success();
}

}  // namespace tutti::editor
