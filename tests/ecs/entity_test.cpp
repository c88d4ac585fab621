// SPDX-License-Identifier: MIT
#include <tutti/ecs/entity.hpp>

#include <gtest/gtest.h>

#include <unordered_set>

#include <tutti/ecs/type_name.hpp>

namespace tutti::ecs {
namespace {

struct Heading {
  float x = 0.0F;
};

TEST(EntityTest, DefaultIsNull) {
  constexpr Entity e;
  static_assert(e.is_null());
  EXPECT_EQ(e, Entity::null);
  EXPECT_TRUE(Entity::null.is_null());
  EXPECT_FALSE((Entity{0, 0}.is_null()));
}

TEST(EntityTest, ComparesIndexAndGeneration) {
  EXPECT_EQ((Entity{3, 1}), (Entity{3, 1}));
  EXPECT_NE((Entity{3, 1}), (Entity{3, 2}));
  EXPECT_NE((Entity{3, 1}), (Entity{4, 1}));
  EXPECT_LT((Entity{3, 9}), (Entity{4, 0}));
  EXPECT_LT((Entity{3, 1}), (Entity{3, 2}));
}

TEST(EntityTest, BitsRoundTripWithGenerationInHighHalf) {
  constexpr Entity e{0x12345678U, 0x9ABCDEF0U};
  static_assert(e.bits() == 0x9ABCDEF012345678ULL);
  static_assert(Entity::from_bits(e.bits()) == e);
  EXPECT_EQ(Entity::from_bits(Entity::null.bits()), Entity::null);
}

TEST(EntityTest, HashesDistinctHandlesApart) {
  std::unordered_set<Entity> set;
  set.insert(Entity{1, 0});
  set.insert(Entity{1, 1});
  set.insert(Entity{2, 0});
  set.insert(Entity{1, 0});
  EXPECT_EQ(set.size(), 3U);
  EXPECT_TRUE(set.contains(Entity{1, 1}));
  EXPECT_FALSE(set.contains(Entity{2, 1}));
}

TEST(EntityTest, PrintsIndexVGeneration) {
  EXPECT_EQ(to_string(Entity{5, 2}), "5v2");
  EXPECT_EQ(to_string(Entity::null), "null");
}

TEST(TypeNameTest, NamesTheType) {
  static_assert(type_name<int>() == "int");
  EXPECT_EQ(type_name<double>(), "double");
  EXPECT_NE(type_name<Heading>().find("Heading"), std::string_view::npos);
  EXPECT_EQ(type_name<Heading>().find(']'), std::string_view::npos);
  EXPECT_EQ(type_name<Heading>().find(';'), std::string_view::npos);
}

}  // namespace
}  // namespace tutti::ecs
