// SPDX-License-Identifier: MIT
#include <tutti/ecs/sparse_set.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace tutti::ecs {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

struct Value {
  int v = 0;
};
struct Tag {};

TEST(SparseSetTest, EmplaceAppendsInDenseOrder) {
  Pool<Value> pool;
  pool.emplace(Entity{7, 0}, 70);
  pool.emplace(Entity{2, 3}, 20);
  pool.emplace(Entity{9, 1}, 90);
  EXPECT_THAT(pool.entities(), ElementsAre(Entity{7, 0}, Entity{2, 3}, Entity{9, 1}));
  EXPECT_EQ(pool.position(Entity{2, 3}), 1U);
  EXPECT_EQ(pool.value_at(2).v, 90);
  EXPECT_EQ(pool.get(Entity{7, 0}).v, 70);
  EXPECT_EQ(pool.type_name(), type_name<Value>());
}

TEST(SparseSetTest, ContainsChecksTheGeneration) {
  Pool<Value> pool;
  pool.emplace(Entity{4, 2}, 1);
  EXPECT_TRUE(pool.contains(Entity{4, 2}));
  EXPECT_FALSE(pool.contains(Entity{4, 1}));
  EXPECT_FALSE(pool.contains(Entity{4, 3}));
  EXPECT_FALSE(pool.contains(Entity{5, 2}));
  EXPECT_FALSE(pool.contains(Entity::null));
  EXPECT_EQ(pool.try_get(Entity{4, 1}), nullptr);
  EXPECT_FALSE(pool.remove(Entity{4, 1}));
  EXPECT_EQ(pool.size(), 1U);
}

TEST(SparseSetTest, RemoveMovesTheLastElementIntoTheHole) {
  Pool<Value> pool;
  for (std::uint32_t i = 0; i < 5; ++i) pool.emplace(Entity{i, 0}, static_cast<int>(i) * 10);
  EXPECT_TRUE(pool.remove(Entity{1, 0}));
  EXPECT_THAT(pool.entities(), ElementsAre(Entity{0, 0}, Entity{4, 0}, Entity{2, 0}, Entity{3, 0}));
  EXPECT_EQ(pool.position(Entity{4, 0}), 1U);
  EXPECT_EQ(pool.get(Entity{4, 0}).v, 40);
  EXPECT_EQ(pool.value_at(1).v, 40);
  EXPECT_TRUE(pool.remove(Entity{3, 0}));  // the last one: nothing moves
  EXPECT_THAT(pool.entities(), ElementsAre(Entity{0, 0}, Entity{4, 0}, Entity{2, 0}));
  std::vector<int> values;
  for (const Value& v : pool.values()) values.push_back(v.v);
  EXPECT_THAT(values, ElementsAre(0, 40, 20));
  EXPECT_FALSE(pool.contains(Entity{1, 0}));
  EXPECT_FALSE(pool.contains(Entity{3, 0}));
}

TEST(SparseSetTest, PagesCoverLargeAndScatteredIndices) {
  Pool<Value> pool;
  const std::vector<std::uint32_t> indices = {0, SparseSet::kPageSize - 1, SparseSet::kPageSize,
                                              10 * SparseSet::kPageSize + 17, 3'000'000};
  for (const std::uint32_t i : indices) pool.emplace(Entity{i, 0}, static_cast<int>(i % 1000));
  for (const std::uint32_t i : indices) {
    ASSERT_TRUE(pool.contains(Entity{i, 0})) << i;
    EXPECT_EQ(pool.get(Entity{i, 0}).v, static_cast<int>(i % 1000));
  }
  EXPECT_FALSE(pool.contains(Entity{SparseSet::kPageSize + 1, 0}));
  EXPECT_FALSE(pool.contains(Entity{5 * SparseSet::kPageSize, 0}));  // page never allocated
}

TEST(SparseSetTest, ClearEmptiesAndAllowsReuse) {
  Pool<Value> pool;
  pool.emplace(Entity{1, 0}, 1);
  pool.emplace(Entity{2, 0}, 2);
  pool.clear();
  EXPECT_TRUE(pool.empty());
  EXPECT_FALSE(pool.contains(Entity{1, 0}));
  pool.emplace(Entity{2, 0}, 5);
  EXPECT_EQ(pool.get(Entity{2, 0}).v, 5);
}

TEST(SparseSetTest, TagPoolStoresEntitiesOnly) {
  Pool<Tag> pool;
  static_assert(Pool<Tag>::kTag);
  pool.emplace(Entity{1, 0});
  pool.emplace(Entity{2, 0});
  EXPECT_EQ(pool.size(), 2U);
  EXPECT_NE(pool.try_get(Entity{1, 0}), nullptr);
  EXPECT_EQ(pool.try_get(Entity{3, 0}), nullptr);
  EXPECT_TRUE(pool.remove(Entity{1, 0}));
  EXPECT_THAT(pool.entities(), ElementsAre(Entity{2, 0}));
}

TEST(SparseSetTest, LockAllowsRemovingOnlyTheVisitedEntity) {
  Pool<Value> pool;
  for (std::uint32_t i = 0; i < 3; ++i) pool.emplace(Entity{i, 0}, 0);
  Entity cursor{1, 0};
  IterationFrame frame{&cursor};
  pool.begin_iteration(frame);
  EXPECT_EQ(pool.iterating(), 1U);
  EXPECT_THAT(
      [&] {
        pool.emplace(Entity{9, 0}, 0);
      },
      ThrowsMessage<std::logic_error>(HasSubstr("while a view iterates it")));
  EXPECT_THROW(pool.remove(Entity{0, 0}), std::logic_error);
  EXPECT_THROW(pool.clear(), std::logic_error);
  EXPECT_EQ(pool.size(), 3U);
  EXPECT_TRUE(pool.removable(Entity{1, 0}));
  EXPECT_TRUE(pool.remove(Entity{1, 0}));

  // A nested iteration visiting another entity forbids removing either.
  Entity inner_cursor{2, 0};
  IterationFrame inner{&inner_cursor};
  pool.begin_iteration(inner);
  EXPECT_EQ(pool.iterating(), 2U);
  EXPECT_FALSE(pool.removable(Entity{2, 0}));
  cursor = Entity{2, 0};
  EXPECT_TRUE(pool.removable(Entity{2, 0}));
  pool.end_iteration(inner);
  pool.end_iteration(frame);
  EXPECT_EQ(pool.iterating(), 0U);
  pool.emplace(Entity{9, 0}, 9);
  EXPECT_EQ(pool.size(), 3U);
}

TEST(SparseSetTest, IterationsMayEndOutOfOrder) {
  Pool<Value> pool;
  pool.emplace(Entity{0, 0}, 0);
  Entity a_cursor{0, 0};
  Entity b_cursor{5, 0};
  IterationFrame a{&a_cursor};
  IterationFrame b{&b_cursor};
  pool.begin_iteration(a);
  pool.begin_iteration(b);
  pool.end_iteration(a);
  EXPECT_EQ(pool.iterating(), 1U);
  EXPECT_FALSE(pool.removable(Entity{0, 0}));  // b still visits 5v0
  pool.end_iteration(b);
  EXPECT_TRUE(pool.remove(Entity{0, 0}));
}

}  // namespace
}  // namespace tutti::ecs
