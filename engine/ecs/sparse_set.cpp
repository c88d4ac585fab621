// SPDX-License-Identifier: MIT
#include <tutti/ecs/sparse_set.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tutti::ecs {

namespace {

constexpr std::string_view kAdvice = "; defer the change (World::defer)";

}  // namespace

SparseSet::~SparseSet() = default;

bool SparseSet::remove(Entity e) {
  if (!contains(e)) return false;
  check_remove(e);
  const std::uint32_t pos = pages_[e.index / kPageSize][e.index % kPageSize];
  // The component moves first: if a throwing move leaves early, the entity array is untouched.
  swap_and_pop_component(pos);
  const Entity last = dense_.back();
  dense_[pos] = last;
  pages_[last.index / kPageSize][last.index % kPageSize] = pos;
  dense_.pop_back();
  pages_[e.index / kPageSize][e.index % kPageSize] = kAbsent;
  return true;
}

void SparseSet::clear() {
  check_clear();
  clear_components();
  for (const Entity e : dense_) pages_[e.index / kPageSize][e.index % kPageSize] = kAbsent;
  dense_.clear();
}

bool SparseSet::removable(Entity e) const noexcept {
  for (const IterationFrame* frame = iteration_; frame != nullptr; frame = frame->outer) {
    if (*frame->cursor != e) return false;
  }
  return true;
}

void SparseSet::check_add() const {
  if (iterating_ == 0) return;
  throw std::logic_error("ecs: cannot add " + std::string(type_name_) +
                         " to a pool while a view iterates it" + std::string(kAdvice));
}

void SparseSet::check_remove(Entity e) const {
  if (removable(e)) return;
  throw std::logic_error("ecs: cannot remove " + std::string(type_name_) + " from entity " +
                         to_string(e) +
                         " while a view iterates its pool and visits another entity; only the "
                         "visited entity may lose components or be destroyed" +
                         std::string(kAdvice));
}

void SparseSet::check_clear() const {
  if (iterating_ == 0) return;
  throw std::logic_error("ecs: cannot clear the pool of " + std::string(type_name_) +
                         " while a view iterates it" + std::string(kAdvice));
}

void SparseSet::begin_iteration(IterationFrame& frame) noexcept {
  frame.outer = iteration_;
  iteration_ = &frame;
  ++iterating_;
}

void SparseSet::end_iteration(IterationFrame& frame) noexcept {
  // Usually the innermost frame; range-for iterators may end out of order, so unlink anywhere.
  for (IterationFrame** link = &iteration_; *link != nullptr; link = &(*link)->outer) {
    if (*link == &frame) {
      *link = frame.outer;
      --iterating_;
      return;
    }
  }
  assert(false && "end_iteration without begin_iteration");
}

void SparseSet::push_entity(Entity e) {
  assert(!e.is_null());
  const std::size_t page = e.index / kPageSize;
  if (page >= pages_.size()) pages_.resize(page + 1);
  if (!pages_[page]) {
    pages_[page] = std::make_unique<std::uint32_t[]>(kPageSize);
    std::fill_n(pages_[page].get(), kPageSize, kAbsent);
  }
  const auto pos = static_cast<std::uint32_t>(dense_.size());
  dense_.push_back(e);
  pages_[page][e.index % kPageSize] = pos;
}

void SparseSet::copy_entities_from(const SparseSet& other) {
  pages_.clear();
  pages_.reserve(other.pages_.size());
  for (const auto& page : other.pages_) {
    if (!page) {
      pages_.emplace_back();
      continue;
    }
    auto copied = std::make_unique<std::uint32_t[]>(kPageSize);
    std::copy(page.get(), page.get() + kPageSize, copied.get());
    pages_.push_back(std::move(copied));
  }
  dense_ = other.dense_;
}

}  // namespace tutti::ecs
