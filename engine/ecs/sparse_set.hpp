// SPDX-License-Identifier: MIT
#pragma once
// Component storage as sparse sets, after EnTT's sparse_set.hpp. A paged sparse array maps an
// entity index to a position in two packed arrays, one of entities and one of components, kept in
// step. Lookup is O(1), iterating a pool is a linear walk over contiguous memory, and removal is
// O(1) by moving the last element into the hole ("swap and pop"). Pages of the sparse array are
// allocated on first use, so a pool holding a few entities with large indices stays small.
//
// SparseSet is the type-erased half (entities and the sparse array), so a World can remove a
// destroyed entity from every pool without knowing the component types. Pool<T> adds the
// components. Neither is thread-safe.
//
// Views lock the pools they iterate (begin_iteration/end_iteration). While a pool is locked, the
// only structural change it accepts is removing the entity that every iteration in progress is
// visiting; anything else throws std::logic_error and leaves the pool unchanged.

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <tutti/ecs/entity.hpp>
#include <tutti/ecs/type_name.hpp>

namespace tutti::ecs {

// One per (pool, iteration in progress). The frames of a pool form a list, innermost first, so
// the pool can tell the entity being visited from any other.
struct IterationFrame {
  const Entity* cursor = nullptr;  // the entity the iteration is visiting now
  IterationFrame* outer = nullptr;
};

class SparseSet {
 public:
  static constexpr std::uint32_t kPageSize = 4096;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  virtual ~SparseSet();
  SparseSet(const SparseSet&) = delete;
  SparseSet& operator=(const SparseSet&) = delete;
  SparseSet(SparseSet&&) = delete;
  SparseSet& operator=(SparseSet&&) = delete;

  // False for Entity::null and for stale handles (the stored handle carries the generation).
  [[nodiscard]] bool contains(Entity e) const noexcept {
    const std::uint32_t* slot = find_slot(e.index);
    return slot != nullptr && *slot != kAbsent && dense_[*slot] == e;
  }
  // Position of e in entities(), or npos if e is not in the pool. One lookup where contains()
  // followed by position() would take two.
  [[nodiscard]] std::size_t find(Entity e) const noexcept {
    const std::uint32_t* slot = find_slot(e.index);
    return slot != nullptr && *slot != kAbsent && dense_[*slot] == e ? *slot : npos;
  }
  // Position of e in entities(). Precondition: contains(e).
  [[nodiscard]] std::size_t position(Entity e) const noexcept {
    assert(contains(e));
    return pages_[e.index / kPageSize][e.index % kPageSize];
  }
  [[nodiscard]] std::size_t size() const noexcept { return dense_.size(); }
  [[nodiscard]] bool empty() const noexcept { return dense_.empty(); }
  // Packed, in no meaningful order; every add and remove may reorder it.
  [[nodiscard]] std::span<const Entity> entities() const noexcept { return dense_; }
  // Precondition: pos < size().
  [[nodiscard]] Entity entity_at(std::size_t pos) const noexcept {
    assert(pos < dense_.size());
    return dense_[pos];
  }
  [[nodiscard]] std::string_view type_name() const noexcept { return type_name_; }

  // Removes e and its component, moving the last element into its place. Returns false if e is
  // not in the pool (stale handles included). Throws std::logic_error, changing nothing, if the
  // pool is locked and some iteration in progress visits another entity.
  bool remove(Entity e);
  // Throws std::logic_error, changing nothing, if the pool is locked.
  void clear();

  // Iterations in progress: views' each() calls and live range-for loops.
  [[nodiscard]] std::uint32_t iterating() const noexcept { return iterating_; }
  // Whether remove(e) would be accepted: no iteration, or every iteration visits e.
  [[nodiscard]] bool removable(Entity e) const noexcept;
  // Throw std::logic_error with the user-facing message if the change would be rejected.
  void check_add() const;
  void check_remove(Entity e) const;
  void check_clear() const;

  // For views. Frames must outlive the iteration; the pool links them but does not own them.
  void begin_iteration(IterationFrame& frame) noexcept;
  void end_iteration(IterationFrame& frame) noexcept;

  // A pool holding copies of this one's entities and components (World::copy), no iteration
  // in progress. Throws std::logic_error for a component type that cannot be copied.
  [[nodiscard]] virtual std::unique_ptr<SparseSet> copy() const = 0;

 protected:
  explicit SparseSet(std::string_view type_name) noexcept : type_name_(type_name) {}

  // This set's entities and sparse pages become `other`'s.
  void copy_entities_from(const SparseSet& other);

  // Appends e, whose component the derived pool has just appended at the same position.
  // Precondition: !contains(e). Strong guarantee: on bad_alloc nothing changed here.
  void push_entity(Entity e);

  // Moves the last component to pos and destroys the last one, mirroring the entity array.
  virtual void swap_and_pop_component(std::size_t pos) = 0;
  virtual void clear_components() noexcept = 0;

 private:
  static constexpr std::uint32_t kAbsent = std::numeric_limits<std::uint32_t>::max();

  [[nodiscard]] const std::uint32_t* find_slot(std::uint32_t index) const noexcept {
    const std::size_t page = index / kPageSize;
    if (page >= pages_.size() || !pages_[page]) return nullptr;
    return &pages_[page][index % kPageSize];
  }

  std::vector<std::unique_ptr<std::uint32_t[]>> pages_;
  std::vector<Entity> dense_;
  std::string_view type_name_;
  IterationFrame* iteration_ = nullptr;  // innermost iteration in progress
  std::uint32_t iterating_ = 0;
};

namespace detail {

// Brace-initialises aggregates, so add<Position>(e, 1.0F, 2.0F) works on clang 14, which lacks
// parenthesised aggregate initialisation.
template <typename T, typename... Args>
[[nodiscard]] T make_component(Args&&... args) {
  if constexpr (std::is_constructible_v<T, Args...>) {
    return T(std::forward<Args>(args)...);
  } else {
    return T{std::forward<Args>(args)...};
  }
}

}  // namespace detail

// Components of type T: any move-constructible object type. Empty types ("tags") store nothing;
// every tag reference points at one shared, stateless instance, which must be
// default-constructible.
template <typename T>
class Pool final : public SparseSet {
  static_assert(std::is_object_v<T> && std::is_same_v<T, std::remove_cv_t<T>>,
                "components are unqualified object types");
  static_assert(std::is_move_constructible_v<T> && std::is_destructible_v<T>,
                "components must be move-constructible");

 public:
  using value_type = T;
  static constexpr bool kTag = std::is_empty_v<T>;
  static_assert(!kTag || std::is_default_constructible_v<T>,
                "tag components need a default constructor");

  Pool() : SparseSet(ecs::type_name<T>()) {}
  ~Pool() override = default;
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;
  Pool(Pool&&) = delete;
  Pool& operator=(Pool&&) = delete;

  // Precondition: !contains(e). Throws std::logic_error, changing nothing, if the pool is locked;
  // if T's constructor or an allocation throws, nothing changed either.
  template <typename... Args>
  T& emplace(Entity e, Args&&... args) {
    assert(!contains(e));
    check_add();
    if constexpr (kTag) {
      if constexpr (sizeof...(Args) > 0) {
        // Built and dropped so that the arguments still have to make sense for T.
        [[maybe_unused]] const T discarded = detail::make_component<T>(std::forward<Args>(args)...);
      }
      push_entity(e);
      return storage_;
    } else {
      if constexpr (std::is_constructible_v<T, Args...>) {
        storage_.emplace_back(std::forward<Args>(args)...);
      } else {
        storage_.push_back(T{std::forward<Args>(args)...});
      }
      try {
        push_entity(e);
      } catch (...) {
        storage_.pop_back();
        throw;
      }
      return storage_.back();
    }
  }

  // Precondition: contains(e).
  [[nodiscard]] T& get(Entity e) noexcept { return value_at(position(e)); }
  [[nodiscard]] const T& get(Entity e) const noexcept { return value_at(position(e)); }

  // nullptr if e is not in the pool, including stale handles.
  [[nodiscard]] T* try_get(Entity e) noexcept { return contains(e) ? &get(e) : nullptr; }
  [[nodiscard]] const T* try_get(Entity e) const noexcept {
    return contains(e) ? &get(e) : nullptr;
  }

  // The component of entities()[pos]. Precondition: pos < size().
  [[nodiscard]] T& value_at(std::size_t pos) noexcept {
    assert(pos < size());
    if constexpr (kTag) {
      return storage_;
    } else {
      return storage_[pos];
    }
  }
  [[nodiscard]] const T& value_at(std::size_t pos) const noexcept {
    return const_cast<Pool*>(this)->value_at(pos);
  }

  // Packed components, parallel to entities(). Not available for tags.
  [[nodiscard]] std::span<T> values() noexcept requires(!kTag) { return storage_; }

  [[nodiscard]] std::unique_ptr<SparseSet> copy() const override {
    if constexpr (std::is_copy_constructible_v<T>) {
      auto out = std::make_unique<Pool<T>>();
      if constexpr (!kTag) out->storage_ = std::vector<T>(storage_);  // T need not be assignable
      out->copy_entities_from(*this);
      return out;
    } else {
      throw_not_copyable();
    }
  }

 private:
  void swap_and_pop_component(std::size_t pos) override {
    if constexpr (!kTag) {
      const std::size_t last = storage_.size() - 1;
      if (pos != last) {
        if constexpr (std::is_move_assignable_v<T>) {
          storage_[pos] = std::move(storage_[last]);
        } else {
          // Types with const or reference members cannot be assigned; rebuild the slot instead.
          static_assert(std::is_nothrow_move_constructible_v<T>,
                        "components that are not move-assignable need a noexcept move constructor");
          std::destroy_at(&storage_[pos]);
          std::construct_at(&storage_[pos], std::move(storage_[last]));
        }
      }
      storage_.pop_back();
    }
  }

  void clear_components() noexcept override {
    if constexpr (!kTag) storage_.clear();
  }

  [[noreturn]] void throw_not_copyable() const;

  [[no_unique_address]] std::conditional_t<kTag, T, std::vector<T>> storage_{};
};

template <typename T>
void Pool<T>::throw_not_copyable() const {
  throw std::logic_error("ecs: cannot copy a world holding " + std::string(type_name()) +
                         " components: the type cannot be copied");
}

}  // namespace tutti::ecs
