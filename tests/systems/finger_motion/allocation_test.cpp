// evaluate_hand_pose never allocates: this program replaces the global operator new with a
// counting one and evaluates many frames after planning.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "finger_motion/evaluate_hand_pose.hpp"
#include "finger_motion_fixture.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace tutti::finger_motion {
namespace {

TEST(EvaluateHandPoseAllocation, NoAllocationPerCall) {
  std::vector<test::TestNote> notes;
  for (int i = 0; i < 64; ++i) {
    notes.push_back({48 + (i * 7) % 24, 0.2 * i, 0.2 * i + 0.3, 1 + i % 5});
  }
  const FingerMotionPlan plan = test::plan_notes(notes, 700, 0);
  const motion::HandPath path = test::constant_path(700);
  HandPose pose;
  const long before = g_allocations.load();
  double sum = 0;
  for (int i = 0; i < 2000; ++i) {
    evaluate_hand_pose(plan, path, components::HandSide::right, i / 120.0, pose);
    sum += pose.fingers[2].mcp_flexion_rad;
  }
  const long after = g_allocations.load();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
  // The counter works.
  auto* probe = new int(3);
  EXPECT_EQ(g_allocations.load(), after + 1);
  delete probe;
}

}  // namespace
}  // namespace tutti::finger_motion
