// Issue 19's fuzzing: a hole vertex a hair above the outer ring's edge left a sliver piece (the
// triangle of that edge and the vertex). A wall between two rings no thicker than twice the
// sliver width of its edge is bad input (refuse_sliver_regions); anything thicker is cut within
// the contract. Checked on the fuzzer's reproducer and on seeded near-touching rings, their gap
// from 1e-300 to 1e-3 of the region's size.
#include "hullcook/cook/contract.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace hullcook {
namespace {

constexpr Measure kMeasures[] = {Measure::sl, Measure::sp, Measure::h1, Measure::h2};

// The pieces of every measure at τ 0 and 1 % of R keep the contract (slivers included).
void expect_cut_within_contract(const Region& region, const std::string& what) {
  const double radius = enclosing_radius({region});
  for (Measure measure : kMeasures) {
    for (double tau : {0.0, 0.01 * radius}) {
      const DecompositionTree tree = decompose(region, {tau, measure, 0.1, 1.0});
      std::vector<CookedPiece> pieces;
      for (const Piece& piece : tree.pieces_at(tau)) {
        pieces.push_back({piece.component, piece.hull, piece.concavity});
      }
      const std::vector<std::string> violations =
          find_contract_violations(pieces, {region}, {tau, measure, {0, 0.0}});
      EXPECT_TRUE(violations.empty())
          << what << " " << measure_name(measure) << " tau " << tau << ": " << violations.front();
    }
  }
}

// The fuzzer's reproducer: a 0.756 x 0.152 rectangle whose hexagonal hole has its lowest vertex
// 1.2e-9 (or 3.3e-30, or 3e-302) above the bottom edge. The sliver width there is 7.56e-10, and
// the triangle a cut to the edge's ends leaves (area 4.4e-10 over a length of 0.756) is a sliver.
TEST(Issue19Fuzz, HoleVertexAHairAboveTheOuterEdgeIsRefusedAsBadInput) {
  for (const char* height : {".000000001177075663", "3.3e-30", "3e-302"}) {
    const std::string text =
        std::string("2\n4 out\n0 0\n0.756 0\n0.756 0.152\n0 0.152\n1 2 3 4\n") +
        "6 in\n0.7055 0.033198729810778066\n0.6555 " + height +
        "\n0.6305 0.0765\n0.6555 0.11980127018922193\n0.7055 "
        "0.11980127018922193\n0.7305 0.0765\n1 2 3 4 5 6\n";
    const std::vector<Region> regions = clean_and_validate(parse_poly(text, "hair.poly"), "hair");
    try {
      refuse_sliver_regions(regions, "hair.poly");
      ADD_FAILURE() << height << ": not refused";
    } catch (const InputError& error) {
      EXPECT_EQ(error.code, ExitCode::bad_input);
      EXPECT_TRUE(std::string(error.what())
                      .starts_with("hair.poly: region 1 is too thin to cut into pieces within the "
                                   "output's contract (hole "
                                   "1 comes within "))
          << error.what();
      EXPECT_NE(std::string(error.what()).find("of the outer boundary at (0.6555, "),
                std::string::npos)
          << error.what();
    }
  }
}

// Seeded regions with two rings a gap g apart, g = size x 10^u, u from -300 to -3 (a third of them
// from -12 to -3):
//  - a hole's lowest vertex g above the outer ring's bottom edge;
//  - a hole's lowest vertex g above another hole's top edge;
//  - the outer ring's spike, its tip g below a hole's bottom edge.
// The edge lies on y = 0, so that the gap is exact; half the regions are then turned (rounded)
// and moved. Each is refused as bad input (by the validation when rounding made the rings touch)
// or cut within the contract; a gap below half the refusal width is always refused, one above
// twice it never.
struct NearTouching {
  Region region;
  double gap;          // [units] as placed, before turning
  double edge_length;  // [units] of the edge the wall stands on
};

Ring arc_above(Vec2 bottom, double radius, int sides, double first_angle) {
  Ring ring{bottom};  // clockwise from the bottom: a hole
  const Vec2 centre = bottom + Vec2{0.0, radius};
  for (int k = 1; k < sides; ++k) {
    const double angle = first_angle - 2 * M_PI * k / sides;
    ring.push_back(centre + radius * Vec2{std::sin(angle), -std::cos(angle)});
  }
  return ring;
}

NearTouching near_touching(std::mt19937_64& random, int kind) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size = std::ldexp(1.0, int(unit(random) * 20) - 10);
  // A third of the gaps within 1e-12 of the size, where the refusal's threshold lies.
  const double decades = unit(random) < 1.0 / 3.0 ? 9.0 : 297.0;
  const double gap = size * std::pow(10.0, -3.0 - decades * unit(random));
  const double width = size * (1.0 + unit(random)), height = size * (0.5 + unit(random));
  const int sides = 3 + int(unit(random) * 6);
  const double radius = 0.15 * height;
  const double x = width * (0.3 + 0.4 * unit(random));
  NearTouching out{};
  out.gap = gap;
  out.edge_length = width;
  if (kind == 0) {
    out.region.outer = {{0, 0}, {width, 0}, {width, height}, {0, height}};
    out.region.holes.push_back(arc_above({x, gap}, radius, sides, 0.0));
  } else if (kind == 1) {
    out.region.outer = {{0, -height}, {width, -height}, {width, height}, {0, height}};
    const double left = 0.2 * width, right = 0.8 * width;
    out.region.holes.push_back(
        {{left, 0}, {right, 0}, {right, -0.5 * height}, {left, -0.5 * height}});
    out.region.holes.push_back(arc_above({x, gap}, radius, sides, 0.0));
    out.edge_length = right - left;
  } else {
    // The hole's bottom edge on y = 0, the spike's tip gap below it.
    const double spike = 0.05 * width;
    out.region.outer = {{0, -height},     {x - spike, -height}, {x, -gap},  {x + spike, -height},
                        {width, -height}, {width, height},      {0, height}};
    const double half = 0.1 * width;
    out.region.holes.push_back(
        {{x - half, 0}, {x - half, 0.5 * height}, {x + half, 0.5 * height}, {x + half, 0}});
    out.edge_length = 2 * half;
  }
  if (unit(random) < 0.5) {
    const double turn = 2 * M_PI * unit(random);
    const Vec2 offset = size * Vec2{unit(random) - 0.5, unit(random) - 0.5} * 1e3;
    auto place = [&](Vec2 p) {
      return offset + Vec2{p.x * std::cos(turn) - p.y * std::sin(turn),
                           p.x * std::sin(turn) + p.y * std::cos(turn)};
    };
    for (Vec2& p : out.region.outer) p = place(p);
    for (Ring& hole : out.region.holes) {
      for (Vec2& p : hole) p = place(p);
    }
  }
  return out;
}

TEST(Issue19Fuzz, NearTouchingRingsAreRefusedOrCutWithinContract) {
  std::mt19937_64 random(19);
  int refused_by_wall = 0, cut = 0;
  for (int trial = 0; trial < 240; ++trial) {
    const NearTouching sample = near_touching(random, trial % 3);
    // The refusal width by the contract's rounding slack (1e-9 of the extent, or of a thousandth
    // of the largest coordinate), computed here on its own.
    double low_x = INFINITY, high_x = -INFINITY, low_y = INFINITY, high_y = -INFINITY, largest = 0;
    for (Vec2 p : sample.region.outer) {
      low_x = std::min(low_x, p.x), high_x = std::max(high_x, p.x);
      low_y = std::min(low_y, p.y), high_y = std::max(high_y, p.y);
      largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    }
    const double slack = 1e-9 * std::max({high_x - low_x, high_y - low_y, 1e-3 * largest});
    const double refused_below = 2.0 * std::max(slack, 1e-9 * sample.edge_length);
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.3g", sample.gap / refused_below);
    const std::string what =
        "trial " + std::to_string(trial) + " gap " + ratio + " x the refusal width";
    std::vector<Region> regions;
    std::string refusal;
    try {
      regions = clean_and_validate({sample.region}, "near.poly");
      refuse_sliver_regions(regions, "near.poly");
    } catch (const InputError& error) {
      refusal = error.what();
    }
    if (sample.gap < 0.5 * refused_below) {
      EXPECT_FALSE(refusal.empty()) << what << ": not refused";
    }
    if (sample.gap > 2.0 * refused_below) {
      EXPECT_TRUE(refusal.empty()) << what << ": " << refusal;
    }
    if (refusal.find("comes within") != std::string::npos) ++refused_by_wall;
    if (!refusal.empty()) continue;
    ++cut;
    ASSERT_EQ(regions.size(), 1u) << what;
    expect_cut_within_contract(regions[0], what);
  }
  // Both sides of the rule are exercised.
  EXPECT_GT(refused_by_wall, 50);
  EXPECT_GT(cut, 20);
}

// Just either side of the refusal width, the fuzzer's rectangle and hexagon: 0.9 of it is
// refused, 1.1 of it is cut within the contract.
TEST(Issue19Fuzz, WallsJustThickerThanTheRefusalWidthAreCutWithinContract) {
  const double width = 0.756, refused_below = 2.0 * 1e-9 * width;
  for (double factor : {0.9, 1.1, 2.0, 10.0}) {
    const Region region{{{0, 0}, {width, 0}, {width, 0.152}, {0, 0.152}},
                        {arc_above({0.6555, factor * refused_below}, 0.04, 6, 0.3)}};
    const std::string what = "gap " + std::to_string(factor) + " x the refusal width";
    const std::vector<Region> regions = clean_and_validate({region}, "near.poly");
    if (factor < 1.0) {
      EXPECT_THROW(refuse_sliver_regions(regions, "near.poly"), InputError) << what;
    } else {
      EXPECT_NO_THROW(refuse_sliver_regions(regions, "near.poly")) << what;
      expect_cut_within_contract(regions[0], what);
    }
  }
}

// Regions are checked on several threads when asked (issue 17): the first region's error is the
// one thrown, whatever the count.
TEST(Issue19Fuzz, Issue17_ThreadsRefuseTheFirstThinRegion) {
  const double width = 0.756;
  std::vector<Region> regions;
  for (int k = 0; k < 30; ++k) {
    const Vec2 at{k * 1.0, 0};
    // Regions 12 and 24: walls far below the refusal width (about 6e-8 here); the others 0.01.
    const double gap = (k == 11 || k == 23) ? 1e-10 : 0.01;
    Ring outer{at, at + Vec2{width, 0}, at + Vec2{width, 0.152}, at + Vec2{0, 0.152}};
    Ring hole = arc_above({0.6555, gap}, 0.04, 6, 0.3);
    for (Vec2& p : hole) p += at;
    regions.push_back(Region{outer, {hole}});
  }
  regions = clean_and_validate(regions, "near.poly");
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    try {
      refuse_sliver_regions(regions, "near.poly", 1, threads);
      ADD_FAILURE() << threads << " threads: accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("near.poly: region 12 is too thin"),
                std::string::npos)
          << threads << " threads: " << error.what();
    }
  }
}

// The poly fuzzer (scripts/fuzz, 60 s, in issue 17's session): the rectangle with five hexagonal
// holes, the second of which has an edge two ulps long, and the others' bottom vertices on a line.
// Every cut from an end of that edge passed within the graze width of its other end, so every
// cut from that notch grazed, and the fallback cut along the line of the holes' bottoms; it left a
// needle 1.3e-10 thin, which came out a piece of its own (a sliver: area 9.6e-12 over a length of
// 0.151), and `decompose` exited 4 under every measure. A vertex within the graze width of a
// cut's end is at that end, and no longer grazes.
TEST(Issue17Fuzz, EdgeOfTwoUlpsAtANotchIsCutWithinContract) {
  const auto path = std::filesystem::path(HULLCOOK_SOURCE_DIR) /
                    "tests/core/data/issue17_fuzz_edge_of_two_ulps.poly";
  const std::vector<Region> regions = clean_and_validate(read_poly_file(path), "two_ulps.poly");
  ASSERT_EQ(regions.size(), 1u);
  ASSERT_EQ(regions[0].holes.size(), 5u);
  ASSERT_NO_THROW(refuse_sliver_regions(regions, "two_ulps.poly"));  // valid input
  expect_cut_within_contract(regions[0], "two ulps");
}

// The poly fuzzer again (14 minutes, in issue 17's session): an 18-gon of extent 19 with vertices
// at (8.1e-300, 2) and (1e-101, 2), an edge 1e-101 long on the line of a cut from (-4, 2). One
// piece's cut ran to one of them and its neighbour's to the other: collinear stretches that the
// partition check failed to cut at the near end (its fraction along the stretch rounded to 1), so
// `decompose` exited 4 on a partition that holds.
TEST(Issue17Fuzz, CollinearCutsAcrossAnEdgeOf1e101PartitionTheOutline) {
  const auto path = std::filesystem::path(HULLCOOK_SOURCE_DIR) /
                    "tests/core/data/issue17_fuzz_edge_of_1e-101.poly";
  const std::vector<Region> regions = clean_and_validate(read_poly_file(path), "1e-101.poly");
  ASSERT_EQ(regions.size(), 1u);
  ASSERT_NO_THROW(refuse_sliver_regions(regions, "1e-101.poly"));  // valid input
  expect_cut_within_contract(regions[0], "edge of 1e-101");
}

// The poly fuzzer (scripts/fuzz's fuzz_poly, 10 minutes): a 64-gon of radius 7 with two vertices
// drawn out into spikes 6e7 and 8.3e8 long. The longer sets the rounding slack (0.83); the shorter
// is 1.2 wide at its base, and under every measure at τ 0 and 1 % of R the piece holding its tip
// came out a sliver (area 3.4e7 over a length of 6e7), so decompose and cook exited 4. Its sides
// come within the refusal width of each other: bad input, exit 2, naming the spike.
TEST(Issue19Fuzz, SpikeThinnerThanALongerSpikesSlackIsRefusedAsBadInput) {
  const auto path =
      std::filesystem::path(HULLCOOK_SOURCE_DIR) / "tests/core/data/issue19_fuzz_two_spikes.poly";
  const std::vector<Region> regions = read_poly_file(path);
  try {
    refuse_sliver_regions(regions, "spikes.poly");
    ADD_FAILURE() << "not refused";
  } catch (const InputError& error) {
    EXPECT_EQ(error.code, ExitCode::bad_input);
    EXPECT_TRUE(std::string(error.what())
                    .starts_with("spikes.poly: region 1 is too thin to cut into pieces within the "
                                 "output's contract (the outer boundary comes within "))
        << error.what();
    // Refused where it first comes near itself: the radius-7 body's own vertices are within the
    // slack of each other's edges, so the spike's sides are not the only place.
    EXPECT_NE(std::string(error.what()).find(" of itself at ("), std::string::npos) << error.what();
  }
}

// A triangle spike w wide and 1e6 long on a 1000 px square, beside a spike 1e9 long that sets
// the slack to 1: refused up to twice the slack, cut within the contract from a few times it; and
// a unit square with a flat near-collinear chain (vertices 1e-12 off the line, edges 1e-6 long)
// is never refused: nearness along the ring is an edge's length, not a spike.
TEST(Issue19Fuzz, SpikesAreRefusedUpToTheRefusalWidthAndCutWithinContractBeyond) {
  auto region_with_spike = [](double width) {
    return Region{{{0, 0},
                   {500, -1e9},
                   {1000, 0},
                   {1000, 1000},
                   {500 + width / 2, 1000},
                   {500, 1e6},
                   {500 - width / 2, 1000},
                   {0, 1000}},
                  {}};
  };
  for (double width : {0.5, 1.9, 8.0, 40.0}) {
    const std::string what = "spike " + std::to_string(width) + " wide";
    const Region region = region_with_spike(width);
    if (width < 2.0) {
      EXPECT_THROW(refuse_sliver_regions({region}, "spike.poly"), InputError) << what;
    } else {
      EXPECT_NO_THROW(refuse_sliver_regions({region}, "spike.poly")) << what;
      expect_cut_within_contract(region, what);
    }
  }
  Ring flat{{0, 0}, {1, 0}, {1, 1}};
  for (int k = 1; k < 1000; ++k) {
    const double x = 1.0 - k * 1e-6;
    flat.push_back({x, 1.0 + ((k % 2) ? 1e-12 : -1e-12)});
  }
  flat.push_back({0, 1});
  EXPECT_NO_THROW(refuse_sliver_regions({Region{flat, {}}}, "flat.poly"));
}

// A star of long spikes from a small core: every spike's edges pass by the core's corners, which
// share a few grid cells, so the grid's cells tested every edge against all of them (a star of
// 40,000 vertices: 800 million tests); a k-d tree finds each edge's near corners instead. The valid
// star is accepted, and a hole a hair from a spike's edge is named.
TEST(ThinWalls, CrowdedCornersOfALongStarAreCheckedNearEachEdge) {
  const int spikes = 20000;
  Ring star;
  for (int i = 0; i < spikes; ++i) {
    const double a = 2 * M_PI * i / spikes, b = 2 * M_PI * (i + 0.5) / spikes;
    star.push_back({1000 * std::cos(a), 1000 * std::sin(a)});
    star.push_back({10 * std::cos(b), 10 * std::sin(b)});
  }
  const std::vector<Region> valid = clean_and_validate({Region{star, {}}}, "star.poly");
  EXPECT_NO_THROW(refuse_sliver_regions(valid, "star.poly"));
  // Inside spike 0 (1.6e-3 wide there), 1e-7 from its lower edge (from the core at minus half a
  // spike to the tip at angle 0), 500 along it: far below the refusal width of that edge (2e-6).
  const Vec2 from = star[star.size() - 1], to = star[0];
  const Vec2 along = (to - from) / std::hypot(to.x - from.x, to.y - from.y);
  const Vec2 inward{-along.y, along.x};
  const Vec2 near = from + 500.0 * along + 1e-7 * inward;
  const Ring hole{near, near + 0.001 * along + 0.0002 * inward, near + 0.002 * along};
  const std::vector<Region> walled = clean_and_validate({Region{star, {hole}}}, "star.poly");
  try {
    refuse_sliver_regions(walled, "star.poly");
    ADD_FAILURE() << "a hole 1e-7 from the outer boundary was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("hole 1 comes within 1e-07 of the outer boundary"),
              std::string::npos)
        << error.what();
  }
}

// A region refused only because it is far from the origin (the contract's slack is a billionth
// of a thousandth of the largest coordinate there) says so: the same rectangle near the origin
// passes.
TEST(ThinWalls, ARegionTooThinOnlyFarFromTheOriginSaysToMoveIt) {
  auto rectangle = [](Vec2 at) {
    return Region{{at, at + Vec2{1e-3, 0}, at + Vec2{1e-3, 1e-4}, at + Vec2{0, 1e-4}}, {}};
  };
  EXPECT_NO_THROW(refuse_sliver_regions({rectangle({0, 0})}, "near.poly"));
  EXPECT_NO_THROW(refuse_sliver_regions({rectangle({1e3, 1e3})}, "near.poly"));
  try {
    refuse_sliver_regions({rectangle({1e9, 1e9})}, "far.poly");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_TRUE(what.starts_with("far.poly: region 1 is too thin to cut")) << what;
    EXPECT_NE(what.find("; its coordinates reach 1e+09, where the contract's slack for rounding is "
                        "0.001: move it nearer the origin"),
              std::string::npos)
        << what;
  }
  // A region thin at any distance gets no such advice.
  const Region hair{{{0, 0}, {1, 0}, {1, 1e-10}, {0, 1e-10}}, {}};
  try {
    refuse_sliver_regions({hair}, "hair.poly");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("origin"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace hullcook
