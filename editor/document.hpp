// SPDX-License-Identifier: MIT
#pragma once
// An open scene file in the editor: its JSON (keys in the user's order), the Scene it parses to,
// the undo/redo history, and saving. Every edit goes through apply(), which keeps the document
// valid: an edit that would make the file fail to load (a time out of range, a shot before the
// previous one) is refused with the loader's one-line message and changes nothing.
//
// Saving is atomic with one backup (atomic_file.hpp). While there are unsaved edits, autosave()
// writes them to a side file (".<name>.autosave" beside the scene), never over the scene;
// open() reports one that is newer than the scene, and recover_autosave() takes its contents
// back as an undoable edit.
//
// UI-free: the editor's panels, its --script runner and the tests drive the same calls.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/editor/json_edit.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::editor {

class Document {
 public:
  // Errors are the scene loader's ("quartet.json: /shots/1/camera: ...").
  static Result<Document> open(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  const Json& json() const { return json_; }
  const scene::Scene& scene() const { return scene_; }

  // Applies `edit` if the result is a valid scene and `accept` (when given) agrees; records it
  // for undo and clears the redo list. `coalesce`: when the last edit changed the same places
  // under the same label (a slider being dragged), the two become one undo step.
  using Check = std::function<Status(const scene::Scene&)>;
  Status apply(Edit edit, bool coalesce = false, const Check& accept = {});
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  const std::string& undo_label() const;  // "" when nothing to undo
  const std::string& redo_label() const;
  Status undo(const Check& accept = {});
  Status redo(const Check& accept = {});
  // The edits applied so far (the undo list, oldest first).
  const std::vector<Edit>& history() const { return undo_; }

  // Every apply/undo/redo counts up; an unchanged revision means an unchanged document.
  std::uint64_t revision() const { return revision_; }
  bool dirty() const { return !same_json(json_, saved_json_); }

  Status save();  // to path(), atomically, the previous version kept as <file>.bak
  // Tests only (AtomicWriteOptions::pause_before_rename_ms).
  void set_save_pause_ms(int ms) { save_pause_ms_ = ms; }
  // Writes the unsaved state to autosave_path() when it changed since the last autosave (or
  // removes a stale one when there is nothing unsaved).
  Status autosave();
  // Removes the autosave file (after an explicit "discard changes").
  void discard_autosave() const;
  static std::filesystem::path autosave_path(const std::filesystem::path& scene_path);
  // open() found an autosave newer than the scene, with different contents.
  bool autosave_available() const { return autosave_available_; }
  // Loads the autosave's contents as one undoable edit (the document becomes dirty).
  Status recover_autosave(const Check& accept = {});

 private:
  Document() = default;
  Result<scene::Scene> parse(const Json& json) const;

  std::filesystem::path path_;
  Json json_;
  Json saved_json_;
  Json autosaved_json_;
  scene::Scene scene_;
  std::vector<Edit> undo_;
  std::vector<Edit> redo_;
  std::uint64_t revision_ = 0;
  bool autosave_available_ = false;
  int save_pause_ms_ = 0;
};

}  // namespace tutti::editor
