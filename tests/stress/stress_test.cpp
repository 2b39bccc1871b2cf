// Issue 16's stress tests in CI: a fixed set of seeds of every polygon family decomposed under
// SL, SP, H1 and H2 at tau 0, 0.5, 1 and 4 and cooked (engine limits included) at tau 0.5, 1
// and 4; drawn sprites and the sample sprites cooked at tau 1
// and 4 px (1 px per unit) and at tau 1 px with 100 px per unit; every output judged by the
// independent checker. A failure names the seed, family, measure and tau, and where the input
// was saved for replay with `hullcook decompose` or `hullcook cook`.
//
// Case counts: kSeedsPerFamily polygons per family and kImagesPerFamily images per image family
// in a Release build; under AddressSanitizer (detected at compile time) a quarter of them, which
// keeps the sanitizer run within its time. HULLCOOK_STRESS_SEEDS=N in the environment sets the
// count of both for a run (scripts/stress runs thousands with the hullcook_stress driver).
#include "stress_runner.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/poly_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
#define HULLCOOK_STRESS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HULLCOOK_STRESS_SANITIZED 1
#endif
#endif

namespace hullcook::stress {

// Test names and failures print the parameters by name.
void PrintTo(Family family, std::ostream* out) { *out << family_name(family); }
void PrintTo(ImageFamily family, std::ostream* out) { *out << image_family_name(family); }
void PrintTo(const CookCase& cook, std::ostream* out) {
  *out << "tau " << cook.tau_px << ", ppu " << cook.pixels_per_unit << ", "
       << measure_name(cook.measure);
}

namespace {

#ifdef HULLCOOK_STRESS_SANITIZED
constexpr int kSeedsPerFamily = 3;
constexpr int kImagesPerFamily = 2;
#else
constexpr int kSeedsPerFamily = 12;
constexpr int kImagesPerFamily = 8;
#endif

// Failure messages printed per test; the rest are counted.
constexpr int kMessagesShown = 8;

int cases(int default_count) {
  const char* text = std::getenv("HULLCOOK_STRESS_SEEDS");
  if (text == nullptr || *text == '\0') return default_count;
  return std::max(0, std::atoi(text));
}

const std::filesystem::path kFailures =
    std::filesystem::path(HULLCOOK_BINARY_DIR) / "stress-failures";

constexpr Measure kMeasures[] = {Measure::sl, Measure::sp, Measure::h1, Measure::h2};
constexpr double kTaus[] = {0.0, 0.5, 1.0, 4.0};
const std::vector<CookCase> kCooks = image_cooks({Measure::h1});
// Polygons are also cooked (engine limits included, see polygon_cook) at these tolerances, one
// measure per seed.
constexpr double kCookTaus[] = {0.0, 0.5, 1.0, 4.0};
constexpr Measure kCookMeasures[] = {Measure::h1, Measure::sl, Measure::sp};

// Reports a failed outcome (the first few in full) and counts it.
class FailureLog {
 public:
  void add(const CaseOutcome& outcome) {
    ++runs_;
    if (outcome.ok()) return;
    if (failures_++ < kMessagesShown) ADD_FAILURE() << outcome.message();
  }
  ~FailureLog() {
    if (failures_ > kMessagesShown) {
      ADD_FAILURE() << failures_ << " of " << runs_ << " runs failed (the first " << kMessagesShown
                    << " are shown above)";
    }
  }

 private:
  int runs_ = 0, failures_ = 0;
};

// The two reproductions of issue 16, as given: a square with four diamond holes, and a 64x16 UI
// button whose two holes nearly fill it (each decomposed whole, holes and all).
constexpr const char* kIssueCases[][2] = {{"issue16-four-diamonds", R"(5
4 out
0 0
25 0
25 25
0 25
1 2 3 4
4 in
7 12
12 7
7 2
2 7
1 2 3 4
4 in
7 23
12 18
7 13
2 18
1 2 3 4
4 in
18 12
23 7
18 2
13 7
1 2 3 4
4 in
18 23
23 18
18 13
13 18
1 2 3 4
)"},
                                          {"issue16-button", R"(3
4 out
1.4 -6.6
30.6 -6.6
30.6 6.6
1.4 6.6
1 2 3 4
12 in
13.5 6.3
13.8 2.5
13.5 2.2
9.8 -1.5
10.5 -2.2
13.5 -2.2
13.8 -2.5
13.5 -6.3
2.5 -6.3
1.7 -5.5
1.7 5.5
2.5 6.3
1 2 3 4 5 6 7 8 9 10 11 12
12 in
29.5 6.3
30.3 5.5
30.3 -5.5
29.5 -6.3
18.5 -6.3
18.2 -2.5
18.5 -2.2
21.5 -2.2
21.5 2.2
18.5 2.2
18.2 2.5
18.2 5.5
1 2 3 4 5 6 7 8 9 10 11 12
)"}};

TEST(IssueReproductions, EveryDecompositionPassesTheIndependentCheck) {
  FailureLog log;
  for (const auto& [name, text] : kIssueCases) {
    const std::vector<Region> regions = clean_and_validate(parse_poly(text, name), name);
    for (Measure measure : kMeasures) {
      for (double tau : kTaus) {
        log.add(run_polygon_case(name, regions, "from the issue", measure, tau, kFailures));
      }
    }
  }
}

class PolygonFamily : public ::testing::TestWithParam<Family> {};

TEST_P(PolygonFamily, EveryDecompositionAndCookPassesTheIndependentCheck) {
  FailureLog log;
  int rejected = 0;
  const int count = cases(kSeedsPerFamily);
  for (int seed = 1; seed <= count; ++seed) {
    const GeneratedCase generated = generate_case(GetParam(), seed);
    if (!generated.rejection.empty()) {
      ++rejected;
      continue;
    }
    for (Measure measure : kMeasures) {
      for (double tau : kTaus) log.add(run_polygon_case(generated, measure, tau, kFailures));
    }
    for (double tau : kCookTaus) {
      if (!cooks_polygon_at(GetParam(), tau)) continue;
      const CookCase cook = polygon_cook(tau, kCookMeasures[seed % std::size(kCookMeasures)]);
      log.add(run_polygon_cook_case(generated, cook, kFailures));
    }
  }
  EXPECT_LE(rejected, count / 10) << "the generator's cases are mostly not valid input";
}

INSTANTIATE_TEST_SUITE_P(Stress, PolygonFamily, ::testing::ValuesIn(all_families()),
                         [](const auto& info) { return std::string(family_name(info.param)); });

class ImageFamilies : public ::testing::TestWithParam<ImageFamily> {};

TEST_P(ImageFamilies, EveryCookedImagePassesTheIndependentCheck) {
  FailureLog log;
  const int count = static_cast<int>(
      images_to_draw(GetParam(), static_cast<std::size_t>(cases(kImagesPerFamily))));
  for (int seed = 1; seed <= count; ++seed) {
    const DrawnImage image = draw_image(GetParam(), seed);
    for (const CookCase& cook : image_cooks({Measure::h1}, GetParam())) {
      log.add(run_image_case(image, cook, kFailures));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Stress, ImageFamilies, ::testing::ValuesIn(all_image_families()),
                         [](const auto& info) {
                           return std::string(image_family_name(info.param));
                         });

// scripts/stress 1500 --seed 9001: a strip of a one-pixel diagonal wall at 100 px per unit,
// halved below the weld, got the smallest engine-ready triangle, which reaches 17 px along the
// wall over its neighbours (within tau of the outline, as the cook's contract allows; the checker
// had held cooked hulls to their own component).
TEST(Issue16Regressions, AWeldGrownHullMayReachOverItsNeighbours) {
  FailureLog log;
  const DrawnImage image = draw_image(ImageFamily::one_pixel_walls, 9074);
  log.add(run_image_case(image, image_cook(1.0, 100.0), kFailures));
}

// hullcook_stress --family soft_edges (seed 1, 200 images): 11 soft sprites cooked at tau 0.25 px,
// alpha 1, simplify 0 left hulls 0.0006 px thin along the image's border, which the .hcb writer
// refused; such hulls are now merged into neighbours (and rounded outward on the grid).
TEST(SoftEdgeRegressions, HullsAlongASoftBorderFitTheBundlesGrid) {
  FailureLog log;
  const DrawnImage image = draw_image(ImageFamily::soft_edges, 8);
  for (const CookCase& cook : image_cooks({Measure::h1}, ImageFamily::soft_edges)) {
    log.add(run_image_case(image, cook, kFailures));
  }
}

// scripts/stress 1200 --seed 20261207, the first run that cooked polygons at tau 0 (weld 0):
// convex pieces of a thin wall and of grids that the engine limits halved from vertex 0 into a
// sliver (area 1.3e-15 over a length of 6.2), an internal error. Halving now avoids slivers.
TEST(TauZeroRegressions, ConvexPiecesAreHalvedWithoutSlivers) {
  FailureLog log;
  for (const auto& [family, seed] : {std::pair{Family::thin_wall, 20261367},
                                     {Family::grid, 20261252},
                                     {Family::grid, 20261318}}) {
    const GeneratedCase generated = generate_case(family, std::uint64_t(seed));
    ASSERT_TRUE(generated.rejection.empty()) << generated.rejection;
    for (Measure measure : {Measure::sl, Measure::h1}) {
      log.add(run_polygon_cook_case(generated, polygon_cook(0.0, measure), kFailures));
    }
  }
}

class SampleSprites : public ::testing::TestWithParam<CookCase> {};

TEST_P(SampleSprites, EveryCookedSpritePassesTheIndependentCheck) {
  const std::filesystem::path sprites =
      std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(sprites)) {
    if (entry.path().extension() == ".png") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
#ifdef HULLCOOK_STRESS_SANITIZED
  files.resize(std::min<std::size_t>(files.size(), 8));
#endif
  FailureLog log;
  for (const std::filesystem::path& file : files) log.add(run_sprite_case(file, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Stress, SampleSprites, ::testing::ValuesIn(kCooks), [](const auto& info) {
  return "tau" + std::to_string(static_cast<int>(info.param.tau_px)) + "_ppu" +
         std::to_string(static_cast<int>(info.param.pixels_per_unit));
});

}  // namespace
}  // namespace hullcook::stress
