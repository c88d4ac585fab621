// SPDX-License-Identifier: MIT
#include <tutti/generator/generate.hpp>

#include <sstream>
#include <system_error>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/generator/brass_assets.hpp>
#include <tutti/generator/hand_asset.hpp>
#include <tutti/generator/horn_asset.hpp>
#include <tutti/generator/performer_asset.hpp>
#include <tutti/generator/piano_asset.hpp>
#include <tutti/generator/props.hpp>
#include <tutti/generator/stage_asset.hpp>
#include <tutti/generator/upright_brass.hpp>
#include <tutti/piano_model/keyboard.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>

namespace tutti::content_generator {

Result<std::string> to_glb(const tinygltf::Model& model) {
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true) || !out) {
    return Error{"cannot serialise glTF model"};
  }
  return out.str();
}

Status write_glb(const tinygltf::Model& model, const std::filesystem::path& path) {
  auto bytes = to_glb(model);
  if (!bytes.ok()) return Error{path.string() + ": " + bytes.error().message};
  return write_file_atomically(path, *bytes);
}

std::vector<std::string> asset_file_names() {
  return {"piano.glb",     "music_stand.glb", "chair.glb",     "stage.glb",     "trumpet.glb",
          "trombone.glb",  "hand_right.glb",  "hand_left.glb", "performer.glb", "euphonium.glb",
          "tuba.glb",      "horn.glb"};
}

namespace {

// The keyboard family's instruments other than the piano: the piano's build with each one's
// compass and case (content/piano/instruments.json).
Status generate_keyboards(const std::filesystem::path& content_dir, const PianoDimensions& piano,
                          const std::filesystem::path& out_dir) {
  auto instruments =
      piano_model::KeyboardInstruments::load(piano_model::keyboard_instruments_path(content_dir));
  if (!instruments.ok()) return instruments.error();
  for (const piano_model::KeyboardInstrument& instrument : instruments->all()) {
    if (instrument.model == "piano.glb") continue;
    auto keyboard =
        piano_model::Keyboard::load(content_dir / "piano" / "keyboard.json", instrument.lowest_key,
                                    instrument.highest_key, instrument.octave_span_mm);
    if (!keyboard.ok()) return keyboard.error();
    PianoDimensions dims = piano;
    // An organ's console stands on its platform, the pedals at the floor.
    if (instrument.pedalboard) dims.key_top_above_floor_mm += instrument.pedalboard->seat_raise_mm;
    // A narrower octave's black keys are narrower by as much as its white keys.
    if (instrument.octave_span_mm > 0.0) {
      auto piano_keys = piano_model::Keyboard::load(content_dir / "piano" / "keyboard.json");
      if (!piano_keys.ok()) return piano_keys.error();
      dims.black_key_width_mm *= keyboard->white_key_width_mm() / piano_keys->white_key_width_mm();
    }
    dims.cheek_width_mm = instrument.case_shape.cheek_width_mm;
    dims.cabinet_height_mm = instrument.case_shape.cabinet_height_mm;
    dims.cabinet_depth_mm = instrument.case_shape.cabinet_depth_mm;
    const tinygltf::Model model =
        build_piano(*keyboard, dims, instrument.case_shape.color, instrument.id,
                    instrument.pedalboard ? &*instrument.pedalboard : nullptr);
    if (Status status = write_glb(model, out_dir / instrument.model); !status.ok()) return status;
  }
  return Status::success();
}

}  // namespace

Status generate_assets(const std::filesystem::path& content_dir,
                       const std::filesystem::path& out_dir) {
  auto keyboard = piano_model::Keyboard::load(content_dir / "piano" / "keyboard.json");
  if (!keyboard.ok()) return keyboard.error();
  auto dimensions = AssetDimensions::load(content_dir / "generator" / "dimensions.json");
  if (!dimensions.ok()) return dimensions.error();
  auto trombone = brass_model::load_instrument(content_dir / "instruments" / "trombone_tenor.json");
  if (!trombone.ok()) return trombone.error();
  if (trombone->slide_length_mm <= 0.0 ||
      trombone->slide_length_mm + 30.0 > dimensions->trombone.inner_slide_length_mm) {
    return Error{
        "dimensions.json: /trombone/inner_slide_length_mm: must exceed the slide's "
        "7th position in trombone_tenor.json (" +
        std::to_string(trombone->slide_length_mm) + " mm) by at least 30 mm"};
  }
  auto right_hand = load_hand_rig(content_dir, components::HandSide::right);
  if (!right_hand.ok()) return right_hand.error();
  auto left_hand = load_hand_rig(content_dir, components::HandSide::left);
  if (!left_hand.ok()) return left_hand.error();
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) return Error{out_dir.string() + ": cannot create folder (" + error.message() + ")"};

  const tinygltf::Model models[] = {
      build_piano(*keyboard, dimensions->piano),
      build_music_stand(dimensions->music_stand),
      build_chair(dimensions->chair),
      build_stage(dimensions->stage),
      build_trumpet(dimensions->trumpet),
      build_trombone(trombone->slide_length_mm, dimensions->trombone),
      build_hand(*right_hand),
      build_hand(*left_hand),
      build_performer(dimensions->performer, *right_hand, *left_hand),
      build_upright("euphonium", dimensions->euphonium),
      build_upright("tuba", dimensions->tuba),
      build_horn(dimensions->horn)};
  const std::vector<std::string> names = asset_file_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (Status status = write_glb(models[i], out_dir / names[i]); !status.ok()) return status;
  }
  return generate_keyboards(content_dir, dimensions->piano, out_dir);
}

}  // namespace tutti::content_generator
