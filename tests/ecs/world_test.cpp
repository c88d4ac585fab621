// SPDX-License-Identifier: MIT
#include <tutti/ecs/world.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace tutti::ecs {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

struct Position {
  float x = 0.0F;
  float y = 0.0F;
};
struct Velocity {
  float dx = 0.0F;
};
struct Name {
  std::string text;
};
struct Soloist {};  // tag

TEST(WorldTest, CreateGivesDistinctLiveHandles) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  EXPECT_NE(a, b);
  EXPECT_TRUE(world.valid(a));
  EXPECT_TRUE(world.valid(b));
  EXPECT_FALSE(world.valid(Entity::null));
  EXPECT_FALSE(world.valid(Entity{b.index + 1, 0}));
  EXPECT_EQ(world.alive(), 2U);
}

TEST(WorldTest, DestroyThenCreateReusesTheIndexWithANewGeneration) {
  World world;
  const Entity old = world.create();
  world.add<Position>(old, 1.0F, 2.0F);
  ASSERT_TRUE(world.destroy(old));
  EXPECT_FALSE(world.valid(old));
  EXPECT_EQ(world.alive(), 0U);

  const Entity reused = world.create();
  EXPECT_EQ(reused.index, old.index);
  EXPECT_EQ(reused.generation, old.generation + 1);
  EXPECT_TRUE(world.valid(reused));
  EXPECT_FALSE(world.valid(old));

  world.add<Position>(reused, 5.0F, 6.0F);
  EXPECT_FALSE(world.has<Position>(old));
  EXPECT_EQ(world.try_get<Position>(old), nullptr);
  EXPECT_FALSE(world.remove<Position>(old));
  EXPECT_FALSE(world.destroy(old));
  EXPECT_TRUE(world.valid(reused));
  ASSERT_TRUE(world.has<Position>(reused));
  EXPECT_EQ(world.get<Position>(reused).x, 5.0F);
}

TEST(WorldTest, DestroyRemovesTheEntityFromEveryPool) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  world.add<Position>(a, 1.0F, 1.0F);
  world.add<Velocity>(a, 2.0F);
  world.add<Name>(a, "a");
  world.add<Soloist>(a);
  world.add<Position>(b, 3.0F, 3.0F);
  world.add<Name>(b, "b");

  ASSERT_TRUE(world.destroy(a));
  EXPECT_EQ(world.size<Position>(), 1U);
  EXPECT_EQ(world.size<Velocity>(), 0U);
  EXPECT_EQ(world.size<Name>(), 1U);
  EXPECT_EQ(world.size<Soloist>(), 0U);
  EXPECT_FALSE(world.has<Position>(a));
  EXPECT_FALSE(world.has<Soloist>(a));
  EXPECT_EQ(world.get<Name>(b).text, "b");
  EXPECT_EQ(world.get<Position>(b).x, 3.0F);
  EXPECT_EQ(world.alive(), 1U);
}

TEST(WorldTest, SwapAndPopKeepsOtherEntitiesComponents) {
  World world;
  std::vector<Entity> es;
  for (int i = 0; i < 6; ++i) {
    es.push_back(world.create());
    world.add<Position>(es.back(), static_cast<float>(i), static_cast<float>(-i));
    world.add<Name>(es.back(), "n" + std::to_string(i));
  }
  EXPECT_TRUE(world.remove<Position>(es[1]));
  EXPECT_TRUE(world.destroy(es[3]));
  EXPECT_TRUE(world.remove<Name>(es[0]));
  EXPECT_FALSE(world.remove<Name>(es[0]));

  EXPECT_EQ(world.size<Position>(), 4U);
  EXPECT_EQ(world.size<Name>(), 4U);
  for (const int i : {0, 2, 4, 5}) {
    ASSERT_TRUE(world.has<Position>(es[i])) << i;
    EXPECT_EQ(world.get<Position>(es[i]).x, static_cast<float>(i));
    EXPECT_EQ(world.get<Position>(es[i]).y, static_cast<float>(-i));
  }
  for (const int i : {1, 2, 4, 5}) {
    ASSERT_TRUE(world.has<Name>(es[i])) << i;
    EXPECT_EQ(world.get<Name>(es[i]).text, "n" + std::to_string(i));
  }
}

TEST(WorldTest, AddReturnsTheComponentAndReplacesAnExistingOne) {
  World world;
  const Entity e = world.create();
  Position& p = world.add<Position>(e, 1.0F, 2.0F);
  EXPECT_EQ(&p, &world.get<Position>(e));
  p.x = 10.0F;
  EXPECT_EQ(world.get<Position>(e).x, 10.0F);
  Position& again = world.emplace<Position>(e, 7.0F, 8.0F);
  EXPECT_EQ(&again, &p);
  EXPECT_EQ(world.get<Position>(e).x, 7.0F);
  EXPECT_EQ(world.get<Position>(e).y, 8.0F);
  EXPECT_EQ(world.size<Position>(), 1U);
}

TEST(WorldTest, AddToADeadEntityThrows) {
  World world;
  const Entity e = world.create();
  world.destroy(e);
  EXPECT_THAT([&] { world.add<Position>(e); },
              ThrowsMessage<std::invalid_argument>(HasSubstr("the entity is not alive")));
  EXPECT_THROW(world.add<Position>(Entity::null), std::invalid_argument);
  EXPECT_EQ(world.size<Position>(), 0U);
}

TEST(WorldTest, TryGetAndConstAccess) {
  World world;
  const Entity e = world.create();
  const Entity bare = world.create();
  world.add<Velocity>(e, 4.0F);
  const World& view = world;
  EXPECT_EQ(view.get<Velocity>(e).dx, 4.0F);
  ASSERT_NE(view.try_get<Velocity>(e), nullptr);
  EXPECT_EQ(view.try_get<Velocity>(e)->dx, 4.0F);
  EXPECT_EQ(view.try_get<Velocity>(bare), nullptr);
  EXPECT_EQ(view.try_get<Name>(e), nullptr);  // pool never created
  EXPECT_FALSE(view.has<Name>(e));
  EXPECT_EQ(view.size<Name>(), 0U);
}

TEST(WorldTest, TagComponents) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  world.add<Soloist>(a);
  world.add<Soloist>(a);  // replacing a tag is a no-op
  EXPECT_TRUE(world.has<Soloist>(a));
  EXPECT_FALSE(world.has<Soloist>(b));
  EXPECT_EQ(world.size<Soloist>(), 1U);
  EXPECT_NE(world.try_get<Soloist>(a), nullptr);
  EXPECT_EQ(world.try_get<Soloist>(b), nullptr);
  EXPECT_TRUE(world.remove<Soloist>(a));
  EXPECT_FALSE(world.has<Soloist>(a));
}

TEST(WorldTest, MoveOnlyComponents) {
  World world;
  std::vector<Entity> es;
  for (int i = 0; i < 4; ++i) {
    es.push_back(world.create());
    world.add<std::unique_ptr<int>>(es.back(), std::make_unique<int>(i));
  }
  world.remove<std::unique_ptr<int>>(es[0]);
  for (int i = 1; i < 4; ++i) EXPECT_EQ(*world.get<std::unique_ptr<int>>(es[i]), i);
}

struct Fixed {
  const int id;
};

TEST(WorldTest, ComponentsThatCannotBeAssigned) {
  World world;
  std::vector<Entity> es;
  for (int i = 0; i < 4; ++i) {
    es.push_back(world.create());
    world.add<Fixed>(es.back(), i);
  }
  world.remove<Fixed>(es[1]);
  world.add<Fixed>(es[2], 20);  // replaces by remove + add
  EXPECT_EQ(world.get<Fixed>(es[0]).id, 0);
  EXPECT_EQ(world.get<Fixed>(es[2]).id, 20);
  EXPECT_EQ(world.get<Fixed>(es[3]).id, 3);
  EXPECT_EQ(world.size<Fixed>(), 3U);
}

TEST(WorldTest, ClearDestroysEverythingAndKeepsOldHandlesInvalid) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  world.add<Position>(a);
  world.add<Soloist>(b);
  world.clear();
  EXPECT_EQ(world.alive(), 0U);
  EXPECT_FALSE(world.valid(a));
  EXPECT_FALSE(world.valid(b));
  EXPECT_EQ(world.size<Position>(), 0U);
  EXPECT_EQ(world.size<Soloist>(), 0U);
  const Entity c = world.create();
  EXPECT_TRUE(world.valid(c));
  EXPECT_NE(c, a);
  EXPECT_NE(c, b);
  EXPECT_FALSE(world.has<Position>(c));
}

TEST(WorldTest, ManyEntitiesAcrossSparsePages) {
  World world;
  std::vector<Entity> es;
  for (int i = 0; i < 20'000; ++i) es.push_back(world.create());
  for (std::size_t i = 0; i < es.size(); i += 997)
    world.add<Velocity>(es[i], static_cast<float>(i));
  EXPECT_EQ(world.size<Velocity>(), 21U);
  for (std::size_t i = 0; i < es.size(); ++i) {
    ASSERT_EQ(world.has<Velocity>(es[i]), i % 997 == 0) << i;
  }
  EXPECT_EQ(world.get<Velocity>(es[19'940]).dx, 19'940.0F);
}

TEST(WorldTest, WorldsHaveSeparatePools) {
  World one;
  World two;
  const Entity a = one.create();
  const Entity b = two.create();
  ASSERT_EQ(a, b);  // same first handle
  one.add<Velocity>(a, 1.0F);
  EXPECT_FALSE(two.has<Velocity>(b));
  EXPECT_EQ(two.size<Velocity>(), 0U);
}

TEST(WorldTest, DeferredCommandsRunAtFlushInOrder) {
  World world;
  const Entity e = world.create();
  std::vector<std::string> log;
  world.defer([&](World& w) {
    w.add<Velocity>(e, 1.0F);
    log.push_back("first");
    w.defer([&](World&) { log.push_back("queued by first"); });
  });
  world.defer([&](World&) { log.push_back("second"); });
  EXPECT_EQ(world.deferred(), 2U);
  EXPECT_FALSE(world.has<Velocity>(e));
  EXPECT_TRUE(log.empty());

  world.flush();
  EXPECT_TRUE(world.has<Velocity>(e));
  EXPECT_THAT(log, ElementsAre("first", "second", "queued by first"));
  EXPECT_EQ(world.deferred(), 0U);
  world.flush();  // nothing left to run
  EXPECT_EQ(log.size(), 3U);
}

TEST(WorldTest, AThrowingCommandKeepsTheRestQueued) {
  World world;
  std::vector<int> ran;
  world.defer([&](World&) { ran.push_back(1); });
  world.defer([](World&) { throw std::runtime_error("boom"); });
  world.defer([&](World&) { ran.push_back(3); });
  EXPECT_THROW(world.flush(), std::runtime_error);
  EXPECT_THAT(ran, ElementsAre(1));
  EXPECT_EQ(world.deferred(), 1U);
  world.flush();
  EXPECT_THAT(ran, ElementsAre(1, 3));
}

TEST(WorldTest, DeferRejectsAnEmptyCommand) {
  World world;
  EXPECT_THROW(world.defer(nullptr), std::invalid_argument);
  EXPECT_EQ(world.deferred(), 0U);
}

TEST(WorldTest, MovingAWorldKeepsItsContent) {
  World world;
  const Entity e = world.create();
  world.add<Name>(e, "kept");
  World moved = std::move(world);
  EXPECT_TRUE(moved.valid(e));
  EXPECT_EQ(moved.get<Name>(e).text, "kept");
}

}  // namespace
}  // namespace tutti::ecs

namespace tutti::ecs {
namespace {

struct Clock {
  double t_s = 0.0;
};

TEST(WorldTest, AResourceIsOnePerWorldAndReplaced) {
  World world;
  EXPECT_EQ(world.resource<Clock>(), nullptr);
  Clock& clock = world.set_resource(Clock{1.5});
  EXPECT_EQ(clock.t_s, 1.5);
  world.set_resource(Clock{2.5});
  ASSERT_NE(world.resource<Clock>(), nullptr);
  EXPECT_EQ(world.resource<Clock>(), &clock);  // replaced in place
  EXPECT_EQ(world.resource<Clock>()->t_s, 2.5);
  const World& view = world;
  EXPECT_EQ(view.resource<Clock>()->t_s, 2.5);
  World other;
  EXPECT_EQ(other.resource<Clock>(), nullptr);  // not shared between worlds
  World moved = std::move(world);
  ASSERT_NE(moved.resource<Clock>(), nullptr);
  EXPECT_EQ(moved.resource<Clock>()->t_s, 2.5);
}

}  // namespace
}  // namespace tutti::ecs

namespace tutti::ecs {
namespace {

// A copy is a world of its own: the same handles, components and resources; changing one
// leaves the other as it was (the per-caller sampling contexts are copies of a stage's world).
TEST(WorldCopyTest, ACopyHasTheSameEntitiesComponentsAndResourcesAndIsIndependent) {
  World world;
  const Entity a = world.create();
  const Entity b = world.create();
  const Entity gone = world.create();
  world.destroy(gone);
  world.add<Position>(a, 1.0F, 2.0F);
  world.add<Name>(b, "b");
  world.add<Soloist>(b);
  world.add<Fixed>(a, 7);  // copyable, not assignable
  world.set_resource(Velocity{3.0F});

  World copy = world.copy();
  EXPECT_EQ(copy.alive(), 2U);
  EXPECT_TRUE(copy.valid(a));
  EXPECT_FALSE(copy.valid(gone));
  ASSERT_NE(copy.try_get<Position>(a), nullptr);
  EXPECT_EQ(copy.get<Position>(a).y, 2.0F);
  EXPECT_EQ(copy.get<Name>(b).text, "b");
  EXPECT_TRUE(copy.has<Soloist>(b));
  EXPECT_EQ(copy.get<Fixed>(a).id, 7);
  ASSERT_NE(copy.resource<Velocity>(), nullptr);
  EXPECT_EQ(copy.resource<Velocity>()->dx, 3.0F);

  copy.get<Position>(a).x = 10.0F;
  copy.resource<Velocity>()->dx = 4.0F;
  copy.remove<Name>(b);
  const Entity c = copy.create();
  EXPECT_EQ(c.index, gone.index);  // the copy reuses the same free slot, with a newer generation
  EXPECT_EQ(world.get<Position>(a).x, 1.0F);
  EXPECT_EQ(world.resource<Velocity>()->dx, 3.0F);
  EXPECT_EQ(world.get<Name>(b).text, "b");
  EXPECT_FALSE(world.valid(c));
  int seen = 0;
  copy.view<const Position>().each([&](const Position& p) { seen += static_cast<int>(p.x); });
  EXPECT_EQ(seen, 10);
}

TEST(WorldCopyTest, AComponentThatCannotBeCopiedIsAnErrorNamingIt) {
  World world;
  world.add<std::unique_ptr<int>>(world.create(), std::make_unique<int>(1));
  EXPECT_THAT([&] { (void)world.copy(); },
              ThrowsMessage<std::logic_error>(HasSubstr("cannot be copied")));
}

TEST(WorldCopyTest, CopyingWhileAViewIteratesIsRefused) {
  World world;
  world.add<Position>(world.create());
  EXPECT_THROW(world.view<Position>().each([&](Position&) { (void)world.copy(); }),
               std::logic_error);
}

}  // namespace
}  // namespace tutti::ecs
