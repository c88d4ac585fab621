// SPDX-License-Identifier: MIT
// View iteration and entity creation at orchestra-plus scale (1,000,000 entities). Items are
// entities visited (views) or created (creation).

#include <benchmark/benchmark.h>

#include <cstddef>
#include <memory>

#include <tutti/ecs/world.hpp>

namespace {

using tutti::ecs::Entity;
using tutti::ecs::World;

constexpr int kEntities = 1'000'000;

struct Position {
  float x = 0.0F;
  float y = 0.0F;
  float z = 0.0F;
};
struct Velocity {
  float dx = 0.0F;
  float dy = 0.0F;
  float dz = 0.0F;
};
struct Mass {
  float kg = 1.0F;
};

// Every entity has Position and Velocity; every tenth also has Mass.
std::unique_ptr<World> make_world() {
  auto world = std::make_unique<World>();
  for (int i = 0; i < kEntities; ++i) {
    const Entity e = world->create();
    const auto f = static_cast<float>(i);
    world->add<Position>(e, f, f, f);
    world->add<Velocity>(e, 1.0F, 2.0F, 3.0F);
    if (i % 10 == 0) world->add<Mass>(e, 2.0F);
  }
  return world;
}

void BM_View1(benchmark::State& state) {
  const auto world = make_world();
  for (auto _ : state) {
    world->view<Position>().each([](Position& p) { p.x += 1.0F; });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kEntities);
}
BENCHMARK(BM_View1)->Unit(benchmark::kMillisecond);

void BM_View2(benchmark::State& state) {
  const auto world = make_world();
  for (auto _ : state) {
    world->view<Position, const Velocity>().each([](Position& p, const Velocity& v) {
      p.x += v.dx;
      p.y += v.dy;
      p.z += v.dz;
    });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kEntities);
}
BENCHMARK(BM_View2)->Unit(benchmark::kMillisecond);

void BM_View2WithEntity(benchmark::State& state) {
  const auto world = make_world();
  for (auto _ : state) {
    std::size_t sum = 0;
    world->view<Position, Velocity>().each([&](Entity e, Position& p, Velocity& v) {
      sum += e.index;
      p.x += v.dx;
    });
    benchmark::DoNotOptimize(sum);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kEntities);
}
BENCHMARK(BM_View2WithEntity)->Unit(benchmark::kMillisecond);

// The Mass pool (10%) drives; items are the 100,000 matching entities.
void BM_View3Sparse(benchmark::State& state) {
  const auto world = make_world();
  for (auto _ : state) {
    world->view<Position, Velocity, const Mass>().each([](Position& p, Velocity& v, const Mass& m) {
      v.dx += 0.5F / m.kg;
      p.x += v.dx;
    });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * (kEntities / 10));
}
BENCHMARK(BM_View3Sparse)->Unit(benchmark::kMillisecond);

void BM_RangeFor2(benchmark::State& state) {
  const auto world = make_world();
  for (auto _ : state) {
    float sum = 0.0F;
    for (const Entity e : world->view<Position, Velocity>()) sum += world->get<Velocity>(e).dx;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kEntities);
}
BENCHMARK(BM_RangeFor2)->Unit(benchmark::kMillisecond);

void BM_Create2Components(benchmark::State& state) {
  for (auto _ : state) {
    auto world = std::make_unique<World>();
    for (int i = 0; i < kEntities; ++i) {
      const Entity e = world->create();
      world->add<Position>(e, 1.0F, 2.0F, 3.0F);
      world->add<Velocity>(e, 1.0F, 2.0F, 3.0F);
    }
    benchmark::DoNotOptimize(world->size<Velocity>());
    benchmark::ClobberMemory();
    state.PauseTiming();  // tearing the world down is not creation
    world.reset();
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * kEntities);
}
BENCHMARK(BM_Create2Components)->Unit(benchmark::kMillisecond);

}  // namespace
