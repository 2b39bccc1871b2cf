// Bundle::open(), find() and every accessor must not touch the heap: this binary replaces the
// global operator new and counts the calls made while the runtime works.
#include "synthetic_assets.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/runtime.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (counting.load()) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return ::operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace hullcook {
namespace {

TEST(RuntimeAllocation, OpenLookupAndAccessAllocateNothing) {
  const std::vector<CookedAsset> assets = test::synthetic_assets();
  const std::string bytes = write_bundle(assets);
  std::vector<std::string> names;
  for (const CookedAsset& asset : assets) names.push_back(asset.name);

  // The counter must see allocations at all, or the test could not fail.
  counting = true;
  // (A direct call: new-expressions may be elided by the optimiser.)
  ::operator delete(::operator new(16));
  counting = false;
  ASSERT_EQ(allocations.load(), 1);
  allocations = 0;

  counting = true;
  runtime::Bundle bundle;
  const runtime::Status status = bundle.open(bytes.data(), bytes.size());
  std::size_t found = 0, vertices = 0;
  runtime::Vec2 points[runtime::kMaxStackVertices];
  for (const std::string& name : names) {
    const runtime::Asset asset = bundle.find(name);
    found += asset.valid();
    const runtime::Level level = asset.select_level(0.5f);
    for (std::size_t h = 0; h < level.hull_count(); ++h)
      vertices += level.hull(h).copy_vertices(points, std::size(points), {2.0f, true});
  }
  found += bundle.find("not there").valid();
  const double sum = test::touch_everything(bundle);
  counting = false;

  EXPECT_EQ(status, runtime::Status::ok);
  EXPECT_EQ(found, names.size());
  EXPECT_GT(vertices, 0u);
  EXPECT_NE(sum, 0.0);
  EXPECT_EQ(allocations.load(), 0) << "the runtime allocated while opening or reading";
}

}  // namespace
}  // namespace hullcook
