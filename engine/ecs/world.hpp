// SPDX-License-Identifier: MIT
#pragma once
// The World owns entities and their components (EnTT's registry, Bevy's World).
//
// Contracts, in short:
//  - Handles are validated: operations on a stale or null handle are harmless (valid/has are
//    false, try_get is nullptr, remove/destroy return false), except add(), which throws
//    std::invalid_argument because a component on a dead entity would be lost.
//  - get<T>(e) is unchecked: precondition has<T>(e), asserted in debug builds.
//  - While a view iterates, structural changes to its pools are restricted (see view.hpp) and
//    rejected with std::logic_error; World::defer queues a change for World::flush instead.
//  - Not thread-safe.

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <tutti/ecs/entity.hpp>
#include <tutti/ecs/sparse_set.hpp>
#include <tutti/ecs/type_index.hpp>
#include <tutti/ecs/view.hpp>

namespace tutti::ecs {

class World {
 public:
  using Command = std::function<void(World&)>;

  World();
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  // Views and pool references stay valid across a move (pools live on the heap).
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // A world of its own with copies of every entity (same handles), component and resource: the
  // state a second caller computes frames in while sharing what the components point at
  // (ozz-animation's per-caller context). Deferred commands are not copied. Throws
  // std::logic_error, copying nothing, if a view is iterating or a component or resource type
  // cannot be copied.
  [[nodiscard]] World copy() const;

  // A new entity with no components. Reuses the slot of a destroyed entity (with a higher
  // generation) before growing. Throws std::length_error after 2^32 - 1 slots.
  [[nodiscard]] Entity create();

  // Removes all of e's components, then retires the handle. Returns false if e was not valid.
  // Throws std::logic_error, changing nothing, if a view iterates one of e's pools and visits
  // another entity.
  bool destroy(Entity e);

  // Whether e was issued by this World and not destroyed since.
  [[nodiscard]] bool valid(Entity e) const noexcept {
    return e.index < slots_.size() && slots_[e.index].alive &&
           slots_[e.index].generation == e.generation;
  }

  // Live entities.
  [[nodiscard]] std::size_t alive() const noexcept { return alive_; }

  // Gives e a T built from args (T{args...} for aggregates) and returns it. If e already has a T,
  // the new value replaces it in place (no structural change). Throws std::invalid_argument if
  // !valid(e), std::logic_error if a view iterates T's pool (see view.hpp).
  template <typename T, typename... Args>
  T& add(Entity e, Args&&... args) {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "add takes an unqualified type");
    if (!valid(e)) throw_not_alive(ecs::type_name<T>(), e);
    Pool<T>& pool = assure<T>();
    if (T* existing = pool.try_get(e)) {
      if constexpr (!Pool<T>::kTag) {
        if constexpr (std::is_move_assignable_v<T>) {
          *existing = detail::make_component<T>(std::forward<Args>(args)...);
        } else {
          pool.check_add();  // so a rejected replacement leaves the old value in place
          pool.remove(e);
          return pool.emplace(e, std::forward<Args>(args)...);
        }
      }
      return *existing;
    }
    return pool.emplace(e, std::forward<Args>(args)...);
  }
  // EnTT's name for add().
  template <typename T, typename... Args>
  T& emplace(Entity e, Args&&... args) {
    return add<T>(e, std::forward<Args>(args)...);
  }

  // Removes e's T. Returns false if e had none (stale handles included). Throws std::logic_error,
  // changing nothing, if a view iterates T's pool and visits another entity.
  template <typename T>
  bool remove(Entity e) {
    Pool<T>* pool = find<T>();
    return pool != nullptr && pool->remove(e);
  }

  // Precondition: has<T>(e) (asserted in debug builds). The reference lives until T's pool
  // next changes structure (an add or remove of any T).
  template <typename T>
  [[nodiscard]] T& get(Entity e) noexcept {
    assert(has<T>(e));
    return find<T>()->get(e);
  }
  template <typename T>
  [[nodiscard]] const T& get(Entity e) const noexcept {
    assert(has<T>(e));
    return find<T>()->get(e);
  }

  // e's T, or nullptr if it has none or the handle is stale.
  template <typename T>
  [[nodiscard]] T* try_get(Entity e) noexcept {
    Pool<T>* pool = find<T>();
    return pool != nullptr ? pool->try_get(e) : nullptr;
  }
  template <typename T>
  [[nodiscard]] const T* try_get(Entity e) const noexcept {
    const Pool<T>* pool = find<T>();
    return pool != nullptr ? pool->try_get(e) : nullptr;
  }

  template <typename T>
  [[nodiscard]] bool has(Entity e) const noexcept {
    const Pool<T>* pool = find<T>();
    return pool != nullptr && pool->contains(e);
  }

  // Number of entities with a T.
  template <typename T>
  [[nodiscard]] std::size_t size() const noexcept {
    const Pool<T>* pool = find<T>();
    return pool != nullptr ? pool->size() : 0;
  }

  // Entities having all of Ts (each optionally const); see view.hpp.
  template <typename... Ts>
  [[nodiscard]] View<Ts...> view() {
    return View<Ts...>(assure<std::remove_const_t<Ts>>()...);
  }

  // T's pool, created empty on first use. For tools, tests and benchmarks that need the raw
  // arrays or the lock state.
  template <typename T>
  [[nodiscard]] Pool<T>& storage() {
    return assure<T>();
  }

  // Destroys every entity. Generations survive, so handles from before stay invalid. Deferred
  // commands stay queued. Throws std::logic_error, changing nothing, if a view is iterating.
  void clear();

  // Queues a change to apply at the next flush(): the way to change structure while a view
  // iterates. Throws std::invalid_argument if command is empty.
  void defer(Command command);
  // Runs queued commands in the order they were queued, including ones they queue themselves.
  // If a command throws, flush stops and rethrows; that command is dropped and the ones after
  // it stay queued.
  void flush();
  [[nodiscard]] std::size_t deferred() const noexcept { return commands_.size(); }

  // Resources (Bevy's): at most one T per World, owned by no entity — the frame's time, the
  // clock it comes from. set_resource replaces the previous value; resource<T>() is nullptr
  // until one is set.
  template <typename T>
  T& set_resource(T value) {
    static_assert(std::is_same_v<T, std::remove_cvref_t<T>>, "resources are unqualified types");
    const std::size_t id = type_index<T>();
    if (id >= resources_.size()) resources_.resize(id + 1);
    if (resources_[id] == nullptr) {
      resources_[id] = std::make_shared<T>(std::move(value));
      if (id >= resource_copiers_.size()) resource_copiers_.resize(id + 1, nullptr);
      resource_copiers_[id] = &copy_resource<T>;
    } else {
      *static_cast<T*>(resources_[id].get()) = std::move(value);
    }
    return *static_cast<T*>(resources_[id].get());
  }
  template <typename T>
  [[nodiscard]] T* resource() noexcept {
    const std::size_t id = type_index<T>();
    return id < resources_.size() ? static_cast<T*>(resources_[id].get()) : nullptr;
  }
  template <typename T>
  [[nodiscard]] const T* resource() const noexcept {
    const std::size_t id = type_index<T>();
    return id < resources_.size() ? static_cast<const T*>(resources_[id].get()) : nullptr;
  }

 private:
  struct Slot {
    std::uint32_t generation = 0;
    bool alive = false;
  };

  template <typename T>
  [[nodiscard]] Pool<T>* find() const noexcept {
    const std::size_t id = type_index<T>();
    return id < pools_.size() ? static_cast<Pool<T>*>(pools_[id].get()) : nullptr;
  }

  template <typename T>
  [[nodiscard]] Pool<T>& assure() {
    const std::size_t id = type_index<T>();
    if (id >= pools_.size()) pools_.resize(id + 1);
    if (!pools_[id]) pools_[id] = std::make_unique<Pool<T>>();
    return static_cast<Pool<T>&>(*pools_[id]);
  }

  // Marks slot `index` dead and bumps its generation; a slot whose generation would wrap is
  // retired instead of reused, so an old handle can never match again.
  void release(std::uint32_t index);

  [[noreturn]] static void throw_not_alive(std::string_view type, Entity e);
  [[noreturn]] static void throw_not_copyable(std::string_view type);
  template <typename T>
  static std::shared_ptr<void> copy_resource(const void* value) {
    if constexpr (std::is_copy_constructible_v<T>) {
      return std::make_shared<T>(*static_cast<const T*>(value));
    } else {
      throw_not_copyable(ecs::type_name<T>());
    }
  }
  using ResourceCopier = std::shared_ptr<void> (*)(const void*);

  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_;  // dead slots to reuse, most recent last
  std::size_t alive_ = 0;
  std::vector<std::unique_ptr<SparseSet>> pools_;  // by type_index<T>()
  std::vector<Command> commands_;
  std::vector<std::shared_ptr<void>> resources_;  // by type_index<T>()
  std::vector<ResourceCopier> resource_copiers_;  // by type_index<T>(), for copy()
};

}  // namespace tutti::ecs
