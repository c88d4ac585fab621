// SPDX-License-Identifier: MIT
// ScenePlayer on the piano scene, headless (an OffscreenTarget), silent (the transport on the
// host clock): camera modes through the key bindings, the transport through them, and a drawn
// frame. Skipped without a Vulkan device.
#include <tutti/runtime/scene_player.hpp>
#include <tutti/runtime/stage_view.hpp>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include <tutti/render/offscreen_target.hpp>
#include "render/render_test_support.hpp"
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>

namespace tutti::runtime {
namespace {

constexpr float kAspect = 16.0f / 9.0f;

void expect_same_view(const render::Camera& a, const render::Camera& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a.view[c][r], b.view[c][r], 1e-4f);
  }
}

class ScenePlayerTest : public render::test::VulkanTest {
 protected:
  void SetUp() override {
    render::test::VulkanTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    auto target = render::OffscreenTarget::create(*context_, 160, 90, 2, VK_SAMPLE_COUNT_1_BIT);
    ASSERT_TRUE(target) << target.error().message;
    target_ = std::move(*target);
    auto scene = scene::load_scene(std::string(TUTTI_SOURCE_DIR) + "/content/scenes/piano.json", performance::scene_load_options());
    ASSERT_TRUE(scene) << scene.error().message;
    ScenePlayerOptions options;
    options.sound = false;
    options.stage.asset_dir = TUTTI_ASSET_DIR;
    auto player = ScenePlayer::create(*context_, *target_, *scene, options);
    ASSERT_TRUE(player) << player.error().message;
    player_ = std::move(*player);
  }
  void TearDown() override {
    if (context_) {
      EXPECT_TRUE(context_->wait_idle());
    }
    player_.reset();
    target_.reset();
    render::test::VulkanTest::TearDown();
  }

  std::unique_ptr<render::OffscreenTarget> target_;
  std::unique_ptr<ScenePlayer> player_;
};

TEST_F(ScenePlayerTest, CameraModesFollowTheKeys) {
  ScenePlayer& p = *player_;
  ASSERT_GE(p.stage().scene().cameras.size(), 2u);
  EXPECT_EQ(p.camera_mode(), CameraMode::director);
  expect_same_view(p.camera(kAspect), runtime::camera_at(p.stage(), p.shown_time(), kAspect));

  EXPECT_TRUE(p.apply(key_action(GLFW_KEY_2, 0), 0.0, 90.0f));
  EXPECT_EQ(p.camera_mode(), CameraMode::scene_camera);
  EXPECT_EQ(p.camera_index(), 1u);
  expect_same_view(p.camera(kAspect), runtime::scene_camera(p.stage(), 1, kAspect));
  EXPECT_NE(p.status_line().find("camera 2"), std::string::npos) << p.status_line();

  // A camera the scene does not have: nothing changes.
  if (p.stage().scene().cameras.size() < 9) {
    p.apply(key_action(GLFW_KEY_9, 0), 0.0, 90.0f);
    EXPECT_EQ(p.camera_index(), 1u);
  }

  // A drag: the free camera, starting where camera 2 is, then orbiting.
  p.apply(drag_action(GLFW_MOUSE_BUTTON_LEFT, 0, 0.0f, 0.0f), 0.0, 90.0f);
  EXPECT_EQ(p.camera_mode(), CameraMode::free);
  expect_same_view(p.camera(kAspect), runtime::scene_camera(p.stage(), 1, kAspect));
  p.apply(drag_action(GLFW_MOUSE_BUTTON_LEFT, 0, 50.0f, 0.0f), 0.0, 90.0f);
  EXPECT_NE(p.camera(kAspect).position, runtime::scene_camera(p.stage(), 1, kAspect).position);

  p.apply(key_action(GLFW_KEY_0, 0), 0.0, 90.0f);
  EXPECT_EQ(p.camera_mode(), CameraMode::director);
  EXPECT_FALSE(p.apply(key_action(GLFW_KEY_ESCAPE, 0), 0.0, 90.0f));
}

TEST_F(ScenePlayerTest, TransportFollowsTheKeys) {
  ScenePlayer& p = *player_;
  const double start = p.stage().start_s();
  EXPECT_EQ(p.update(0.0), start);
  p.apply(key_action(GLFW_KEY_SPACE, 0), 0.0, 90.0f);
  EXPECT_TRUE(p.transport().playing());
  EXPECT_NEAR(p.update(1.0), start + 1.0, 0.01);
  EXPECT_DOUBLE_EQ(p.shown_time(), p.transport().time());
  p.apply(key_action(GLFW_KEY_RIGHT, 0), 1.0, 90.0f);
  EXPECT_NEAR(p.update(1.0), start + 6.0, 0.01);
  p.apply(key_action(GLFW_KEY_HOME, 0), 1.0, 90.0f);
  EXPECT_DOUBLE_EQ(p.update(1.0), start);
  p.apply(key_action(GLFW_KEY_EQUAL, 0), 1.0, 90.0f);
  EXPECT_DOUBLE_EQ(p.transport().tempo(), 1.1);
  p.apply(key_action(GLFW_KEY_MINUS, 0), 1.0, 90.0f);
  p.apply(key_action(GLFW_KEY_MINUS, 0), 1.0, 90.0f);
  EXPECT_DOUBLE_EQ(p.transport().tempo(), 0.9);
  EXPECT_NE(p.status_line().find("tempo 0.90"), std::string::npos) << p.status_line();
  p.apply(key_action(GLFW_KEY_SPACE, 0), 1.0, 90.0f);
  EXPECT_FALSE(p.transport().playing());
  EXPECT_NE(p.status_line().find("paused"), std::string::npos) << p.status_line();
}

TEST_F(ScenePlayerTest, RecordsAFrame) {
  ScenePlayer& p = *player_;
  p.show(p.stage().start_s() + 2.0);
  auto frame = target_->begin_frame();
  ASSERT_TRUE(frame) << frame.error().message;
  ASSERT_TRUE(p.record(*frame, *target_));
  auto id = target_->end_frame();
  ASSERT_TRUE(id) << id.error().message;
  std::vector<std::uint8_t> rgba;
  ASSERT_TRUE(target_->read_pixels(*id, rgba));
  std::size_t lit = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) lit += rgba[i] > 40 || rgba[i + 1] > 40;
  EXPECT_GT(lit, rgba.size() / 4 / 10);
  EXPECT_GT(p.renderer().last_stats().main_draws, 0u);
}

bool same_pose(const model::ModelPose& a, const model::ModelPose& b) {
  if (a.local.size() != b.local.size() || a.morph_weights != b.morph_weights) return false;
  for (std::size_t i = 0; i < a.local.size(); ++i) {
    if (a.local[i].translation != b.local[i].translation ||
        a.local[i].rotation != b.local[i].rotation || a.local[i].scale != b.local[i].scale) {
      return false;
    }
  }
  return true;
}

// The player poses a sampling context of its own and draws that (as render, export and the host
// API do): the stage's own world is left as it was built, and what is shown at t is what any
// other context of the stage gives at t.
TEST_F(ScenePlayerTest, ItPosesAContextOfItsOwnAndLeavesTheStagesWorldAlone) {
  ScenePlayer& p = *player_;
  const stage::Stage& stage = p.stage();
  std::vector<model::ModelPose> built;
  for (std::size_t i = 0; i < stage.instances().size(); ++i) built.push_back(stage.placed(i).pose);
  const double t = stage.start_s() + 5.0;
  p.show(stage.start_s() + 2.0);
  p.show(t);
  stage::StageContext fresh = stage.make_context();
  stage.run(fresh, {t, 0.0});
  std::size_t moved = 0;
  for (std::size_t i = 0; i < stage.instances().size(); ++i) {
    EXPECT_TRUE(same_pose(stage.placed(i).pose, built[i])) << "instance " << i;
    EXPECT_TRUE(same_pose(p.posed().placed(i).pose, fresh.placed(i).pose)) << "instance " << i;
    moved += same_pose(p.posed().placed(i).pose, built[i]) ? 0 : 1;
  }
  EXPECT_GT(moved, 0u) << "the pianist and the keys move between the start and 5 s";
}

}  // namespace
}  // namespace tutti::runtime
