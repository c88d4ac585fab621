// SPDX-License-Identifier: MIT
#include <tutti/ecs/world.hpp>

#include <iterator>
#include <stdexcept>
#include <string>

namespace tutti::ecs {

World::World() = default;
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Entity World::create() {
  if (!free_.empty()) {
    const std::uint32_t index = free_.back();
    free_.pop_back();
    Slot& slot = slots_[index];
    slot.alive = true;
    ++alive_;
    return Entity{index, slot.generation};
  }
  if (slots_.size() >= Entity::kNullIndex) throw std::length_error("ecs: out of entity indices");
  const auto index = static_cast<std::uint32_t>(slots_.size());
  slots_.push_back(Slot{0, true});
  ++alive_;
  return Entity{index, 0};
}

bool World::destroy(Entity e) {
  if (!valid(e)) return false;
  // Check every pool before touching any, so a rejected destroy leaves the entity whole.
  for (const auto& pool : pools_) {
    if (pool != nullptr && pool->contains(e)) pool->check_remove(e);
  }
  for (const auto& pool : pools_) {
    if (pool != nullptr) pool->remove(e);
  }
  release(e.index);
  return true;
}

void World::clear() {
  for (const auto& pool : pools_) {
    if (pool != nullptr) pool->check_clear();
  }
  for (const auto& pool : pools_) {
    if (pool != nullptr) pool->clear();
  }
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].alive) release(static_cast<std::uint32_t>(i));
  }
}

void World::release(std::uint32_t index) {
  Slot& slot = slots_[index];
  slot.alive = false;
  --alive_;
  if (slot.generation == Entity::kMaxGeneration) return;
  ++slot.generation;
  free_.push_back(index);
}

void World::defer(Command command) {
  if (!command) throw std::invalid_argument("ecs: World::defer needs a callable command");
  commands_.push_back(std::move(command));
}

void World::flush() {
  while (!commands_.empty()) {
    std::vector<Command> batch;
    batch.swap(commands_);
    std::size_t i = 0;
    try {
      for (; i < batch.size(); ++i) batch[i](*this);
    } catch (...) {
      // Put the unrun rest back ahead of anything the batch queued, preserving order.
      commands_.insert(commands_.begin(), std::make_move_iterator(batch.begin() + i + 1),
                       std::make_move_iterator(batch.end()));
      throw;
    }
  }
}

World World::copy() const {
  World out;
  out.slots_ = slots_;
  out.free_ = free_;
  out.alive_ = alive_;
  out.pools_.resize(pools_.size());
  for (std::size_t i = 0; i < pools_.size(); ++i) {
    if (pools_[i] == nullptr) continue;
    if (pools_[i]->iterating() > 0) {
      throw std::logic_error("ecs: cannot copy a world while a view iterates " +
                             std::string(pools_[i]->type_name()));
    }
    out.pools_[i] = pools_[i]->copy();
  }
  out.resources_.resize(resources_.size());
  out.resource_copiers_ = resource_copiers_;
  for (std::size_t i = 0; i < resources_.size(); ++i) {
    if (resources_[i] != nullptr) out.resources_[i] = resource_copiers_[i](resources_[i].get());
  }
  return out;
}

void World::throw_not_copyable(std::string_view type) {
  throw std::logic_error("ecs: cannot copy a world holding a " + std::string(type) +
                         " resource: the type cannot be copied");
}

void World::throw_not_alive(std::string_view type, Entity e) {
  throw std::invalid_argument("ecs: cannot add " + std::string(type) + " to entity " +
                              to_string(e) + ": the entity is not alive");
}

}  // namespace tutti::ecs
