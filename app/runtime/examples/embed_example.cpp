// SPDX-License-Identifier: MIT
// Embedding tutti in a game loop (docs/embedding.md): load a scene, stage it, and every frame
// pose it at the time *your* clock says and draw it into *your* frame. Headless here (an
// OffscreenTarget, so it runs as a test without a display); a game passes its WindowTarget or
// its own FrameTarget instead.
//
//   tutti_embed_example SCENE [FRAMES] [OUT.png]
//
// Exit 0 when the frames rendered and the last one is not all background; 77 when there is no
// Vulkan device (ctest counts that as skipped).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <tutti/image/png.hpp>
#include <tutti/render/offscreen_target.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/runtime/scene_player.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

using namespace tutti;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: tutti_embed_example SCENE [FRAMES] [OUT.png]\n");
    return 2;
  }
  const int frames = argc > 2 ? std::atoi(argv[2]) : 10;
  const std::string out = argc > 3 ? argv[3] : "";

  // 1. Your engine's Vulkan device and a target to draw into.
  auto context = render::VulkanContext::create({});
  if (!context) {
    std::fprintf(stderr, "error: %s\n", context.error().message.c_str());
    return context.error().message.rfind("no Vulkan device found", 0) == 0 ? 77 : 1;
  }
  auto target = render::OffscreenTarget::create(**context, 320, 180, 2, VK_SAMPLE_COUNT_4_BIT);
  if (!target) {
    std::fprintf(stderr, "error: %s\n", target.error().message.c_str());
    return 1;
  }

  // 2. The scene, staged once (music, models, every performer's plan) with a renderer for
  //    the target. sound = false: the game plays (or ignores) the music; tutti only shows it.
  auto scene = scene::load_scene(argv[1], performance::scene_load_options());
  if (!scene) {
    std::fprintf(stderr, "error: %s\n", scene.error().message.c_str());
    return 2;
  }
  runtime::ScenePlayerOptions options;
  options.sound = false;
  auto player = runtime::ScenePlayer::create(**context, **target, *scene, options);
  if (!player) {
    std::fprintf(stderr, "error: %s\n", player.error().message.c_str());
    return 1;
  }

  // 3. The game loop: your clock (here a fixed 30 Hz step from the scene's start).
  std::vector<std::uint8_t> rgba;
  std::uint64_t last_id = 0;
  for (int k = 0; k < frames; ++k) {
    const double music_s = (*player)->stage().start_s() + k / 30.0;
    (*player)->show(music_s);  // pose every performer at that time (deterministic)

    auto frame = (*target)->begin_frame();
    if (!frame) {
      std::fprintf(stderr, "error: %s\n", frame.error().message.c_str());
      return 1;
    }
    // Your own passes (shadows, a sky) may be recorded here, before the main pass ...
    if (Status s = (*player)->record(*frame, **target); !s) {
      std::fprintf(stderr, "error: %s\n", s.error().message.c_str());
      return 1;
    }
    // ... and your overlays here, after it (a WindowTarget's overlay pass, for ImGui).
    auto id = (*target)->end_frame();
    if (!id) {
      std::fprintf(stderr, "error: %s\n", id.error().message.c_str());
      return 1;
    }
    last_id = *id;
  }

  // The last frame, to check something was drawn.
  if (Status s = (*target)->read_pixels(last_id, rgba); !s) {
    std::fprintf(stderr, "error: %s\n", s.error().message.c_str());
    return 1;
  }
  std::size_t lit = 0;
  for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (rgba[i] > 40 || rgba[i + 1] > 40 || rgba[i + 2] > 40) ++lit;
  }
  if (!out.empty()) (void)image::write_png(out, rgba, (*target)->width(), (*target)->height());
  std::printf("embed: %d frames of %s, %zu of %zu pixels lit in the last\n", frames, argv[1], lit,
              rgba.size() / 4);
  return frames > 0 && lit > 0 ? 0 : 1;
}
