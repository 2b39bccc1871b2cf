// HullFitter: fitting, reducing to max_verts edge lines, mending weld and collinearity violations.
#include "hull_fitter.h"
#include "contract.h"
#include "engine_limits_fixtures.h"
#include "mend_queue.h"
#include "outline_distance.h"
#include "piece_merge.h"

#include "hullcook/cook/constrain.h"
#include "hullcook/cook/cook.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace hullcook {
namespace {

using test::area_of;
using test::convex_piece;
using test::convex_piece_of;
using test::decompose_at;
using test::expect_within;
using test::FitterInputs;
using test::no_split;
using test::regular_polygon;
using test::ring_area;
using test::rough_disc;

TEST(EngineLimits, Issue17_ApexShortcutGivesTheSameFitAsTheOutlineQuery) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> wobble(-1.0, 1.0);
  int reduced = 0, compared = 0;
  std::uint64_t queries_with_shortcut = 0, queries_without = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Ring star;
    const int n = 40 + trial * 3;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * i / n;
      const double radius = 50 + 12 * wobble(random) + 20 * std::sin(3 * angle);
      star.push_back(radius * Vec2{std::cos(angle), std::sin(angle)});
    }
    // τ down to 2e-7 of the star's size, where the shortcut's margins matter.
    for (double tau : {1e-5, 0.5, 2.0, 6.0}) {
      for (std::size_t max_verts : {8u, 6u, 4u}) {
        const EngineLimits limits{max_verts, 0.005};
        for (const CookedPiece& piece : decompose_at(Region{star, {}}, tau)) {
          if (piece.hull.size() <= max_verts) continue;
          const FitterInputs inputs(piece, tau);
          const OutlineDistance& reach = inputs.reach;
          HullFitter with_shortcut = inputs.fitter(limits, HullFitter::Reach::component);
          HullFitter query_only = inputs.fitter(limits, HullFitter::Reach::outline);
          std::uint64_t before = reach.distance_queries();
          const std::optional<Ring> fast = with_shortcut.fit(piece.hull);
          queries_with_shortcut += reach.distance_queries() - before;
          before = reach.distance_queries();
          const std::optional<Ring> slow = query_only.fit(piece.hull);
          queries_without += reach.distance_queries() - before;
          ++compared;
          ASSERT_EQ(fast.has_value(), slow.has_value()) << "trial " << trial << ", tau " << tau;
          if (fast) {
            ++reduced;
            EXPECT_EQ(*fast, *slow) << "trial " << trial << ", tau " << tau;
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 100);
  EXPECT_GT(reduced, 100);
  // The shortcut is taken: the same fits, with fewer outline queries.
  EXPECT_LT(queries_with_shortcut * 5, queries_without * 4)
      << queries_with_shortcut << " queries with the shortcut, " << queries_without << " without";
}

// Stop 51: a cap of a rough disc of 10,000 vertices (2,500 of them, 250 hull lines) took 100 ms
// to fit, nearly all of it in the scans of every start's lines, about 30 each; slicing fits
// about 20 caps per slice. A line's scan now starts where the nearest scan before it reached
// (a line moved towards another meets it nearer), and the polygon kept has its apexes checked.
// Fitting with inferred reaches must give the hulls the exact scans give, on caps of rough discs,
// stars whose pockets break the argument and crowns, whole and in pieces,
// with and without a weld, testing fewer apexes; and a cap of a 4,000-gon without a weld (a
// 5,000-gon at --tau 1% --weld 0 took 153 s).
TEST(EngineLimits, InferredReachesGiveTheHullsOfTheExactScans) {
  std::mt19937 random(51);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ring> shapes;
  for (unsigned seed = 1; seed <= 4; ++seed) {  // caps of rough discs, as slicing cuts them
    const Ring disc = rough_disc(1000 * seed, 250.0 * seed, 0.3, seed);
    for (std::size_t parts : {12, 8, 5, 3}) {
      // Closed through a point well inside: a chord between rough ends may cross the rim.
      Ring cap(disc.begin(), disc.begin() + std::ptrdiff_t(disc.size() / parts));
      cap.push_back(0.25 * (cap.front() + cap.back()));
      shapes.push_back(cap);
    }
  }
  for (int trial = 0; trial < 6; ++trial) {  // stars with deep pockets
    Ring star;
    const int n = 60 + 40 * trial;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * i / n;
      const double radius = 50 + 20 * unit(random) + 15 * std::sin(5 * angle);
      star.push_back(radius * Vec2{std::cos(angle), std::sin(angle)});
    }
    shapes.push_back(star);
  }
  for (int tips : {40, 90}) {  // crowns
    Ring crown;
    for (int i = 0; i < 2 * tips; ++i) {
      const double angle = M_PI * i / tips;
      crown.push_back((i % 2 == 0 ? 50.0 : 47.0) * Vec2{std::cos(angle), std::sin(angle)});
    }
    shapes.push_back(crown);
  }
  int compared = 0, reduced = 0;
  // The apexes tested for the caps, whose hulls' lines each reach tens on.
  std::uint64_t tests_inferred = 0, tests_exact = 0;
  for (const Ring& shape : shapes) {
    const bool is_cap = &shape < &shapes[16];
    for (double tau : {0.5, 2.0, 5.0}) {
      std::vector<CookedPiece> pieces = decompose_at(Region{shape, {}}, tau);
      pieces.push_back(convex_piece_of(shape));
      for (const CookedPiece& piece : pieces) {
        const FitterInputs inputs(piece, tau);
        for (std::size_t max_verts : {4u, 6u, 8u}) {
          if (piece.hull.size() <= max_verts) continue;
          for (double weld : {0.005, 0.0}) {
            const EngineLimits limits{max_verts, weld};
            HullFitter inferring = inputs.fitter(limits), exact = inputs.fitter(limits);
            exact.infer_reaches(false);
            const std::optional<Ring> fast = inferring.fit(piece.hull);
            const std::optional<Ring> slow = exact.fit(piece.hull);
            if (is_cap) {
              tests_inferred += inferring.apex_tests();
              tests_exact += exact.apex_tests();
            }
            ++compared;
            ASSERT_EQ(fast.has_value(), slow.has_value())
                << "shape of " << shape.size() << ", tau " << tau << ", max_verts " << max_verts;
            if (!fast) continue;
            ++reduced;
            EXPECT_EQ(*fast, *slow)
                << "shape of " << shape.size() << ", tau " << tau << ", max_verts " << max_verts;
          }
        }
      }
    }
  }
  // A cap of a 4,000-gon: turns below a millionth of its size, where without a weld every start
  // is scanned (see may_close_within_max_verts) and rounding could break the argument.
  const Ring fine_circle = regular_polygon(4000, 100);
  Ring cap(fine_circle.begin(), fine_circle.begin() + 400);
  cap.push_back(0.25 * (cap.front() + cap.back()));
  const CookedPiece fine_cap = convex_piece_of(cap);
  const FitterInputs inputs(fine_cap, 2.0);
  HullFitter inferring = inputs.fitter({8, 0.0}), exact = inputs.fitter({8, 0.0});
  exact.infer_reaches(false);
  const std::optional<Ring> fast = inferring.fit(fine_cap.hull);
  ASSERT_TRUE(fast.has_value());
  EXPECT_EQ(*fast, exact.fit(fine_cap.hull));
  EXPECT_LT(inferring.apex_tests() * 4, exact.apex_tests())
      << inferring.apex_tests() << " apexes tested inferring, " << exact.apex_tests() << " exact";
  EXPECT_GT(compared, 300);
  EXPECT_GT(reduced, 150);
  EXPECT_LT(tests_inferred * 4, tests_exact * 3)
      << tests_inferred << " apexes tested inferring, " << tests_exact << " exact";
}

// Issue 17's robustness hunt: a 2000-vertex circle (.poly) at the default --max-verts 8 took 17 s
// and an m x m table of apexes (64 MB), every halving level trying every start; no start can close
// when the greedy chain from one start needs two lines more than max_verts.
TEST(EngineLimits, Issue17_HullThatNoEightLinesCloseIsRefusedAfterOneGreedyChain) {
  const Ring circle = regular_polygon(1500, 100);
  const CookedPiece piece = convex_piece(circle);
  const EngineLimits limits{8, 0.005};
  // Eight lines round a radius-100 circle reach 100 / cos(22.5°) - 100 ≈ 8.2 out: beyond τ 2.
  const double tau = 2;
  const FitterInputs inputs(piece, tau);
  const OutlineDistance& reach = inputs.reach;
  HullFitter fitter = inputs.fitter(limits);
  const std::uint64_t before = reach.distance_queries();
  EXPECT_FALSE(fitter.fit(piece.hull).has_value());
  // One query per corner, then one per line scanned by the ten lines of one greedy chain (about
  // 95 lines each): every start's chain was 1500 x 95.
  EXPECT_LT(reach.distance_queries() - before, 3000u);
  // Halved until each part fits: the contract holds.
  const auto pieces = apply_engine_limits({piece}, tau, limits, no_split, "test");
  EXPECT_GT(pieces.size(), 1u);
  EXPECT_NEAR(area_of(pieces), ring_area(circle), 1e-6 * ring_area(circle));
  expect_within(pieces, tau, limits);
}

// Issue 17's robustness hunt: a square of 4000 vertices bulging out by 1e-6 (nearly collinear
// on its sides) took minutes to cook, every removal of a hull edge checked against every vertex
// and edge. The mending checks only what a removal changes; it must decide as the whole-hull
// checks do, on hulls of nearly collinear vertices, jittered circles and pieces of stars. Mending
// with a MendQueue (from 64 vertices by default) must give what a full scan after each removal
// gives, whatever the hull's size (stop 47's review).
TEST(EngineLimits, Issue17_MendingChecksWhatARemovalChangesAsTheWholeHullChecksDo) {
  std::mt19937 random(1704);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ring> shapes;
  for (int sides : {30, 80}) {  // squares with sides of that many nearly collinear vertices
    Ring square;
    const Vec2 corners[4] = {{0, 0}, {100, 0}, {100, 100}, {0, 100}};
    for (int c = 0; c < 4; ++c) {
      const Vec2 from = corners[c], to = corners[(c + 1) % 4];
      const Vec2 outward = Vec2{to.y - from.y, from.x - to.x} / 100.0;
      for (int i = 0; i < sides; ++i) {
        const double t = static_cast<double>(i) / sides;
        square.push_back(from + (to - from) * t + outward * (1e-6 * std::sin(M_PI * t)));
      }
    }
    shapes.push_back(square);
  }
  for (int trial = 0; trial < 6; ++trial) {  // circles, their radii jittered
    const int n = 60 + 50 * trial;
    const double jitter = trial % 2 == 0 ? 1e-9 : 1e-3;
    Ring circle;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * i / n;
      circle.push_back((50 + jitter * (unit(random) - 0.5)) *
                       Vec2{std::cos(angle), std::sin(angle)});
    }
    shapes.push_back(circle);
  }
  for (int tips : {60, 100}) {  // crowns: tips closer than the weld over notches deeper than τ
    Ring crown;
    for (int i = 0; i < 2 * tips; ++i) {
      const double angle = M_PI * i / tips;
      crown.push_back((i % 2 == 0 ? 5.0 : 4.0) * Vec2{std::cos(angle), std::sin(angle)});
    }
    shapes.push_back(crown);
  }
  for (int trial = 0; trial < 4; ++trial) {  // stars
    Ring star;
    const int n = 80 + 40 * trial;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * i / n;
      star.push_back((40 + 15 * unit(random)) * Vec2{std::cos(angle), std::sin(angle)});
    }
    shapes.push_back(star);
  }
  int compared = 0, changed = 0, refused = 0, local = 0, large = 0;
  for (const Ring& shape : shapes) {
    for (double tau : {0.5, 2.0}) {
      // Its pieces at τ, and the whole shape as one piece (its pockets deeper than τ allowed).
      std::vector<CookedPiece> pieces = decompose_at(Region{shape, {}}, tau);
      pieces.push_back(convex_piece_of(shape));
      for (const CookedPiece& piece : pieces) {
        const FitterInputs inputs(piece, tau);
        for (double weld : {0.005, 0.05, 0.4}) {
          // Every weld and collinearity violation mended, whatever the vertex count.
          const EngineLimits limits{0, weld};
          HullFitter by_removal = inputs.fitter(limits);
          HullFitter whole = inputs.fitter(limits);
          whole.check_whole_hull_when_mending(true);
          // The checks by removal are taken when every vertex passes in the hull given.
          local += by_removal.holds_component(piece.hull);
          const std::optional<Ring> by_change = by_removal.mend_local_violations(piece.hull);
          const std::optional<Ring> by_whole = whole.mend_local_violations(piece.hull);
          // The queue (issue 17) against a full scan after each removal, on every hull.
          HullFitter queued = inputs.fitter(limits), scanned = inputs.fitter(limits);
          queued.queue_mending_from(0);
          scanned.queue_mending_from(std::numeric_limits<std::size_t>::max());
          const std::optional<Ring> by_queue = queued.mend_local_violations(piece.hull);
          const std::optional<Ring> by_scan = scanned.mend_local_violations(piece.hull);
          ++compared;
          ASSERT_EQ(by_change.has_value(), by_whole.has_value())
              << "shape of " << shape.size() << ", tau " << tau << ", weld " << weld;
          ASSERT_EQ(by_queue.has_value(), by_scan.has_value())
              << "shape of " << shape.size() << ", tau " << tau << ", weld " << weld;
          ASSERT_EQ(by_queue.has_value(), by_change.has_value());
          if (!by_change) {
            ++refused;
            continue;
          }
          EXPECT_EQ(*by_change, *by_whole)
              << "shape of " << shape.size() << ", tau " << tau << ", weld " << weld;
          EXPECT_EQ(*by_queue, *by_scan)
              << "shape of " << shape.size() << ", tau " << tau << ", weld " << weld;
          EXPECT_EQ(*by_queue, *by_change);
          if (piece.hull.size() >= 64) ++large;
          if (*by_change != piece.hull) ++changed;
        }
      }
    }
  }
  EXPECT_GT(compared, 200);
  EXPECT_GT(local, compared * 9 / 10);  // the checks by removal are what is compared
  EXPECT_GT(changed, 50);               // the mending is exercised
  EXPECT_GT(refused, 10);               // and fails on some hulls (the crowns' notches)
  EXPECT_GT(large, 20);                 // hulls the default queues too
}

// Found by stop 46's adversarial polygons: a star of 10 000 spikes at unit scale took 74 s to
// cook (its decomposition 0.25 s), as mending its hull asked edges_to_mend and sorted every
// candidate again after each of thousands of removals. MendQueue keeps both up to date: after
// every removal (any candidate, not only the first) it must list what a full scan lists, in the
// same order, on hulls with clusters closer than the weld, nearly collinear runs, two sides
// closer than the weld, and on scattered rings.
TEST(EngineLimits, Issue17_MendQueueListsWhatAFullScanListsAfterEveryRemoval) {
  std::mt19937 random(4617);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t removals = 0, compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const double radius = std::pow(10.0, -3 + 6 * unit(random));
    const double weld = radius * std::pow(10.0, -3 + 2 * unit(random));
    const double bound = radius * (0.001 + 0.05 * unit(random));
    Ring hull;
    const int n = 4 + static_cast<int>(300 * unit(random));
    // Every other hull a flat ellipse, whose two sides lie closer than the weld: pairs of
    // vertices far apart along the ring.
    const double flat = trial % 2 ? 1.0 : weld / radius * unit(random);
    double angle = 0;
    for (int i = 0; i < n && angle < 2 * M_PI; ++i) {
      hull.push_back(radius * Vec2{std::cos(angle), flat * std::sin(angle)});
      // Runs of vertices closer than the weld, and wide gaps.
      angle += (unit(random) < 0.5 ? 0.5 * weld / radius : 6.0 / n) * (0.2 + unit(random));
    }
    // Every third, scattered points (any ring, reflex turns too), a third of them each closer
    // than the weld to an earlier one anywhere along the ring.
    if (trial % 3 == 2) {
      for (std::size_t i = 0; i < hull.size(); ++i) {
        hull[i] = unit(random) < 0.3 && i > 0
                      ? hull[static_cast<std::size_t>(unit(random) * static_cast<double>(i))] +
                            weld * Vec2{unit(random) - 0.5, unit(random) - 0.5}
                      : radius * Vec2{unit(random), unit(random)};
      }
    }
    const EngineLimits limits{8, trial % 7 == 6 ? 0.0 : weld};
    // Any deterministic error: the distance beyond the circle.
    auto error_of = [&](Vec2 apex) {
      return trial % 3 == 2 ? glm::length(apex) / 10 : glm::length(apex / Vec2{1.0, flat}) - radius;
    };
    MendQueue queue(limits, bound, error_of);
    ASSERT_TRUE(queue.start(hull));
    while (hull.size() >= 4) {
      const std::vector<std::size_t> edges = edges_to_mend(hull, limits);
      ASSERT_EQ(queue.wanted_count(), edges.size()) << "trial " << trial;
      struct Expected {
        double error;
        std::size_t edge;
        Vec2 apex;
      };
      std::vector<Expected> expected;
      for (const std::size_t edge : edges) {
        const std::optional<Vec2> apex = removed_edge_apex(hull, edge);
        if (apex && error_of(*apex) <= bound) expected.push_back({error_of(*apex), edge, *apex});
      }
      std::sort(expected.begin(), expected.end(), [](const Expected& a, const Expected& b) {
        return std::tie(a.error, a.edge) < std::tie(b.error, b.edge);
      });
      ASSERT_EQ(queue.candidates().size(), expected.size()) << "trial " << trial;
      std::size_t k = 0;
      for (const MendQueue::Candidate& candidate : queue.candidates()) {
        ASSERT_EQ(queue.index_of(candidate.id), expected[k].edge) << "trial " << trial;
        ASSERT_EQ(queue.apex_of(candidate.id), expected[k].apex) << "trial " << trial;
        ASSERT_EQ(candidate.error, expected[k].error) << "trial " << trial;
        ++k;
      }
      ++compared;
      if (expected.empty()) break;
      const Expected& chosen = expected[static_cast<std::size_t>(
          unit(random) < 0.7 ? 0 : unit(random) * static_cast<double>(expected.size()))];
      Ring next;
      for (std::size_t i = 0; i < hull.size(); ++i) {
        if (i == chosen.edge) {
          next.push_back(chosen.apex);
        } else if (i != (chosen.edge + 1) % hull.size()) {
          next.push_back(hull[i]);
        }
      }
      queue.remove_edge(chosen.edge, next);
      hull = std::move(next);
      ++removals;
    }
  }
  EXPECT_GT(removals, 2000u);
  EXPECT_GT(compared, removals);
  // From the review: vertices 3.9e-166 apart square to a length of 0, closer than a weld of
  // 1e-170, though thousands of cells of twice that weld apart.
  Ring tiny;
  for (int i = 0; i < 80; ++i) {
    const double angle = 2 * M_PI * i / 80;
    tiny.push_back(5e-155 * Vec2{std::cos(angle), std::sin(angle)});
  }
  tiny.insert(tiny.begin() + 11, tiny[10] + Vec2{3.9e-166, 0.0});
  const EngineLimits limits{8, 1e-170};
  MendQueue queue(limits, 1.0, [](Vec2) { return 0.0; });
  ASSERT_TRUE(queue.start(tiny));
  EXPECT_EQ(queue.wanted_count(), edges_to_mend(tiny, limits).size());
  EXPECT_GT(queue.wanted_count(), 0u);
}

// edges_to_mend finds the pairs closer than the weld along a sorted axis: the same edges as
// measuring every pair, on random hulls with clustered, huge, tiny and non-finite coordinates.
TEST(EngineLimits, Issue17_EdgesToMendFindsThePairsEveryPairWouldFind) {
  std::mt19937 random(1717);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto every_pair = [](const Ring& hull, const EngineLimits& limits) {
    const std::size_t n = hull.size();
    std::vector<char> wanted(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const double height = turn_height(hull, i);
      if (height < kCollinearFractionOfWeld * limits.weld || !(height > 0)) {
        wanted[(i + n - 1) % n] = wanted[i] = 1;
      }
      for (std::size_t j = i + 1; j < n; ++j) {
        if (glm::length(hull[i] - hull[j]) < limits.weld) {
          wanted[(i + n - 1) % n] = wanted[i] = wanted[(j + n - 1) % n] = wanted[j] = 1;
        }
      }
    }
    std::vector<std::size_t> edges;
    for (std::size_t i = 0; i < n; ++i) {
      if (wanted[i]) edges.push_back(i);
    }
    return edges;
  };
  int with_pairs = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double scale = std::pow(10.0, -6 + 12 * unit(random));
    const double weld = scale * std::pow(10.0, -4 + 4 * unit(random));
    Ring hull;
    const int n = 3 + static_cast<int>(60 * unit(random));
    for (int i = 0; i < n; ++i) {
      // Clusters: some vertices a fraction of the weld from the one before.
      if (i > 0 && unit(random) < 0.3) {
        hull.push_back(hull.back() + weld * Vec2{unit(random) - 0.5, unit(random) - 0.5});
      } else {
        hull.push_back(scale * Vec2{unit(random), unit(random)});
      }
    }
    if (trial % 50 == 49) hull[0].x = std::numeric_limits<double>::quiet_NaN();
    if (trial % 50 == 48) hull[0].y = std::numeric_limits<double>::infinity();
    if (trial % 50 == 47) hull[0] = hull[1] = {1.5e308, 1.5e308};  // abscissas overflow
    for (double weld_used : {weld, 0.0}) {
      const EngineLimits limits{8, weld_used};
      const std::vector<std::size_t> expected = every_pair(hull, limits);
      EXPECT_EQ(edges_to_mend(hull, limits), expected) << "trial " << trial;
      with_pairs += expected.size() > 0;
    }
  }
  EXPECT_GT(with_pairs, 200);
}

// A CAD circle of thousands of vertices, each nearly collinear with its neighbours: mending
// removes edges one at a time. Each candidate looked at every vertex of the component and copied
// the hull, so that a 20,000-gon took 65 s to cook; a removal now measures again only the
// vertices nearest the three edges it changes (the same hulls come out: see
// Issue17_MendingChecksWhatARemovalChangesAsTheWholeHullChecksDo above).
TEST(EngineLimits, Stop56_MendingALongNearlyCollinearHullMeasuresOnlyWhatARemovalMoves) {
  const int n = 4000;
  Ring circle;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * i / n;
    circle.push_back(100.0 * Vec2{std::cos(angle), std::sin(angle)});
  }
  const CookedPiece piece = convex_piece_of(circle);
  const FitterInputs inputs(piece, 2.0);
  const EngineLimits limits{0, 0.005};
  HullFitter fitter = inputs.fitter(limits);
  ASSERT_TRUE(fitter.holds_component(piece.hull));
  const std::optional<Ring> mended = fitter.mend_local_violations(piece.hull);
  ASSERT_TRUE(mended.has_value());
  // Every vertex turned by 0.00012, under the least turn (0.0005): most were removed.
  EXPECT_LT(mended->size(), static_cast<std::size_t>(n / 2));
  EXPECT_TRUE(hull_meets_limits(*mended, limits));
  EXPECT_TRUE(fitter.holds_component(*mended));
  EXPECT_TRUE(inputs.reach.growth_within(*mended, piece.hull, 2.0));
  // Each of the thousands of removals looked at a few vertices, not at all 4,000 of them.
  const std::uint64_t removals = n - mended->size();
  EXPECT_GT(removals, 1000u);
  EXPECT_LT(fitter.depth_visits(), 20 * removals) << removals << " removals";
}

}  // namespace
}  // namespace hullcook
