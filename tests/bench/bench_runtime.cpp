// The runtime's costs: open + validate throughput, and Box2D fixture creation through the adapter
// against b2PolygonShape::Set with the same points (issue 6 target: adapter overhead <= 10%).
// The bundle is HULLCOOK_BENCH_BUNDLE when set (e.g. the cooked samples), else a synthetic one
// of 400 sprites with 12 hulls of 3 to 8 vertices each.
#include "synthetic_assets.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/runtime.h"
#ifdef HULLCOOK_BENCH_BOX2D
#include "hullcook/box2d.h"
#endif

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

namespace {

using namespace hullcook;

std::string synthetic_bundle() {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<CookedAsset> assets;
  for (int a = 0; a < 400; ++a) {
    std::vector<Ring> hulls;
    for (int h = 0; h < 12; ++h)
      hulls.push_back(test::regular_polygon({4 * unit(random), 4 * unit(random)},
                                            0.2 + unit(random), 3 + h % 6, unit(random)));
    assets.push_back(test::make_asset("sprites/s" + std::to_string(a) + ".png", {{1.0 / 32, hulls}},
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
    return synthetic_bundle();
  }();
  return bytes;
}

void BM_OpenAndValidate(benchmark::State& state) {
  const std::string& bytes = bundle_bytes();
  for (auto _ : state) {
    runtime::Bundle bundle;
    const runtime::Status status = bundle.open(bytes.data(), bytes.size());
    if (status != runtime::Status::ok) state.SkipWithError(runtime::status_string(status));
    benchmark::DoNotOptimize(bundle);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
  state.counters["bytes"] = static_cast<double>(bytes.size());
}
BENCHMARK(BM_OpenAndValidate);

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
