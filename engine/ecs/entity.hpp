// SPDX-License-Identifier: MIT
#pragma once
// An entity is a handle, not an object: a slot index plus the generation the slot had when the
// handle was issued. Destroying an entity bumps its slot's generation, so every copy of the old
// handle goes stale at once and is detected (World::valid, has, try_get) instead of silently
// aliasing whatever entity reuses the slot next.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

namespace tutti::ecs {

struct Entity {
  static constexpr std::uint32_t kNullIndex = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::uint32_t kMaxGeneration = std::numeric_limits<std::uint32_t>::max();

  // The handle no World ever issues; a default-constructed Entity equals it.
  static const Entity null;

  std::uint32_t index = kNullIndex;
  std::uint32_t generation = kMaxGeneration;

  [[nodiscard]] constexpr bool is_null() const noexcept { return index == kNullIndex; }

  // The 64-bit form (generation in the high half) for hashing, sorting and serialising.
  [[nodiscard]] constexpr std::uint64_t bits() const noexcept {
    return (std::uint64_t{generation} << 32U) | index;
  }
  [[nodiscard]] static constexpr Entity from_bits(std::uint64_t bits) noexcept {
    return Entity{static_cast<std::uint32_t>(bits), static_cast<std::uint32_t>(bits >> 32U)};
  }

  // Orders by index, then generation.
  friend constexpr bool operator==(Entity, Entity) noexcept = default;
  friend constexpr auto operator<=>(Entity, Entity) noexcept = default;
};

inline constexpr Entity Entity::null{};

static_assert(sizeof(Entity) == 8, "an entity handle is 64 bits");

// "5v2" (index 5, generation 2), as Bevy prints it; "null" for Entity::null.
[[nodiscard]] inline std::string to_string(Entity e) {
  if (e.is_null()) return "null";
  return std::to_string(e.index) + "v" + std::to_string(e.generation);
}

}  // namespace tutti::ecs

template <>
struct std::hash<tutti::ecs::Entity> {
  std::size_t operator()(tutti::ecs::Entity e) const noexcept {
    return std::hash<std::uint64_t>{}(e.bits());
  }
};
