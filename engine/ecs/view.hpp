// SPDX-License-Identifier: MIT
#pragma once
// Views: the entities that have all of a set of components, and those components.
//
// A view walks the SMALLEST of its pools (chosen when iteration starts) and checks the others, so
// view<Position, Velocity, Soloist>() over a million positions and ten soloists costs ten steps.
//
// Iteration goes through the driving pool's packed array from the back to the front. That is
// what makes removing the CURRENT entity safe: swap-and-pop moves the pool's last element into
// the current slot, and the last element has already been visited, while every slot below the
// current one stays where it was. So inside each() (or a range-for body) you may remove
// components from, or destroy, the entity being visited; every other matching entity is still
// visited exactly once. After such a removal the references the callback received for the
// removed components are no longer valid: do not use them. When views of one pool are nested,
// the removal must concern the entity that all of them are visiting.
//
// Every other structural change to a pool of the view while it iterates would skip or repeat
// entities, or leave the callback's references dangling after a reallocation, so it is rejected:
// adding a component of one of the view's types to any entity, removing one from another entity,
// destroying another entity that has one, or clearing the pool throws std::logic_error
// ("ecs: cannot add Foo to a pool while a view iterates it; defer the change (World::defer)")
// and changes nothing. Queue such changes with World::defer and apply them with World::flush
// (a Schedule flushes after each phase). Pools of other types, and creating entities, are free.
//
// A view holds pointers to its World's pools; it must not outlive the World.

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <memory>
#include <tuple>
#include <type_traits>
#include <utility>

#include <tutti/ecs/entity.hpp>
#include <tutti/ecs/sparse_set.hpp>

namespace tutti::ecs {

namespace detail {

template <typename... Ts>
inline constexpr bool kDistinct = true;
template <typename T, typename... Ts>
inline constexpr bool kDistinct<T, Ts...> =
    (!std::is_same_v<std::remove_const_t<T>, std::remove_const_t<Ts>> && ...) && kDistinct<Ts...>;

// Locks N pools for one iteration. Not movable: the pools point at its frames.
template <std::size_t N>
class IterationLock {
 public:
  IterationLock(const std::array<SparseSet*, N>& pools, const Entity* cursor) noexcept
      : pools_(pools) {
    for (std::size_t k = 0; k < N; ++k) {
      frames_[k].cursor = cursor;
      pools_[k]->begin_iteration(frames_[k]);
    }
  }
  ~IterationLock() {
    for (std::size_t k = N; k-- > 0;) pools_[k]->end_iteration(frames_[k]);
  }
  IterationLock(const IterationLock&) = delete;
  IterationLock& operator=(const IterationLock&) = delete;
  IterationLock(IterationLock&&) = delete;
  IterationLock& operator=(IterationLock&&) = delete;

 private:
  std::array<SparseSet*, N> pools_;
  std::array<IterationFrame, N> frames_{};
};

template <typename>
inline constexpr bool kAlwaysFalse = false;

}  // namespace detail

// Ts are component types, each optionally const (view<const Score, Pose>: the callback gets
// const Score& and Pose&). Build one with World::view<Ts...>().
template <typename... Ts>
class View {
  static_assert(sizeof...(Ts) > 0, "a view needs at least one component type");
  static_assert(detail::kDistinct<Ts...>, "a view names each component type once");

  static constexpr std::size_t kCount = sizeof...(Ts);
  using Pools = std::tuple<Pool<std::remove_const_t<Ts>>*...>;
  template <std::size_t I>
  using Component = std::tuple_element_t<I, std::tuple<Ts...>>;
  using Indices = std::index_sequence_for<Ts...>;
  using Positions = std::array<std::size_t, kCount>;  // of one entity, in each pool

 public:
  explicit View(Pool<std::remove_const_t<Ts>>&... pools) noexcept : pools_{&pools...} {}

  // Calls f(Entity, Ts&...) or f(Ts&...) once per matching entity, in no meaningful order.
  // Locks the view's pools for the duration (see the file comment); exceptions from f propagate
  // and release the locks.
  template <typename F>
  void each(F&& f) const {
    const std::array<SparseSet*, kCount> pools = erase(pools_);
    SparseSet* const driver = smallest(pools);
    Entity current = Entity::null;
    const detail::IterationLock<kCount> lock(pools, &current);
    // Only the current entity may leave the pools meanwhile, so the slots below pos keep their
    // entities and pos never exceeds the driver's size.
    for (std::size_t pos = driver->size(); pos > 0;) {
      --pos;
      const Entity e = driver->entity_at(pos);
      Positions at;
      if (!locate(driver, pos, e, at, Indices{})) continue;
      current = e;
      call(f, e, at, Indices{});
    }
  }

  // Whether e has all of Ts. False for stale handles.
  [[nodiscard]] bool contains(Entity e) const noexcept {
    return contains_except(pools_, nullptr, e);
  }

  // Size of the smallest pool: an upper bound on the number of matching entities.
  [[nodiscard]] std::size_t size_hint() const noexcept { return smallest(erase(pools_))->size(); }

  // Range-for over the matching entities: `for (Entity e : world.view<A, B>())`. The loop locks
  // the pools exactly like each() until it ends (or the begin iterator is destroyed). The
  // iterator is move-only and allocates its lock state once per loop.
  struct Sentinel {};
  class Iterator {
   public:
    using value_type = Entity;
    using difference_type = std::ptrdiff_t;
    using iterator_concept = std::input_iterator_tag;

    Iterator() = default;
    [[nodiscard]] Entity operator*() const noexcept { return state_->current; }
    Iterator& operator++() {
      if (!state_->advance()) state_.reset();  // releases the locks as soon as the walk ends
      return *this;
    }
    void operator++(int) { ++*this; }
    friend bool operator==(const Iterator& it, Sentinel) noexcept { return it.state_ == nullptr; }

   private:
    friend class View;

    struct State {
      explicit State(const Pools& p)
          : pools(p),
            erased(erase(p)),
            driver(smallest(erased)),
            next(driver->size()),
            lock(erased, &current) {}

      // Moves to the next matching entity below `next`; false when there is none.
      bool advance() noexcept {
        while (next > 0) {
          --next;
          const Entity e = driver->entity_at(next);
          if (contains_except(pools, driver, e)) {
            current = e;
            return true;
          }
        }
        current = Entity::null;
        return false;
      }

      Pools pools;
      std::array<SparseSet*, kCount> erased;
      SparseSet* driver;
      std::size_t next;
      Entity current = Entity::null;
      detail::IterationLock<kCount> lock;
    };

    explicit Iterator(const Pools& pools) : state_(std::make_unique<State>(pools)) {
      if (!state_->advance()) state_.reset();
    }

    std::unique_ptr<State> state_;
  };

  [[nodiscard]] Iterator begin() const { return Iterator(pools_); }
  [[nodiscard]] Sentinel end() const noexcept { return {}; }

 private:
  [[nodiscard]] static std::array<SparseSet*, kCount> erase(const Pools& pools) noexcept {
    return std::apply([](auto*... p) { return std::array<SparseSet*, kCount>{p...}; }, pools);
  }

  [[nodiscard]] static SparseSet* smallest(const std::array<SparseSet*, kCount>& pools) noexcept {
    return *std::min_element(
        pools.begin(), pools.end(),
        [](const SparseSet* a, const SparseSet* b) { return a->size() < b->size(); });
  }

  // The driving pool holds e by construction; skipping it saves a lookup per entity.
  [[nodiscard]] static bool contains_except(const Pools& pools, const SparseSet* driver,
                                            Entity e) noexcept {
    return std::apply(
        [&](const auto*... p) {
          return ((static_cast<const SparseSet*>(p) == driver || p->contains(e)) && ...);
        },
        pools);
  }

  // Finds e in every pool (the driver already knows its position); false if one lacks it.
  template <std::size_t... I>
  bool locate(const SparseSet* driver, std::size_t pos, Entity e, Positions& at,
              std::index_sequence<I...>) const noexcept {
    const auto find = [&](const SparseSet* pool, std::size_t& out) {
      out = pool == driver ? pos : pool->find(e);
      return out != SparseSet::npos;
    };
    return (find(std::get<I>(pools_), at[I]) && ...);
  }

  template <typename F, std::size_t... I>
  void call(F& f, Entity e, const Positions& at, std::index_sequence<I...>) const {
    if constexpr (std::is_invocable_v<F&, Entity, Ts&...>) {
      f(e, static_cast<Component<I>&>(std::get<I>(pools_)->value_at(at[I]))...);
    } else if constexpr (std::is_invocable_v<F&, Ts&...>) {
      f(static_cast<Component<I>&>(std::get<I>(pools_)->value_at(at[I]))...);
    } else {
      static_assert(detail::kAlwaysFalse<F>, "each() takes f(Entity, Ts&...) or f(Ts&...)");
    }
  }

  Pools pools_;
};

}  // namespace tutti::ecs
