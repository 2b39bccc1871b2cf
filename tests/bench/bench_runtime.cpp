// The runtime's costs: open + validate throughput beside memcpy of the same bytes, and Box2D
// fixture creation through the adapter against b2PolygonShape::Set with the same points (issue 6
// target: adapter overhead <= 10%).
// The bundle is HULLCOOK_BENCH_BUNDLE when set (e.g. the cooked samples), else a synthetic one
// of 400 sprites with 12 hulls of 3 to 8 vertices each. Open and memcpy also run on a synthetic
// 100 MB bundle (issue 21 target: open >= 2 GB/s there); their bytes_per_second compare directly.
#include "synthetic_assets.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/format/crc32.h"
#include "hullcook/runtime.h"
#ifdef HULLCOOK_BENCH_BOX2D
#include "hullcook/box2d.h"
#endif

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

namespace {

using namespace hullcook;

// asset_count sprites of 4 x 4 units at 32 px per unit, each with levels of hull_counts[l] hulls
// of 3 to 8 vertices.
std::string synthetic_bundle(int asset_count, const std::vector<int>& hull_counts) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<CookedAsset> assets;
  for (int a = 0; a < asset_count; ++a) {
    std::vector<CookedLevel> levels;
    for (std::size_t l = 0; l < hull_counts.size(); ++l) {
      std::vector<Ring> hulls;
      for (int h = 0; h < hull_counts[l]; ++h)
        hulls.push_back(test::regular_polygon({4 * unit(random), 4 * unit(random)},
                                              0.2 + unit(random), 3 + h % 6, unit(random)));
      levels.push_back({(1.0 + 3.0 * l) / 32, std::move(hulls)});
    }
    assets.push_back(test::make_asset("sprites/s" + std::to_string(a) + ".png", std::move(levels),
                                      32.0, 128, 128));
  }
  return write_bundle(assets);
}

const std::string& bundle_bytes() {
  static const std::string bytes = [] {
    if (const char* path = std::getenv("HULLCOOK_BENCH_BUNDLE")) {
      std::ifstream in(path, std::ios::binary);
      std::ostringstream out;
      out << in.rdbuf();
      return out.str();
    }
    return synthetic_bundle(400, {12});
  }();
  return bytes;
}

// 100 MB of sprites shaped like the cooked samples (tests/formats/golden/v1.0/sprites.hcb: 3 KB,
// 2 levels, 88 hulls and 5.2 vertices per hull per asset), so that names, records and vertices
// weigh in validation as they do in real bundles.
const std::string& large_bundle_bytes() {
  static const std::string bytes = synthetic_bundle(34'000, {60, 28});
  return bytes;
}

void open_and_validate(benchmark::State& state, const std::string& bytes) {
  for (auto _ : state) {
    runtime::Bundle bundle;
    const runtime::Status status = bundle.open(bytes.data(), bytes.size());
    if (status != runtime::Status::ok) state.SkipWithError(runtime::status_string(status));
    benchmark::DoNotOptimize(bundle);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
  state.counters["bytes"] = static_cast<double>(bytes.size());
}

// The floor for any pass over the bytes: copying them once (the destination is written once
// beforehand, so that page faults are not timed).
void copy_bytes(benchmark::State& state, const std::string& bytes) {
  std::vector<char> copy(bytes.size(), 1);
  for (auto _ : state) {
    std::memcpy(copy.data(), bytes.data(), bytes.size());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
  state.counters["bytes"] = static_cast<double>(bytes.size());
}

void BM_OpenAndValidate100MB(benchmark::State& state) {
  open_and_validate(state, large_bundle_bytes());
}
BENCHMARK(BM_OpenAndValidate100MB)->Unit(benchmark::kMillisecond);

// The checksum alone, the part of open() that reads every byte.
void BM_Crc32_100MB(benchmark::State& state) {
  const std::string& bytes = large_bundle_bytes();
  for (auto _ : state) benchmark::DoNotOptimize(format::crc32(0, bytes.data(), bytes.size()));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_Crc32_100MB)->Unit(benchmark::kMillisecond);

// The portable method (slicing-by-16, three streams), which other CPUs and compilers get.
void BM_Crc32Portable_100MB(benchmark::State& state) {
  const std::string& bytes = large_bundle_bytes();
  for (auto _ : state)
    benchmark::DoNotOptimize(format::crc32_portable(0, bytes.data(), bytes.size()));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_Crc32Portable_100MB)->Unit(benchmark::kMillisecond);

void BM_Memcpy100MB(benchmark::State& state) { copy_bytes(state, large_bundle_bytes()); }
BENCHMARK(BM_Memcpy100MB)->Unit(benchmark::kMillisecond);

void BM_OpenAndValidate(benchmark::State& state) { open_and_validate(state, bundle_bytes()); }
BENCHMARK(BM_OpenAndValidate);

void BM_Memcpy(benchmark::State& state) { copy_bytes(state, bundle_bytes()); }
BENCHMARK(BM_Memcpy);

void BM_FindEveryAsset(benchmark::State& state) {
  const std::string& bytes = bundle_bytes();
  runtime::Bundle bundle;
  if (bundle.open(bytes.data(), bytes.size()) != runtime::Status::ok) return;
  std::vector<std::string> names;
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) names.emplace_back(bundle.asset(a).name());
  for (auto _ : state)
    for (const std::string& name : names) benchmark::DoNotOptimize(bundle.find(name));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * names.size()));
}
BENCHMARK(BM_FindEveryAsset);

#ifdef HULLCOOK_BENCH_BOX2D
// Every asset's finest level as fixtures on a body of its own (bodies destroyed untimed).
void BM_FixturesThroughAdapter(benchmark::State& state) {
  const std::string& bytes = bundle_bytes();
  runtime::Bundle bundle;
  if (bundle.open(bytes.data(), bytes.size()) != runtime::Status::ok) return;
  b2World world(b2Vec2(0, -10));
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  b2FixtureDef fixture;
  fixture.density = 1.0f;
  std::size_t hulls = 0;
  std::vector<b2Body*> bodies(bundle.asset_count());
  for (auto _ : state) {
    for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
      bodies[a] = world.CreateBody(&definition);
      const runtime::Asset asset = bundle.asset(a);
      hulls += box2d::create_fixtures(bodies[a], asset, asset.level(0), fixture).created;
    }
    state.PauseTiming();
    for (b2Body* body : bodies) world.DestroyBody(body);
    // Without a step Box2D never empties its broad-phase move buffer, and destroying proxies
    // scans it: an empty step keeps every iteration alike.
    world.Step(1.0f / 60.0f, 1, 1);
    state.ResumeTiming();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(hulls));
}
BENCHMARK(BM_FixturesThroughAdapter)->Unit(benchmark::kMicrosecond);

void BM_FixturesWithSetDirectly(benchmark::State& state) {
  const std::string& bytes = bundle_bytes();
  runtime::Bundle bundle;
  if (bundle.open(bytes.data(), bytes.size()) != runtime::Status::ok) return;
  // The same points, extracted beforehand, as a game with its own format would hold them.
  std::vector<std::vector<std::vector<b2Vec2>>> assets(bundle.asset_count());
  for (std::size_t a = 0; a < bundle.asset_count(); ++a) {
    std::vector<std::vector<b2Vec2>>& polygons = assets[a];
    const runtime::Level level = bundle.asset(a).level(0);
    for (std::size_t h = 0; h < level.hull_count(); ++h) {
      std::vector<b2Vec2> points;
      for (std::size_t v = 0; v < level.hull(h).vertex_count() && v < b2_maxPolygonVertices; ++v)
        points.emplace_back(level.hull(h).vertex(v).x, level.hull(h).vertex(v).y);
      polygons.push_back(std::move(points));
    }
  }
  b2World world(b2Vec2(0, -10));
  b2BodyDef definition;
  definition.type = b2_dynamicBody;
  b2FixtureDef fixture;
  fixture.density = 1.0f;
  b2PolygonShape shape;
  fixture.shape = &shape;
  std::size_t hulls = 0;
  std::vector<b2Body*> bodies(assets.size());
  for (auto _ : state) {
    for (std::size_t a = 0; a < assets.size(); ++a) {
      bodies[a] = world.CreateBody(&definition);
      for (const auto& points : assets[a]) {
        shape.Set(points.data(), static_cast<int32>(points.size()));
        bodies[a]->CreateFixture(&fixture);
        ++hulls;
      }
    }
    state.PauseTiming();
    for (b2Body* body : bodies) world.DestroyBody(body);
    // Without a step Box2D never empties its broad-phase move buffer, and destroying proxies
    // scans it: an empty step keeps every iteration alike.
    world.Step(1.0f / 60.0f, 1, 1);
    state.ResumeTiming();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(hulls));
}
BENCHMARK(BM_FixturesWithSetDirectly)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace

BENCHMARK_MAIN();
