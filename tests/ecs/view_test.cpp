// SPDX-License-Identifier: MIT
#include <tutti/ecs/view.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include <tutti/ecs/world.hpp>

namespace tutti::ecs {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAreArray;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using ::testing::UnorderedElementsAreArray;

struct A {
  int v = 0;
};
struct B {
  int v = 0;
};
struct C {
  int v = 0;
};
struct Unused {
  int v = 0;
};
struct Marked {};

// 100 entities: all have A (v = i), even ones B (v = 10 i), multiples of 3 C (v = 100 i), and
// multiples of 5 the Marked tag. Pool sizes 100, 50, 34, 20 make the smallest pool matter.
class ViewTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 0; i < 100; ++i) {
      const Entity e = world.create();
      es.push_back(e);
      world.add<A>(e, i);
      if (i % 2 == 0) world.add<B>(e, 10 * i);
      if (i % 3 == 0) world.add<C>(e, 100 * i);
      if (i % 5 == 0) world.add<Marked>(e);
    }
  }

  std::vector<Entity> entities_where(bool (*keep)(int)) const {
    std::vector<Entity> out;
    for (int i = 0; i < 100; ++i) {
      if (keep(i)) out.push_back(es[static_cast<std::size_t>(i)]);
    }
    return out;
  }

  World world;
  std::vector<Entity> es;
};

TEST_F(ViewTest, OneComponentVisitsThePool) {
  int count = 0;
  int sum = 0;
  world.view<C>().each([&](C& c) {
    ++count;
    sum += c.v;
  });
  EXPECT_EQ(count, 34);
  int expected = 0;
  for (int i = 0; i < 100; i += 3) expected += 100 * i;
  EXPECT_EQ(sum, expected);
}

TEST_F(ViewTest, TwoPoolsVisitExactlyTheIntersectionWithTheRightComponents) {
  std::vector<Entity> seen;
  world.view<A, B>().each([&](Entity e, A& a, B& b) {
    EXPECT_EQ(b.v, 10 * a.v);
    EXPECT_EQ(e, es[static_cast<std::size_t>(a.v)]);
    seen.push_back(e);
  });
  EXPECT_THAT(seen, UnorderedElementsAreArray(entities_where([](int i) { return i % 2 == 0; })));
}

TEST_F(ViewTest, ThreePoolsVisitExactlyTheIntersection) {
  std::vector<Entity> seen;
  world.view<B, A, C>().each([&](Entity e, B& b, A& a, C& c) {
    EXPECT_EQ(b.v, 10 * a.v);
    EXPECT_EQ(c.v, 100 * a.v);
    seen.push_back(e);
  });
  EXPECT_THAT(seen, UnorderedElementsAreArray(entities_where([](int i) { return i % 6 == 0; })));

  std::vector<Entity> with_tag;
  world.view<A, Marked, C>().each([&](Entity e, A&, Marked&, C&) { with_tag.push_back(e); });
  EXPECT_THAT(with_tag,
              UnorderedElementsAreArray(entities_where([](int i) { return i % 15 == 0; })));
}

TEST_F(ViewTest, TheSmallestPoolDrivesBackToFront) {
  // Scramble C's dense order so that "driven by C" and "driven by A" give different orders.
  world.remove<C>(es[0]);
  world.add<C>(es[0], 0);
  world.remove<C>(es[30]);
  world.add<C>(es[30], 3000);

  std::vector<Entity> expected;
  const auto dense = world.storage<C>().entities();
  for (auto it = dense.rbegin(); it != dense.rend(); ++it) {
    if (world.has<B>(*it)) expected.push_back(*it);
  }
  std::vector<Entity> seen;
  world.view<A, B, C>().each([&](Entity e, A&, B&, C&) { seen.push_back(e); });
  EXPECT_THAT(seen, ElementsAreArray(expected));

  seen.clear();
  for (const Entity e : world.view<A, B, C>()) seen.push_back(e);
  EXPECT_THAT(seen, ElementsAreArray(expected));
}

TEST_F(ViewTest, EachWithoutTheEntityAndRangeFor) {
  int sum_each = 0;
  world.view<A, C>().each([&](const A& a, C&) { sum_each += a.v; });
  int sum_for = 0;
  for (const Entity e : world.view<A, C>()) sum_for += world.get<A>(e).v;
  int expected = 0;
  for (int i = 0; i < 100; i += 3) expected += i;
  EXPECT_EQ(sum_each, expected);
  EXPECT_EQ(sum_for, expected);
}

TEST_F(ViewTest, ConstComponentsArePassedAsConst) {
  world.view<const A, B>().each([](Entity, auto& a, auto& b) {
    static_assert(std::is_const_v<std::remove_reference_t<decltype(a)>>);
    static_assert(!std::is_const_v<std::remove_reference_t<decltype(b)>>);
    b.v += a.v;
  });
  EXPECT_EQ(world.get<B>(es[4]).v, 44);
  EXPECT_EQ(world.get<A>(es[4]).v, 4);
}

TEST_F(ViewTest, ContainsAndSizeHint) {
  auto view = world.view<A, B, C>();
  EXPECT_EQ(view.size_hint(), 34U);
  EXPECT_TRUE(view.contains(es[6]));
  EXPECT_FALSE(view.contains(es[3]));
  EXPECT_FALSE(view.contains(Entity::null));
}

TEST_F(ViewTest, EmptyPoolsGiveEmptyViews) {
  int count = 0;
  world.view<A, Unused>().each([&](A&, Unused&) { ++count; });
  for ([[maybe_unused]] const Entity e : world.view<Unused>()) ++count;
  EXPECT_EQ(count, 0);
  World empty;
  empty.view<A>().each([&](A&) { ++count; });
  EXPECT_EQ(count, 0);
}

TEST_F(ViewTest, RemovingTheCurrentEntitysDrivingComponentVisitsAllOthersOnce) {
  std::map<int, int> visits;
  world.view<C>().each([&](Entity e, C& c) {
    ++visits[c.v / 100];
    EXPECT_TRUE(world.remove<C>(e));
  });
  EXPECT_EQ(visits.size(), 34U);
  for (const auto& [i, n] : visits) EXPECT_EQ(n, 1) << i;
  EXPECT_EQ(world.size<C>(), 0U);
}

TEST_F(ViewTest, RemovingTheCurrentEntitysOtherComponentVisitsAllOthersOnce) {
  // Driven by C (34); removes the current entity's A and B (the larger pools).
  std::map<int, int> visits;
  world.view<A, B, C>().each([&](Entity e, A& a, B&, C&) {
    ++visits[a.v];
    EXPECT_TRUE(world.remove<A>(e));
    EXPECT_TRUE(world.remove<B>(e));
  });
  EXPECT_EQ(visits.size(), 17U);
  for (const auto& [i, n] : visits) {
    EXPECT_EQ(i % 6, 0);
    EXPECT_EQ(n, 1) << i;
  }
  EXPECT_EQ(world.size<A>(), 83U);
  EXPECT_EQ(world.size<B>(), 33U);
  EXPECT_EQ(world.get<A>(es[7]).v, 7);  // swap-and-pop kept the others intact
  EXPECT_EQ(world.get<B>(es[8]).v, 80);
}

TEST_F(ViewTest, DestroyingTheCurrentEntityVisitsAllOthersOnce) {
  std::map<int, int> visits;
  world.view<A, B>().each([&](Entity e, A& a, B&) {
    ++visits[a.v];
    if (a.v % 4 == 0) {
      EXPECT_TRUE(world.destroy(e));
    }
  });
  EXPECT_EQ(visits.size(), 50U);
  for (const auto& [i, n] : visits) EXPECT_EQ(n, 1) << i;
  EXPECT_EQ(world.alive(), 75U);
  EXPECT_EQ(world.size<C>(), 34U - 9U);  // 0, 12, ..., 96 had C
  EXPECT_FALSE(world.valid(es[8]));
  EXPECT_TRUE(world.valid(es[6]));
  EXPECT_EQ(world.get<C>(es[6]).v, 600);
}

TEST_F(ViewTest, DestroyingTheCurrentEntityInsideRangeFor) {
  int visited = 0;
  for (const Entity e : world.view<B>()) {
    ++visited;
    EXPECT_TRUE(world.destroy(e));
  }
  EXPECT_EQ(visited, 50);
  EXPECT_EQ(world.size<B>(), 0U);
  EXPECT_EQ(world.alive(), 50U);
}

TEST_F(ViewTest, AddingToAnIteratedPoolIsRejected) {
  const Entity fresh = world.create();
  int visited = 0;
  world.view<A, B>().each([&](Entity, A&, B&) {
    ++visited;
    EXPECT_THAT([&] { world.add<B>(fresh, 1); },
                ThrowsMessage<std::logic_error>(HasSubstr(
                    "cannot add " + std::string(type_name<B>()) +
                    " to a pool while a view iterates it; defer the change (World::defer)")));
    EXPECT_THROW(world.add<A>(fresh, 1), std::logic_error);
  });
  EXPECT_EQ(visited, 50);
  EXPECT_FALSE(world.has<A>(fresh));
  EXPECT_FALSE(world.has<B>(fresh));
  EXPECT_EQ(world.size<B>(), 50U);
}

TEST_F(ViewTest, RemovingAnotherEntityFromAnIteratedPoolIsRejected) {
  bool checked = false;
  world.view<A, B>().each([&](Entity e, A&, B&) {
    if (checked) return;
    checked = true;
    const Entity other = e == es[0] ? es[2] : es[0];
    EXPECT_THAT([&] { world.remove<B>(other); },
                ThrowsMessage<std::logic_error>(
                    AllOf(HasSubstr("cannot remove " + std::string(type_name<B>()) +
                                    " from entity " + to_string(other)),
                          HasSubstr("defer the change (World::defer)"))));
    EXPECT_THROW(world.remove<A>(other), std::logic_error);
    EXPECT_THROW(world.destroy(other), std::logic_error);
    EXPECT_THROW(world.clear(), std::logic_error);
  });
  EXPECT_TRUE(checked);
  // Nothing changed: the rejected calls were all-or-nothing.
  EXPECT_EQ(world.alive(), 100U);
  EXPECT_EQ(world.size<A>(), 100U);
  EXPECT_EQ(world.size<B>(), 50U);
  EXPECT_EQ(world.size<C>(), 34U);
}

TEST_F(ViewTest, RangeForLocksUntilTheLoopEnds) {
  const Entity fresh = world.create();
  for ([[maybe_unused]] const Entity e : world.view<B>()) {
    EXPECT_THROW(world.add<B>(fresh), std::logic_error);
    EXPECT_EQ(world.storage<B>().iterating(), 1U);
    break;
  }
  EXPECT_EQ(world.storage<B>().iterating(), 0U);
  world.add<B>(fresh, 1);
  EXPECT_TRUE(world.has<B>(fresh));
}

TEST_F(ViewTest, OtherPoolsAndNewEntitiesAreFreeDuringIteration) {
  int visited = 0;
  world.view<A, C>().each([&](Entity e, A& a, C&) {
    ++visited;
    world.add<Unused>(e, a.v);
    const Entity child = world.create();
    world.add<Unused>(child, -1);
  });
  EXPECT_EQ(visited, 34);
  EXPECT_EQ(world.size<Unused>(), 68U);
  EXPECT_EQ(world.alive(), 134U);
  EXPECT_EQ(world.get<Unused>(es[9]).v, 9);
}

TEST_F(ViewTest, DeferredChangesApplyAtFlush) {
  world.view<A, B>().each([&](Entity e, A& a, B&) {
    if (a.v % 4 == 0) {
      world.defer([e](World& w) { w.remove<B>(e); });
    } else {
      world.defer([e](World& w) { w.add<C>(e, -1); });
    }
  });
  EXPECT_EQ(world.size<B>(), 50U);
  world.flush();
  EXPECT_EQ(world.size<B>(), 25U);
  EXPECT_FALSE(world.has<B>(es[4]));
  EXPECT_TRUE(world.has<B>(es[2]));
  EXPECT_EQ(world.get<C>(es[2]).v, -1);
  EXPECT_EQ(world.get<C>(es[6]).v, -1);        // replaced
  EXPECT_EQ(world.size<C>(), 34U + 25U - 8U);  // 25 got C; 8 of them (6 mod 12) had one
}

TEST_F(ViewTest, AnExceptionFromTheCallbackReleasesTheLocks) {
  auto view = world.view<A, B>();
  EXPECT_THROW(view.each([](A&, B&) { throw std::runtime_error("stop"); }), std::runtime_error);
  EXPECT_EQ(world.storage<A>().iterating(), 0U);
  EXPECT_EQ(world.storage<B>().iterating(), 0U);
  world.add<B>(es[1], 1);
  EXPECT_TRUE(world.has<B>(es[1]));
}

TEST_F(ViewTest, NestedViewsOnlyAllowRemovingAnEntityBothVisit) {
  int removed = 0;
  int rejected = 0;
  world.view<C>().each([&](Entity outer, C&) {
    world.view<B, C>().each([&](Entity inner, B&, C&) {
      if (inner != outer) {
        EXPECT_THROW(world.remove<C>(inner), std::logic_error);
        ++rejected;
      }
    });
    if (world.has<B>(outer)) {
      world.view<B, C>().each([&](Entity inner, B&, C&) {
        if (inner == outer) {
          EXPECT_TRUE(world.remove<C>(inner));
          ++removed;
        }
      });
    }
  });
  EXPECT_EQ(removed, 17);
  EXPECT_GT(rejected, 0);
  EXPECT_EQ(world.size<C>(), 17U);
}

}  // namespace
}  // namespace tutti::ecs
