// The cooker's own contract check (issue 16): a sprite cooked by cook() keeps it, and each rule
// broken on purpose in that output is named, with the piece.
#include "contract.h"

#include "hullcook/cook/contract.h"
#include "hullcook/cook/cook.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"
#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>
#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

namespace hullcook {
namespace {

const std::filesystem::path kSprites =
    std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";

const EngineLimits kLimits{8, kDefaultWeld};

// A sprite with holes and many pieces, cooked once at τ 2 px (1 px per unit).
const CookedAsset& grid_sprite() {
  static const CookedAsset asset = [] {
    Settings settings;
    settings.tau = Tolerance{2.0, false};
    return cook({kSprites / "pingus__groundpieces__bridge__space__grid1.png"}, settings)
        .assets.at(0);
  }();
  return asset;
}

std::vector<std::string> violations_of(const CookedAsset& asset,
                                       const EngineLimits& limits = kLimits) {
  return find_contract_violations(asset.pieces, asset.regions,
                                  {asset.tau, *parse_measure(asset.measure), limits});
}

std::string listed(const std::vector<std::string>& violations) {
  std::string text;
  for (const std::string& violation : violations) text += "\n  " + violation;
  return text.empty() ? " none" : text;
}

// Expects the cook of file to be refused as the input's, with the advice to raise --max-verts or
// τ (no split of a piece avoids slivers). refused: what the cook must not have made.
void expect_refused_for_slivers(const std::filesystem::path& file, const Settings& settings,
                                const std::string& refused) {
  try {
    cook({file}, settings);
    ADD_FAILURE() << "cooked " << refused;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("raise --max-verts or --tau"), std::string::npos)
        << error.what();
  }
}

// Whether a violation names piece (0-based here, 1-based in the message) and says problem.
bool names(const std::vector<std::string>& violations, std::size_t piece,
           const std::string& problem) {
  const std::string prefix = "piece " + std::to_string(piece + 1) + ": ";
  return std::any_of(violations.begin(), violations.end(), [&](const std::string& violation) {
    return violation.starts_with(prefix) && violation.find(problem) != std::string::npos;
  });
}

bool says(const std::vector<std::string>& violations, const std::string& problem) {
  return std::any_of(violations.begin(), violations.end(), [&](const std::string& violation) {
    return violation.find(problem) != std::string::npos;
  });
}

// The first piece whose hull has at least this many vertices.
std::size_t piece_with_hull_of(const CookedAsset& asset, std::size_t vertices) {
  for (std::size_t k = 0; k < asset.pieces.size(); ++k) {
    if (asset.pieces[k].hull.size() >= vertices) return k;
  }
  ADD_FAILURE() << "no hull of " << vertices << " vertices";
  return 0;
}

bool strictly_convex(const Ring& ring) {
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
    if (test::cross2(b - a, c - b) <= 0) return false;
  }
  return true;
}

TEST(Contract, CookedSpriteKeepsIt) {
  const CookedAsset& asset = grid_sprite();
  ASSERT_GT(asset.pieces.size(), 20u);
  EXPECT_TRUE(violations_of(asset).empty()) << listed(violations_of(asset));
}

TEST(Contract, DroppedPieceBreaksThePartition) {
  CookedAsset asset = grid_sprite();
  asset.pieces.erase(asset.pieces.begin() + 5);
  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(says(violations, "the pieces' areas add up to")) << listed(violations);
  EXPECT_TRUE(says(violations, "the pieces do not partition the outline")) << listed(violations);
}

// The pieces are checked on several threads when asked (issue 17: one huge image's check was all
// on one thread): the same reports, in the pieces' order, whatever the count.
TEST(Contract, Issue17_ThreadsGiveTheSameReportsInOrder) {
  CookedAsset asset = grid_sprite();
  ASSERT_GT(asset.pieces.size(), 40u);
  const ContractTerms terms{asset.tau, *parse_measure(asset.measure), kLimits};
  EXPECT_TRUE(find_contract_violations(asset.pieces, asset.regions, terms, 3).empty());
  // Three pieces broken: a shrunk hull, one moved far out, one with a vertex too many.
  for (std::size_t k : {3u, 17u, 31u}) {
    Ring& hull = asset.pieces[k].hull;
    Vec2 centre{0, 0};
    for (Vec2 v : hull) centre += v / double(hull.size());
    if (k == 3)
      for (Vec2& v : hull) v = centre + 0.9 * (v - centre);
    if (k == 17)
      for (Vec2& v : hull) v += Vec2{0, 40};
    if (k == 31) hull.insert(hull.begin() + 1, 0.5 * (hull[0] + hull[1]));
  }
  const std::vector<std::string> one = find_contract_violations(asset.pieces, asset.regions, terms);
  ASSERT_GE(one.size(), 3u) << listed(one);
  EXPECT_TRUE(names(one, 3, "outside its hull")) << listed(one);
  EXPECT_TRUE(names(one, 17, "beyond the outline")) << listed(one);
  EXPECT_TRUE(names(one, 31, "")) << listed(one);
  for (unsigned threads : {2u, 3u, 8u}) {
    EXPECT_EQ(find_contract_violations(asset.pieces, asset.regions, terms, threads), one)
        << threads << " threads";
  }
}

TEST(Contract, PiecesWhoseAreasAddUpInTheWrongPlaceBreakThePartition) {
  // The left half of a 2 x 1 rectangle twice: the areas add up, the right half is left out.
  const Region rectangle{{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {}};
  const Ring left{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const CookedPiece half{Region{left, {}}, left, 0.0};
  const std::vector<std::string> violations =
      find_contract_violations({half, half}, {rectangle}, {0.5, Measure::h1, kLimits});
  EXPECT_FALSE(says(violations, "areas")) << listed(violations);
  EXPECT_TRUE(says(violations, "the pieces do not partition the outline")) << listed(violations);
}

// Each region's pieces cancel that region's boundary (issue 17: the regions are checked apart,
// on the threads): pieces given to the wrong region, or to one the outline does not have, break
// the partition although their union is the outline.
TEST(Contract, Issue17_EachRegionsPiecesPartitionThatRegion) {
  const Ring left{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, right{{3, 0}, {4, 0}, {4, 1}, {3, 1}};
  const std::vector<Region> outline{Region{left, {}}, Region{right, {}}};
  std::vector<CookedPiece> pieces{CookedPiece{Region{left, {}}, left, 0.0, 0},
                                  CookedPiece{Region{right, {}}, right, 0.0, 1}};
  const ContractTerms terms{0.5, Measure::h1, kLimits};
  for (unsigned threads : {1u, 2u}) {
    EXPECT_TRUE(find_contract_violations(pieces, outline, terms, threads).empty()) << threads;
  }
  std::swap(pieces[0].region, pieces[1].region);
  EXPECT_TRUE(says(find_contract_violations(pieces, outline, terms),
                   "the pieces do not partition the outline"));
  pieces[0].region = 0, pieces[1].region = 2;
  const std::vector<std::string> violations = find_contract_violations(pieces, outline, terms);
  EXPECT_TRUE(says(violations, "piece 2 is of region 3, but the outline has 2"))
      << listed(violations);
}

// A cook labels every piece with its region, through the engine limits' splits and merges: a
// sheet of many blobs keeps its contract (checked region by region) with any thread count.
TEST(Contract, Issue17_CookedPiecesCarryTheirRegions) {
  Settings settings;
  settings.tau = Tolerance{1.0, false};
  for (unsigned threads : {1u, 3u}) {
    settings.threads = threads;
    const CookedAsset asset =
        cook({kSprites / "teeworlds__mapres__grass_doodads.png"}, settings).assets.at(0);
    ASSERT_GT(asset.regions.size(), 30u);
    std::vector<std::size_t> per_region(asset.regions.size(), 0);
    for (const CookedPiece& piece : asset.pieces) {
      ASSERT_LT(piece.region, asset.regions.size());
      ++per_region[piece.region];
    }
    for (std::size_t count : per_region) EXPECT_GT(count, 0u);
    EXPECT_TRUE(violations_of(asset).empty()) << listed(violations_of(asset));
  }
}

TEST(Contract, ShrunkHullIsNamed) {
  CookedAsset asset = grid_sprite();
  const std::size_t k = 7;
  Ring& hull = asset.pieces[k].hull;
  Vec2 centre{0, 0};
  for (Vec2 v : hull) centre += v / double(hull.size());
  for (Vec2& v : hull) v = centre + 0.9 * (v - centre);
  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(names(violations, k, "outside its hull")) << listed(violations);
}

TEST(Contract, HullOfNineVerticesIsNamed) {
  CookedAsset asset = grid_sprite();
  const std::size_t k = piece_with_hull_of(asset, 5);
  Ring& hull = asset.pieces[k].hull;
  // Edges 0, 1, ... get a vertex at their middle, pushed out by a thousandth of their length: the
  // hull stays convex, with no vertex nearly collinear.
  const Ring original = hull;
  hull.clear();
  for (std::size_t i = 0; i < original.size(); ++i) {
    const Vec2 a = original[i], b = original[(i + 1) % original.size()];
    hull.push_back(a);
    if (original.size() + i < 9) hull.push_back(0.5 * (a + b) + 1e-3 * Vec2{(b - a).y, -(b - a).x});
  }
  ASSERT_EQ(hull.size(), 9u);
  ASSERT_TRUE(strictly_convex(hull));

  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(names(violations, k, "its hull has 9 vertices (at most 8)")) << listed(violations);
  // Without a vertex limit the same hull is no fault of its own.
  EXPECT_FALSE(names(violations_of(asset, {0, kDefaultWeld}), k, "hull"))
      << listed(violations_of(asset, {0, kDefaultWeld}));
}

TEST(Contract, HullVertexMovedOutByMoreThanTauIsNamed) {
  CookedAsset asset = grid_sprite();
  const double tau = asset.tau;
  // A hull vertex moved 1.1 τ away from its hull's centre that then lies beyond τ of the outline
  // (measured here independently) and keeps the hull convex.
  for (std::size_t k = 0; k < asset.pieces.size(); ++k) {
    Ring hull = asset.pieces[k].hull;
    Vec2 centre{0, 0};
    for (Vec2 v : hull) centre += v / double(hull.size());
    for (Vec2& v : hull) {
      const Vec2 original = v;
      v += 1.1 * tau * glm::normalize(v - centre);
      if (strictly_convex(hull) && test::distance_to_regions(v, asset.regions) > tau * 1.05) {
        asset.pieces[k].hull = hull;
        const std::vector<std::string> violations = violations_of(asset);
        EXPECT_TRUE(names(violations, k, "its hull's vertex")) << listed(violations);
        EXPECT_TRUE(names(violations, k, "beyond the outline (τ 2)")) << listed(violations);
        return;
      }
      v = original;
    }
  }
  FAIL() << "no hull vertex to move";
}

// The violations of one piece over outline at tolerance tau.
std::vector<std::string> one_piece_at(const CookedPiece& piece, const Region& outline, double tau) {
  return find_contract_violations({piece}, {outline}, {tau, Measure::h1, kLimits});
}

// A 10 x 10 square with a slot 2 wide and 7 deep from the top, as one piece under the square.
Region slotted_square() {
  return {{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 3}, {4, 3}, {4, 10}, {0, 10}}, {}};
}

TEST(Contract, HullEdgeBeyondTauBetweenVerticesOnTheOutlineIsNamed) {
  // The hull's top edge spans the slot: its vertices lie on the outline, its middle 1 from it.
  const Region region = slotted_square();
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const CookedPiece piece{region, square, 0.0};
  const std::vector<std::string> beyond = one_piece_at(piece, region, 0.9);
  EXPECT_TRUE(names(beyond, 0, "its hull's point (5, 10) lies 1 beyond the outline (τ 0.9)"))
      << listed(beyond);
  const std::vector<std::string> within = one_piece_at(piece, region, 1.01);
  EXPECT_FALSE(says(within, "beyond the outline")) << listed(within);
}

TEST(Contract, ComponentEdgeFartherThanTauFromItsHullBetweenVerticesWithinIsNamed) {
  // A square with a corner cut off, under the whole square: both ends of the cut lie on the hull's
  // boundary, the cut's middle (9, 9) lies 1 from it. Checking vertices alone misses it.
  const Region cut_square{{{0, 0}, {10, 0}, {10, 8}, {8, 10}, {0, 10}}, {}};
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const CookedPiece piece{cut_square, square, 0.0};
  const std::vector<std::string> far = one_piece_at(piece, cut_square, 0.9);
  EXPECT_TRUE(names(far, 0, "its component's point (9, 9) lies 1 from its hull's boundary (τ 0.9)"))
      << listed(far);
  const std::vector<std::string> near = one_piece_at(piece, cut_square, 1.01);
  EXPECT_FALSE(says(near, "from its hull's boundary")) << listed(near);
}

TEST(Contract, WeldedVerticesAreNamed) {
  CookedAsset asset = grid_sprite();
  const std::size_t k = piece_with_hull_of(asset, 4);
  Ring& hull = asset.pieces[k].hull;
  // Vertex 0 slides along its edge to half the weld distance from vertex 1: still convex.
  hull[0] = hull[1] + (hull[0] - hull[1]) * (0.5 * kDefaultWeld / glm::length(hull[0] - hull[1]));
  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(names(violations, k, "apart (weld 0.005)")) << listed(violations);
}

TEST(Contract, ClockwiseHullIsNamed) {
  CookedAsset asset = grid_sprite();
  const std::size_t k = 2;
  std::reverse(asset.pieces[k].hull.begin(), asset.pieces[k].hull.end());
  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(names(violations, k, "its hull is clockwise")) << listed(violations);
}

TEST(Contract, ComponentOutsideTheOutlineIsNamed) {
  CookedAsset asset = grid_sprite();
  const std::size_t k = 4;
  for (Vec2& v : asset.pieces[k].component.outer) v += Vec2{0.5, 0};
  for (Vec2& v : asset.pieces[k].hull) v += Vec2{0.5, 0};
  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(says(violations, "the pieces do not partition the outline")) << listed(violations);
}

TEST(Contract, ClockwiseComponentIsNamed) {
  CookedAsset asset = grid_sprite();
  const std::size_t k = 6;
  Ring& outer = asset.pieces[k].component.outer;
  std::reverse(outer.begin(), outer.end());
  const std::vector<std::string> violations = violations_of(asset);
  EXPECT_TRUE(names(violations, k, "outer ring is not counter-clockwise")) << listed(violations);
}

// Issue 16's square with four diamond holes, whose holes see no vertex of the outer boundary.
Region square_with_four_diamonds() {
  Region region{{{0, 0}, {25, 0}, {25, 25}, {0, 25}}, {}};
  for (Vec2 centre : {Vec2{7, 7}, Vec2{7, 18}, Vec2{18, 7}, Vec2{18, 18}}) {
    region.holes.push_back(
        {centre + Vec2{0, 5}, centre + Vec2{5, 0}, centre + Vec2{0, -5}, centre + Vec2{-5, 0}});
  }
  return clean_and_validate({region}, "four diamonds").front();
}

TEST(Contract, PieceKeepingHolesDeeperThanTauIsNamed) {
  const Region region = square_with_four_diamonds();
  const CookedPiece whole{region, region.outer, 0.0};
  for (Measure measure : {Measure::sl, Measure::sp, Measure::h1, Measure::h2}) {
    SCOPED_TRACE(measure_name(measure));
    const std::vector<std::string> violations =
        find_contract_violations({whole}, {region}, {1.0, measure, kLimits});
    EXPECT_TRUE(names(violations, 0, "its concavity, measured afresh")) << listed(violations);
    // The holes' boundary lies up to 7 from the square's.
    EXPECT_TRUE(names(violations, 0, "from its hull's boundary (τ 1)")) << listed(violations);
  }
  // At a τ above every hole's depth, the one piece keeps the contract.
  EXPECT_TRUE(find_contract_violations({whole}, {region}, {30.0, Measure::h1, kLimits}).empty());
}

TEST(Contract, SliverPieceIsNamed) {
  // A triangle cut off a square along a diagonal that misses a corner by 1e-12.
  const Region square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
  const Ring sliver{{10, 10 - 1e-12}, {10, 10}, {0, 0}};
  const Ring rest{{0, 0}, {10, 0}, {10, 10 - 1e-12}};
  const Ring left{{0, 0}, {10, 10}, {0, 10}};
  const std::vector<CookedPiece> pieces{{Region{rest, {}}, rest, 0.0},
                                        {Region{sliver, {}}, sliver, 0.0},
                                        {Region{left, {}}, left, 0.0}};
  const std::vector<std::string> violations =
      find_contract_violations(pieces, {square}, {0.5, Measure::h1, {0, 0.0}});
  EXPECT_TRUE(names(violations, 1, "its component is a sliver")) << listed(violations);
  EXPECT_FALSE(names(violations, 0, "sliver")) << listed(violations);
}

// Issue 19's fuzzing of the decomposer: an input region that is itself a sliver by the contract
// (a spike thinner than a billionth of its length; a unit triangle whose rounding slack, 1e14
// from the origin, is larger than it) cannot be cut into pieces that keep the contract. It is
// refused as bad input before decomposing; a region only 1e-7 of its length thin is not.
TEST(Issue19Fuzz, RegionsThatAreSliversThemselvesAreRefusedAsBadInput) {
  auto spike = [](double length) {
    return Region{{{0, 0}, {0.9, 0}, {1, -length}, {1.1, 0}, {2, 0}, {2, 2}, {0, 2}}, {}};
  };
  const Vec2 far{1e14, 1e14};
  const Region far_triangle{{far, far + Vec2{1, 0}, far + Vec2{0, 1}}, {}};
  const Region square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  for (const Region& sliver : {spike(1e9), far_triangle}) {
    const double tau = 0.01 * enclosing_radius({sliver});
    const DecompositionTree tree = decompose(sliver, {tau, Measure::h1, 0.1, 1.0});
    std::vector<CookedPiece> pieces;
    for (const Piece& piece : tree.pieces_at(tau)) {
      pieces.push_back({piece.component, piece.hull, piece.concavity});
    }
    const std::vector<std::string> violations =
        find_contract_violations(pieces, {sliver}, {tau, Measure::h1, {0, 0.0}});
    EXPECT_TRUE(says(violations, "is a sliver")) << listed(violations);
    try {
      refuse_sliver_regions({sliver}, "fuzz.poly", 3);
      FAIL() << "not refused";
    } catch (const InputError& error) {
      EXPECT_EQ(error.code, ExitCode::bad_input);
      EXPECT_TRUE(std::string(error.what()).starts_with("fuzz.poly: region 3 is too thin to cut"))
          << error.what();
    }
  }
  EXPECT_NO_THROW(refuse_sliver_regions({spike(1e7), square}, "fuzz.poly"));
  EXPECT_NO_THROW(refuse_sliver_regions({}, "fuzz.poly"));
}

TEST(Contract, AViolationIsAnInternalErrorNamingTheAssetAndTheFirst) {
  CookedAsset asset = grid_sprite();
  std::reverse(asset.pieces[2].hull.begin(), asset.pieces[2].hull.end());
  asset.pieces.erase(asset.pieces.begin() + 5);
  const std::vector<std::string> violations = violations_of(asset);
  ASSERT_GE(violations.size(), 3u) << listed(violations);
  try {
    enforce_contract(asset.source, violations);
    FAIL() << "no error";
  } catch (const ContractError& error) {
    EXPECT_EQ(error.code, ExitCode::internal);
    EXPECT_EQ(std::string(error.what()),
              asset.source + ": internal error: the output breaks its contract: " +
                  violations.front() + " (and " + std::to_string(violations.size() - 1) + " more)");
  }
  EXPECT_NO_THROW(enforce_contract(asset.source, {}));
}

// A model accepted as input (spanning at least 1e-140) may be cut into pieces smaller than that:
// the contract check validates them without the input's size floor. With it, the monkey scaled
// to span 2.5e-140 broke the contract ("its component is not a valid region: too small", exit 4)
// in review of the floor's first version.
TEST(Contract, PiecesSmallerThanTheInputFloorKeepTheContract) {
  const auto path =
      std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons/nazca/nazca_monkey.poly";
  std::vector<Region> regions = read_poly_file(path);
  for (Region& region : regions) {
    for (Vec2& p : region.outer) p = {std::ldexp(p.x, -471), std::ldexp(p.y, -471)};
  }
  ASSERT_NO_THROW(refuse_tiny_rings(regions, "scaled monkey"));  // valid input
  regions = clean_and_validate(std::move(regions), "scaled monkey");
  const double tau = 0.01 * enclosing_radius(regions);
  std::vector<CookedPiece> pieces;
  double smallest = std::numeric_limits<double>::infinity();
  for (Piece& piece : decompose(regions[0], {tau, Measure::h1, 0.1, 1.0}).pieces_at(tau)) {
    Vec2 low = piece.hull[0], high = low;
    for (Vec2 p : piece.hull) low = glm::min(low, p), high = glm::max(high, p);
    smallest = std::min(smallest, std::max(high.x - low.x, high.y - low.y));
    pieces.push_back({std::move(piece.component), std::move(piece.hull), piece.concavity});
  }
  ASSERT_LT(smallest, 1e-140);  // some pieces are below the input floor
  const std::vector<std::string> violations =
      find_contract_violations(pieces, regions, {tau, Measure::h1, EngineLimits{0, 0.0}});
  EXPECT_TRUE(violations.empty()) << listed(violations);
}

// Cooks the .poly text at τ (input units) and weld, and expects the asset within the contract.
void expect_cooked_within_contract(const std::string& poly, const std::string& name, double tau,
                                   double weld) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("hullcook_contract_" + name + ".poly");
  std::ofstream(file) << poly;
  Settings settings;
  settings.tau = Tolerance{tau, false};
  settings.weld = weld;
  CookedAsset asset;
  EXPECT_NO_THROW(asset = cook({file}, settings).assets.at(0)) << name << " tau " << tau;
  std::filesystem::remove(file);
  const std::vector<std::string> violations = violations_of(asset, EngineLimits{8, weld});
  EXPECT_TRUE(violations.empty()) << name << " tau " << tau << " weld " << weld
                                  << listed(violations);
}

// A seeded random simple polygon (the stress family random_simple, on a 0.01 grid) with three
// vertices collinear in decimal, not quite in binary, cooked whole at τ 0. With the default weld
// the cook's own check reported a hull edge along them "9.9e-10 beyond the outline" (exit 4);
// with weld 0 one of its pieces could be placed under no engine hull (exit 4). Both are valid.
TEST(Contract, RandomPolygonWithNearlyCollinearVerticesCooksAtTauZero) {
  const std::string poly = R"(1
50 out
1.0 0.53
0.95 0.53
0.73 0.53
0.77 0.55
0.9 0.57
0.99 0.61
0.65 0.55
0.75 0.61
0.9 0.72
0.91 0.79
0.82 0.78
0.74 0.72
0.62 0.65
0.64 0.83
0.55 0.76
0.56 0.95
0.51 0.61
0.4 0.99
0.4 0.74
0.43 0.63
0.41 0.63
0.18 0.88
0.23 0.78
0.15 0.85
0.12 0.79
0.41 0.56
0.25 0.58
0.39 0.53
0.01 0.6
0.29 0.48
0.23 0.47
0.02 0.38
0.09 0.39
0.31 0.44
0.44 0.45
0.45 0.45
0.23 0.09
0.46 0.41
0.53 0.19
0.59 0.21
0.53 0.42
0.72 0.05
0.72 0.19
0.82 0.11
0.82 0.12
0.88 0.18
0.92 0.22
0.58 0.45
0.61 0.47
0.77 0.45
1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 36 37 38 39 40 41 42 43 44 45 46 47 48 49 50
)";
  for (const double weld : {kDefaultWeld, 0.0}) {
    expect_cooked_within_contract(poly, "nearly_collinear", 0.0, weld);
  }
}

// A unit square whose sides carry 300 vertices each, every coordinate moved by up to 1e-7
// (seeded): at τ 0 the pieces along the sides are convex and some 1e-8 thin. At --max-verts 3
// they must be cut into triangles, and halving from vertex 0 left slivers, which the contract
// caught as an internal error (exit 4). Halving now looks for halves that are no slivers; a
// piece that has none is the input's (its vertices lie too near a line for their precision): an
// InputError that says what to raise. At --max-verts 8 the same input cooks within the contract.
TEST(Contract, SidesOfNearlyCollinearVerticesCutIntoTrianglesAreAnInputError) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "hullcook_contract_bumpy_square.poly";
  {
    std::mt19937_64 random(1);
    auto jitter = [&] { return (double(random() >> 11) * 0x1.0p-53 * 2 - 1) * 1e-7; };
    const Vec2 corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::ofstream out(file);
    out.precision(17);
    out << "1\n1200 out\n";
    for (int side = 0; side < 4; ++side) {
      const Vec2 a = corners[side], b = corners[(side + 1) % 4];
      for (int i = 0; i < 300; ++i) {
        const Vec2 p = a + (b - a) * (double(i) / 300);
        const double x = p.x + jitter();
        out << x << " " << p.y + jitter() << "\n";
      }
    }
    for (int i = 1; i <= 1200; ++i) out << i << (i < 1200 ? " " : "\n");
  }
  Settings settings;
  settings.tau = Tolerance{0.0, false};
  settings.weld = 0.0;
  CookedAsset asset;
  ASSERT_NO_THROW(asset = cook({file}, settings).assets.at(0));
  const std::vector<std::string> violations = violations_of(asset, EngineLimits{8, 0.0});
  EXPECT_TRUE(violations.empty()) << listed(violations);
  settings.max_verts = 3;
  expect_refused_for_slivers(file, settings, "into triangles");
  std::filesystem::remove(file);
}

// A review of the τ 0 rule for notches no deeper than the contract's slack (left where only
// slivers resolve them): a 12-vertex piece of a rectangle's side, 25 long and 4e-3 wide, 1e6 from
// the origin, keeps such a notch at τ 0 and its hull of 10 vertices exceeds --max-verts 8; the
// constrainer found no convex piece to halve and threw an internal error (exit 4), then refused
// it as input. Pieces that are not convex are now halved along a diagonal too: it cooks within
// the contract at --max-verts 8, as at 12.
TEST(Contract, NotchWithinTheSlackOverMaxVertsIsHalvedAlongADiagonal) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "hullcook_contract_notch_far_from_origin.poly";
  {
    std::ofstream out(file);
    out << R"(1
12 out
1000571.298921 999632.0930369999
1000571.299245 999634.165752
1000571.2995679999 999636.238467
1000571.2998909999 999638.311182
1000571.3002139999 999640.383898
1000571.3005359999 999642.4566129999
1000571.300858 999644.5293279999
1000571.301179 999646.6020439999
1000571.3015 999648.674759
1000571.3021399999 999652.820189
1000571.3024599999 999654.8929049999
1000571.3027789999 999656.9656199999
1 2 3 4 5 6 7 8 9 10 11 12
)";
  }
  Settings settings;
  settings.tau = Tolerance{0.0, false};
  settings.weld = 0.0;
  for (std::size_t max_verts : {std::size_t{8}, std::size_t{12}}) {
    settings.max_verts = max_verts;
    CookedAsset asset;
    ASSERT_NO_THROW(asset = cook({file}, settings).assets.at(0));
    const std::vector<std::string> violations = violations_of(asset, EngineLimits{max_verts, 0.0});
    EXPECT_TRUE(violations.empty()) << max_verts << listed(violations);
  }
  std::filesystem::remove(file);
}

// A random outline 1e-4 wide, 1e5 from the origin, with seven small holes: the contract's slack
// (1e-9 of a thousandth of the largest coordinate, 1e-7) is a thousandth of its width. At τ 0
// the decomposition had no cut but one leaving a triangle between two holes and the outer
// boundary 2.7e-8 thick, a sliver at that slack: an internal error (exit 4). The engine limits
// now merge such a sliver into a neighbour (here at τ 0 too), or refuse it as input.
TEST(Contract, SliverThatNoCutAvoidedIsMergedIntoANeighbour) {
  const std::string poly = R"(8
12 out
100000.00008110295 100000.00007496438
100000.00007366456 100000.00008183361
100000.00004714684 100000.000093445
100000.00004735531 100000.00008793238
100000.00004595026 100000.0000858337
100000.00004068734 100000.0000868807
100000.00002984694 100000.00008813952
100000.00001797098 100000.00007531999
100000.0000041178 100000.00004668134
100000.00000334255 100000.00004396691
100000.00005896871 100000.00000977106
100000.00008648308 100000.00004927025
1 2 3 4 5 6 7 8 9 10 11 12
7 in
100000.00006927553 100000.0000461011
100000.00006686806 100000.00004364627
100000.00006344776 100000.00004399795
100000.00006159021 100000.0000468913
100000.00006269416 100000.00005014759
100000.00006592833 100000.00005131474
100000.0000688573 100000.00004951388
1 2 3 4 5 6 7
6 in
100000.00003932431 100000.00005481571
100000.00003609694 100000.00005165671
100000.00003174748 100000.0000528722
100000.0000306254 100000.00005724668
100000.00003385276 100000.00006040568
100000.00003820223 100000.0000591902
1 2 3 4 5 6
5 in
100000.00003680802 100000.00003415401
100000.00003117374 100000.00003233578
100000.0000277034 100000.00003713244
100000.0000311929 100000.00004191518
100000.00003681987 100000.0000400744
1 2 3 4 5
4 in
100000.00005989693 100000.00002680268
100000.0000575325 100000.00002744491
100000.00005817473 100000.00002980935
100000.00006053917 100000.00002916712
1 2 3 4
4 in
100000.00004991134 100000.00004007536
100000.00004296625 100000.00004666994
100000.00004956083 100000.00005361505
100000.00005650593 100000.00004702047
1 2 3 4
13 in
100000.00003500684 100000.00004741628
100000.00003506952 100000.0000466878
100000.00003478648 100000.00004601362
100000.00003422257 100000.00004554822
100000.00003350695 100000.00004539818
100000.00003280358 100000.00004559789
100000.00003227359 100000.0000461016
100000.0000320384 100000.00004679391
100000.00003215186 100000.00004751622
100000.00003258801 100000.00004810306
100000.00003324694 100000.00004842
100000.00003397766 100000.00004839442
100000.00003461279 100000.00004803218
1 2 3 4 5 6 7 8 9 10 11 12 13
12 in
100000.00007362655 100000.00003482902
100000.00007313468 100000.00003281671
100000.00007170255 100000.00003131994
100000.0000697139 100000.00003073976
100000.00006770159 100000.00003123163
100000.00006620483 100000.00003266375
100000.00006562464 100000.0000346524
100000.00006611651 100000.0000366647
100000.00006754864 100000.00003816148
100000.00006953729 100000.00003874165
100000.0000715496 100000.00003824978
100000.00007304637 100000.00003681766
1 2 3 4 5 6 7 8 9 10 11 12
)";
  for (const double tau : {0.0, 0.0000005}) {
    expect_cooked_within_contract(poly, "far_small_holes", tau, 0.0);
  }
}

// A strip 500,000 units long and 0.001 wide, at an angle, cut along its diagonal: each triangle's
// area is a small difference of products near 1e11, and the shoelace about a vertex rounds by far
// more than a billionth of it. The contract sums areas exactly but for a final rounding (stop 56:
// a helper's strip in triangles at --max-verts 3 exited 4, its areas 5.2e-7 apart of 495; 10 of
// these 15 strips fail with the plain shoelace), and still sees half a strip left out.
TEST(Contract, Stop56_LongThinPiecesAreasAreSummedAccurately) {
  int strips = 0;
  for (double angle : {0.1, 0.7853981633974483, 1.3, 2.0, 2.9}) {
    for (double length : {5e4, 5e5, 3e6}) {
      const Vec2 along{std::cos(angle), std::sin(angle)}, across{-along.y, along.x};
      const double width = 0.001;
      const Vec2 a{1234.5678, -876.54321}, b = a + along * length, c = b + across * width,
                                           d = a + across * width;
      const Region strip{{a, b, c, d}, {}};
      const Ring first{b, c, a}, second{c, d, a};
      const std::vector<CookedPiece> pieces{CookedPiece{Region{first, {}}, first, 0.0},
                                            CookedPiece{Region{second, {}}, second, 0.0}};
      const std::vector<std::string> violations =
          find_contract_violations(pieces, {strip}, {0.5, Measure::h1, kLimits});
      EXPECT_FALSE(says(violations, "areas")) << angle << " " << length << listed(violations);
      // Half the strip is missing: its areas do not add up.
      EXPECT_TRUE(says(find_contract_violations({pieces[0]}, {strip}, {0.5, Measure::h1, kLimits}),
                       "areas"));
      ++strips;
    }
  }
  EXPECT_EQ(strips, 15);
}

// A region's rings are summed in one sum (stop 57: a unit square less a hole 1e-8 inside it,
// valid input, decomposed into 4 pieces of the region's own vertices, summed 5.5e-17 off its 4e-8
// with each ring summed apart, and exited 4), in either orientation of its rings.
TEST(Contract, Stop57_AFramesAreaIsItsRingsInOneSum) {
  for (double wall : {1e-8, 3e-9, 2.1e-8}) {
    const double in = wall, out = 1.0 - wall;
    const Ring outer{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
        hole{{in, in}, {in, out}, {out, out}, {out, in}};
    const Region frame{outer, {hole}};
    // The frame's four trapezoids, each along one side.
    const std::vector<Ring> sides{{{0, 0}, {1, 0}, {out, in}, {in, in}},
                                  {{1, 0}, {1, 1}, {out, out}, {out, in}},
                                  {{1, 1}, {0, 1}, {in, out}, {out, out}},
                                  {{0, 1}, {0, 0}, {in, in}, {in, out}}};
    std::vector<CookedPiece> pieces;
    for (const Ring& side : sides) pieces.push_back(CookedPiece{Region{side, {}}, side, 0.0});
    for (const Region& outline :
         {frame, Region{Ring(outer.rbegin(), outer.rend()), {Ring(hole.rbegin(), hole.rend())}}}) {
      const std::vector<std::string> violations =
          find_contract_violations(pieces, {outline}, {0.5, Measure::h1, kLimits});
      EXPECT_FALSE(says(violations, "areas")) << wall << listed(violations);
      // 2 - 2 (out - in)² of the doubles in and out, in quadruple precision.
      const __float128 side = static_cast<__float128>(out) - static_cast<__float128>(in);
      EXPECT_NEAR(accurate_twice_area(outline), static_cast<double>(2 - 2 * side * side), 1e-22)
          << wall;
    }
    // A side missing: the areas do not add up.
    EXPECT_TRUE(says(find_contract_violations({pieces[0], pieces[1], pieces[2]}, {frame},
                                              {0.5, Measure::h1, kLimits}),
                     "areas"));
  }
}

// The review of stop 57: one sum over a region's rings far from the origin carried its own
// rounding, eps² times the products' size (a frame 1e-3 wide at (-1e6, -1e6), walls 1.05e-9: 4.9e-9
// of its area off, over the contract's billionth); the carried errors are now summed compensated
// too.
TEST(Contract, Stop57_AFramesAreaFarFromTheOriginIsSummedToAFewUlps) {
  for (const double offset : {-1e6, 1e5, 1e7}) {
    for (const double side : {1e-3, 1e-5}) {
      const double wall = side * 1.05e-6;
      const double low = offset, high = offset + side, in_low = low + wall, in_high = high - wall;
      const Region frame{
          {{low, low}, {high, low}, {high, high}, {low, high}},
          {{{in_low, in_low}, {in_low, in_high}, {in_high, in_high}, {in_high, in_low}}}};
      // Twice the area of the doubles' squares, in quadruple precision.
      const __float128 outer = static_cast<__float128>(high) - static_cast<__float128>(low);
      const __float128 inner = static_cast<__float128>(in_high) - static_cast<__float128>(in_low);
      const double exact = static_cast<double>(2 * (outer * outer - inner * inner));
      EXPECT_NEAR(accurate_twice_area(frame), exact, 1e-12 * exact) << offset << " " << side;
    }
  }
}

}  // namespace
}  // namespace hullcook
