// The contract of issue 3 on every sample model and on random polygons, for all four measures.
#include "hullcook/core/decompose.h"
#include "decompose_contract.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/poly_io.h"
#include "hullcook/core/predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <queue>
#include <random>

namespace hullcook {
namespace {

using test::brute_sl_concavity;
using test::brute_sp_vertex_concavity;
using test::check_tree;
using test::expect_contract;
using test::kMeasures;

struct Model {
  const char* file;
  bool large;
};

class SampleModels : public ::testing::TestWithParam<Model> {};

TEST_P(SampleModels, ContractForEveryMeasure) {
  const auto path =
      std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons" / GetParam().file;
  const std::vector<Region> regions = read_poly_file(path);
  const double radius = enclosing_radius(regions);
  std::vector<double> fractions{0.1, 0.01};
  if (!GetParam().large) fractions.push_back(0.0);
  for (const Region& region : regions) {
    for (Measure measure : kMeasures) {
      if (GetParam().large && measure != Measure::h1) continue;
      for (double fraction : fractions) {
        const double tau = fraction * radius;
        const std::string what = std::string(GetParam().file) + " " + measure_name(measure) +
                                 " tau " + std::to_string(tau);
        const DecompositionTree tree = decompose(region, {tau, measure, 0.1, 1.0});
        const std::vector<Piece> pieces = tree.pieces_at(tau);
        expect_contract(region, pieces, tau, measure, what, GetParam().large ? 100 : 400);
        if (fraction == 0.01 && !GetParam().large) check_tree(region, tree, measure, what);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Polygons, SampleModels,
    ::testing::Values(Model{"misc/BarbedThing.poly", false}, Model{"misc/batlogo.poly", false},
                      Model{"misc/bird.poly", false}, Model{"misc/egg.poly", false},
                      Model{"misc/hole1.poly", false}, Model{"misc/hole2.poly", false},
                      Model{"misc/hole3.poly", false}, Model{"misc/hole4.poly", false},
                      Model{"misc/mammoth.poly", false}, Model{"misc/simple1.poly", false},
                      Model{"misc/simple2.poly", false}, Model{"misc/simple3.poly", false},
                      Model{"misc/simple4.poly", false}, Model{"misc/simple6.poly", false},
                      Model{"misc/star3.poly", false}, Model{"misc/star4.poly", false},
                      Model{"misc/texas.poly", false}, Model{"misc/torus1.poly", false},
                      Model{"misc/wierd2.poly", false}, Model{"nazca/nazca_heron.poly", false},
                      Model{"nazca/nazca_monkey.poly", false}, Model{"neuron/neuron.poly", false},
                      Model{"nazca/nazca_heron_2.poly", true},
                      Model{"nazca/nazca_monkey_2.poly", true}),
    [](const auto& info) {
      std::string name = std::filesystem::path(info.param.file).stem().string();
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

// Random star-shaped polygons, spirals (pockets that fold back: SP and H1 differ from SL) and
// star-shaped holes in a grid, with a fixed seed.
Region random_star(std::mt19937& random, Vec2 center, double radius, int n, double spread) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(unit(random) * 2 * M_PI);
  std::sort(angles.begin(), angles.end());
  Region region;
  for (double a : angles) {
    const double r = radius * (1.0 - spread * unit(random));
    region.outer.push_back({center.x + r * std::cos(a), center.y + r * std::sin(a)});
  }
  return region;
}

Region spiral(std::mt19937& random, double turns, int steps) {
  std::uniform_real_distribution<double> noise(-0.02, 0.02);
  Region region;
  Ring inner;
  for (int i = 0; i <= steps; ++i) {
    const double a = turns * 2 * M_PI * i / steps;
    const double r = 1.0 + 0.5 * a;
    region.outer.push_back({(r + 0.3 + noise(random)) * std::cos(a), (r + 0.3) * std::sin(a)});
    inner.push_back({(r + noise(random)) * std::cos(a), r * std::sin(a)});
  }
  region.outer.insert(region.outer.end(), inner.rbegin(), inner.rend());
  return region;
}

TEST(RandomPolygons, ContractAndIndependentConcavity) {
  std::mt19937 random(2024);
  std::vector<Region> shapes;
  for (int i = 0; i < 12; ++i) shapes.push_back(random_star(random, {0, 0}, 10, 8 + 4 * i, 0.7));
  for (int i = 0; i < 4; ++i) shapes.push_back(spiral(random, 1.5 + 0.5 * i, 30 + 10 * i));
  for (int i = 0; i < 6; ++i) {
    Region region = random_star(random, {0, 0}, 20, 40, 0.15);
    for (int hx = -1; hx <= 1; ++hx) {
      for (int hy = -1; hy <= 1; ++hy) {
        if ((hx + hy + i) % 2 == 0) continue;
        Ring hole = random_star(random, {hx * 5.0, hy * 5.0}, 2.0, 6 + i, 0.6).outer;
        region.holes.push_back(hole);
      }
    }
    shapes.push_back(region);
  }
  int sp_checked = 0;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    Region region;
    try {
      region = clean_and_validate({shapes[s]}, "random")[0];
    } catch (const std::exception&) {
      continue;
    }
    const double radius = enclosing_radius({region});
    // The library's shortest paths against Dijkstra on the visibility graph.
    if (region.holes.empty()) {
      const std::vector<double> expected = brute_sp_vertex_concavity(region.outer);
      const std::vector<double> actual = outer_vertex_concavity(region.outer, Measure::sp);
      for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_NEAR(actual[i], expected[i], 1e-9 * (1 + expected[i]))
            << "shape " << s << " vertex " << i;
      }
      ++sp_checked;
    }
    for (Measure measure : kMeasures) {
      for (double fraction : {0.0, 0.005, 0.05, 0.2}) {
        const double tau = fraction * radius;
        const std::string what = "shape " + std::to_string(s) + " " + measure_name(measure) +
                                 " tau " + std::to_string(tau);
        const DecompositionTree tree = decompose(region, {tau, measure, 0.1, 1.0});
        expect_contract(region, tree.pieces_at(tau), tau, measure, what, 200);
        if (fraction == 0.005) check_tree(region, tree, measure, what);
      }
    }
  }
  EXPECT_GE(sp_checked, 12);
}

// A block whose top is a comb of leaning teeth: each pocket between two tooth tips holds tips
// that overhang their valleys, so its chain runs back along the bridge in places and forward in
// others. The shortest paths cut such a pocket at chords from the vertices the chain passes only
// once along the bridge, measure the forward parts straight and the others by the funnel: every
// vertex must still get its shortest path, here against Dijkstra on the visibility graph.
Region leaning_comb(std::mt19937& random, int teeth) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pitch = 10.0;
  Ring top;  // right to left, as a counter-clockwise ring runs along its top
  for (int k = teeth - 1; k >= 0; --k) {
    const double x0 = k * pitch + 1.0;
    const double width = 2.0 + 3.0 * unit(random);
    const double gap = pitch - width;
    const double lean = (unit(random) * 2.0 - 1.0) * 0.9 * gap;  // overhangs, never touches
    const double height = 4.0 + 12.0 * unit(random);
    const double floor = 1.0 + 2.0 * unit(random);
    top.push_back({x0 + width + 0.5 * gap, floor});
    top.push_back({x0 + width, 3.0 + unit(random)});
    top.push_back({x0 + width + lean, height});
    top.push_back({x0 + lean + 0.5 * width * unit(random), height + 1.0 + unit(random)});
    top.push_back({x0 + lean, height - 0.5 * unit(random)});
    top.push_back({x0, 3.0 + unit(random)});
  }
  Region region;
  region.outer.push_back({-10.0, -5.0});
  region.outer.push_back({teeth * pitch + 10.0, -5.0});
  for (Vec2 p : top) region.outer.push_back(p);
  return region;
}

TEST(ShortestPaths, PocketsCutAtChordsMatchDijkstra) {
  std::mt19937 random(20261202);
  int checked = 0;
  for (int shape = 0; shape < 40; ++shape) {
    Region region;
    try {
      region = clean_and_validate({leaning_comb(random, 3 + shape % 6)}, "comb")[0];
    } catch (const std::exception&) {
      continue;
    }
    SCOPED_TRACE("comb " + std::to_string(shape));
    const std::vector<double> expected = brute_sp_vertex_concavity(region.outer);
    const std::vector<double> actual = outer_vertex_concavity(region.outer, Measure::sp);
    int beyond_straight_line = 0;
    const std::vector<double> straight = outer_vertex_concavity(region.outer, Measure::sl);
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_NEAR(actual[i], expected[i], 1e-9 * (1 + expected[i])) << "vertex " << i;
      if (expected[i] > straight[i] * (1 + 1e-6)) ++beyond_straight_line;
    }
    EXPECT_GT(beyond_straight_line, 0);  // some tip overhangs a vertex: the funnel had work
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

// Small inputs on which fuzzing the decomposer (issue 3, 2026-12-01) broke the contract: near-
// degenerate coordinates, points exactly on bridges, slivers. Each is checked at τ = 0 and two
// relative τ for every measure, every node against a fresh measurement.
TEST(Issue3Fuzz, ContractOnEachReproducer) {
  const std::pair<const char*, const char*> reproducers[] = {
      {"A_hole_joined_into_pocket_with_bridge_point",
       "2\n5 out\n8 5\n7 5\n6 7\n5 8\n1 1\n1 2 3 4 5\n3 in\n5 7\n5 6\n4 6\n1 2 3\n"},
      {"B_sp_h1_pocket_with_bridge_point_overestimate",
       "1\n9 out\n0 20\n3 16\n0 3\n4 13\n7 10\n2 5\n5 11\n0 2\n19 3\n1 2 3 4 5 6 7 8 9\n"},
      {"C1_exactly_cw_triangle_accepted_as_ccw",
       "1\n3 out\n-3857.600611386481 -4768.1008694683533\n-822.02518108401205 "
       "-6285.8885846195881\n695.7625340672223 -7044.7824421952055\n1 2 3\n"},
      {"C2_sp_zero_for_subulp_notch",
       "1\n4 out\n567.00180505868536 -271.35592824723085\n664.96898774390843 "
       "-152.7641381897156\n716.53057232282447 -49.64083673551238\n768.09215690174062 "
       "53.482464718691062\n1 2 3 4\n"},
      {"D_sliver_piece_zero_float_area",
       "1\n6 out\n-78.493865772402046 328.99614260651038\n-346.73779416721209 "
       "-475.73564257791958\n-1151.4695793516421 -743.97957097272956\n-614.98172256202201 "
       "-1280.4674277623494\n-1151.4695793516421 -1816.9552845519697\n-78.493865772402046 "
       "-2889.9309981312094\n1 2 3 4 5 6\n"},
      // A piece inherits the vertex nearest to a hole's end only if no other was as near: here
      // two are, and the piece numbers its vertices from another start than the parent.
      {"E_tied_nearest_vertex_of_hole_end",
       "5\n3 out\n0 0\n16 0\n0 19\n1 2 3\n3 in\n7 4\n8 4\n6 3\n1 2 3\n3 in\n3 5\n4 7\n5 7\n1 2 "
       "3\n3 in\n8 2\n9 4\n10 3\n1 2 3\n4 in\n6 6\n8 6\n8 5\n6 5\n1 2 3 4\n"},
      // A piece cut along a hole has that hole's chain on its outer ring: the parent's nearest
      // vertex of ∂P0 stays the piece's only if the chain lies farther.
      {"F_cut_hole_chain_nearer_than_inherited_outer_vertex",
       "5\n3 out\n6.3214089685216805 6.0882267092229228\n-5.849096688321139 6.8283503503725944\n"
       "7.288420557163322 -6.7738361191772052\n1 2 3\n3 in\n3.3329687373499448 "
       "3.2623782136186774\n1.9044423356973397 4.2370792224076679\n3.5212359029162101 "
       "4.3735134134198796\n1 2 3\n3 in\n3 1\n3 0\n2 0\n1 2 3\n3 in\n3.6782523864786825 "
       "1.1256208236202898\n3.3394339448187877 1.4738485212707955\n3.762580359996103 "
       "1.389401169304544\n1 2 3\n3 in\n1 4\n2 2\n1 3\n1 2 3\n"},
  };
  for (const auto& [name, text] : reproducers) {
    const std::vector<Region> regions = clean_and_validate(parse_poly(text, name), name);
    const double radius = enclosing_radius(regions);
    for (const Region& region : regions) {
      for (Measure measure : kMeasures) {
        for (double fraction : {0.0, 0.01, 0.1}) {
          const double tau = fraction * radius;
          const std::string what =
              std::string(name) + " " + measure_name(measure) + " tau " + std::to_string(tau);
          const DecompositionTree tree = decompose(region, {tau, measure, 0.1, 1.0});
          expect_contract(region, tree.pieces_at(tau), tau, measure, what, 200);
          check_tree(region, tree, measure, what);
        }
      }
    }
  }
}

TEST(Decompose, ConvexInputIsOnePieceAndSettingsAreChecked) {
  const Region square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  const auto pieces = decompose(square, {0.0, Measure::h1, 0.1, 1.0}).pieces_at(0.0);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].concavity, 0.0);
  EXPECT_DOUBLE_EQ(convexity(pieces), 1.0);
  EXPECT_THROW(decompose(square, {-1.0, Measure::h1, 0.1, 1.0}), std::invalid_argument);
  // Non-finite weights would make Eq. 8's scores NaN, which cannot be ordered (review of issue 3).
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  EXPECT_THROW(decompose(square, {0.0, Measure::sl, kInfinity, 1.0}), std::invalid_argument);
  EXPECT_THROW(decompose(square, {0.0, Measure::sl, -0.1, 1.0}), std::invalid_argument);
  EXPECT_THROW(decompose(square, {0.0, Measure::sl, 0.1, 0.0}), std::invalid_argument);
  EXPECT_THROW(decompose(square, {0.0, Measure::sl, 0.1, std::nan("")}), std::invalid_argument);
  EXPECT_EQ(parse_measure("sp"), Measure::sp);
  EXPECT_FALSE(parse_measure("SP"));
  EXPECT_STREQ(measure_name(Measure::h2), "h2");
}

TEST(Decompose, HoleIsKeptOnlyWithinTolerance) {
  const Region ring{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
  const double depth = measure_concavity(ring, Measure::h1);
  EXPECT_GT(depth, 0.0);
  const auto kept = decompose(ring, {depth, Measure::h1, 0.1, 1.0}).pieces_at(depth);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].component.holes.size(), 1u);
  const auto opened =
      decompose(ring, {depth * 0.99, Measure::h1, 0.1, 1.0}).pieces_at(depth * 0.99);
  EXPECT_GE(opened.size(), 2u);
  for (const Piece& piece : opened) EXPECT_TRUE(piece.component.holes.empty());
}

// A comb's cuts peel one tooth at a time (every notch is as deep as the next), so a tree that
// kept every split node's outline held a copy of the comb per tooth: 0.5 GB at 16,000 vertices.
// Without coarser levels the split nodes give their outlines up, and the pieces are the same.
TEST(Decompose, TreeWithoutCoarserLevelsHoldsItsLeavesOnlyOnAComb) {
  constexpr int kTeeth = 500;
  // Counter-clockwise: the base from left to right, then the teeth (1 wide, 99 above a base 1
  // thick, 1 apart) from right to left.
  Ring comb{{0, 0}, {2.0 * kTeeth - 1, 0}};
  for (int t = kTeeth - 1; t >= 0; --t) {
    comb.insert(comb.end(), {{2.0 * t + 1, 100}, {2.0 * t, 100}});
    if (t > 0) comb.insert(comb.end(), {{2.0 * t, 1}, {2.0 * t - 1, 1}});
  }
  const Region region = clean_and_validate({Region{comb, {}}}, "comb")[0];
  const std::size_t n = region.outer.size();
  for (Measure measure : {Measure::sl, Measure::h1}) {
    SCOPED_TRACE(measure_name(measure));
    DecomposeSettings settings{1.0, measure};
    const DecompositionTree kept = decompose(region, settings);
    settings.keep_coarser_levels = false;
    const DecompositionTree leaves = decompose(region, settings);
    ASSERT_EQ(kept.nodes().size(), leaves.nodes().size());
    std::size_t kept_vertices = 0, leaf_vertices = 0;
    for (std::size_t id = 0; id < kept.nodes().size(); ++id) {
      const auto& node = leaves.nodes()[id];
      EXPECT_EQ(node.component.outer.empty(), !node.is_leaf());
      kept_vertices += kept.nodes()[id].component.outer.size();
      leaf_vertices += node.component.outer.size();
    }
    // Kept: a copy of the comb per tooth, about n^2 / 8 vertices; leaves: the comb's own, once
    // (plus each cut's two ends).
    EXPECT_GT(kept_vertices, 10 * n);
    EXPECT_LT(leaf_vertices, 2 * n);
    const std::vector<Piece> a = kept.pieces_at(1.0), b = leaves.pieces_at(1.0);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].component.outer, b[k].component.outer);
      EXPECT_EQ(a[k].hull, b[k].hull);
    }
    EXPECT_GT(kept.pieces_at(1000.0).size(), 0u);
    EXPECT_THROW(leaves.pieces_at(1000.0), std::logic_error);
    // Keeping one coarser level: the root, here, and no copy of the comb per tooth.
    settings.kept_levels = {1000.0};
    const DecompositionTree root_kept = decompose(region, settings);
    std::size_t root_kept_vertices = 0;
    for (const auto& node : root_kept.nodes()) root_kept_vertices += node.component.outer.size();
    EXPECT_LT(root_kept_vertices, 3 * n);
    const std::vector<Piece> whole = root_kept.pieces_at(1000.0);
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0].component.outer, region.outer);
  }
}

// Trees that keep only the levels to be read give those levels' pieces exactly as a tree that
// keeps every node, on models with holes and under every measure (H2's splits depend on τ).
TEST(Decompose, KeptLevelsReadTheSamePiecesAsTheWholeTree) {
  for (const char* file : {"nazca/nazca_monkey.poly", "neuron/neuron.poly", "misc/hole3.poly"}) {
    const auto path = std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons" / file;
    const std::vector<Region> regions = clean_and_validate(read_poly_file(path.string()), file);
    const double radius = enclosing_radius(regions);
    for (Measure measure : kMeasures) {
      SCOPED_TRACE(std::string(file) + " " + measure_name(measure));
      DecomposeSettings settings{0.01 * radius, measure};
      const std::vector<double> levels{0.03 * radius, 0.1 * radius, 0.3 * radius};
      const DecompositionTree whole = decompose(regions[0], settings);
      settings.keep_coarser_levels = false;
      settings.kept_levels = levels;
      const DecompositionTree kept = decompose(regions[0], settings);
      std::size_t dropped = 0;
      for (const auto& node : kept.nodes()) dropped += node.component.outer.empty();
      for (double tau : {levels[0], levels[1], levels[2], settings.tau}) {
        const std::vector<Piece> a = whole.pieces_at(tau), b = kept.pieces_at(tau);
        ASSERT_EQ(a.size(), b.size()) << tau;
        for (std::size_t k = 0; k < a.size(); ++k) {
          EXPECT_EQ(a[k].component.outer, b[k].component.outer);
          EXPECT_EQ(a[k].component.holes, b[k].component.holes);
          EXPECT_EQ(a[k].hull, b[k].hull);
        }
      }
      // Some split node is a piece of no kept level (else nothing was saved).
      if (measure == Measure::h1) {
        EXPECT_GT(dropped, 0u);
      }
    }
  }
}

// Models scaled towards either end of the coordinates .poly files accept (spans from 1e-140,
// coordinates to 1e150) decompose within the contract. Before the enclosing circle was computed
// on scaled differences, τ = 1% of R was 0 for the monkey at 1e-140 (445 pieces instead of 105)
// and infinite at 1e140 (1 piece). Scaling by a power of two is exact, so the pieces are checked
// scaled back, at the model's own size (where the contract's tolerances mean what they say). The
// pieces are not the model's scaled bit for bit: Eq. 8 scores a diagonal by 1 + sc concave(x),
// which mixes a pure number with a length, so the diagonals chosen depend on the units.
TEST(Decompose, ModelsScaledTowardsTheCoordinateBoundsKeepTheContract) {
  for (const char* file : {"nazca/nazca_monkey.poly", "neuron/neuron.poly", "misc/hole3.poly"}) {
    const auto path = std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons" / file;
    const std::vector<Region> regions = read_poly_file(path);
    ASSERT_EQ(regions.size(), 1u) << file;
    const double radius = enclosing_radius(regions), tau = 0.01 * radius;
    for (Measure measure : {Measure::sl, Measure::h1}) {
      const std::size_t unscaled_count =
          decompose(regions[0], {tau, measure, 0.1, 1.0}).pieces_at(tau).size();
      for (int exponent : {-440, -60, 60, 440}) {
        const std::string what = std::string(file) + " " + measure_name(measure) + " scaled by 2^" +
                                 std::to_string(exponent);
        auto scale_ring = [](Ring ring, int by) {
          for (Vec2& p : ring) p = {std::ldexp(p.x, by), std::ldexp(p.y, by)};
          return ring;
        };
        Region scaled{scale_ring(regions[0].outer, exponent), {}};
        for (const Ring& hole : regions[0].holes)
          scaled.holes.push_back(scale_ring(hole, exponent));
        // Cleaned as a file holding the scaled model would be.
        const std::vector<Region> cleaned = clean_and_validate({scaled}, what);
        ASSERT_EQ(cleaned.size(), 1u);
        const double scaled_radius = enclosing_radius(cleaned);
        ASSERT_EQ(scaled_radius, std::ldexp(radius, exponent)) << what;
        const double scaled_tau = 0.01 * scaled_radius;
        std::vector<Piece> pieces =
            decompose(cleaned[0], {scaled_tau, measure, 0.1, 1.0}).pieces_at(scaled_tau);
        for (Piece& piece : pieces) {
          piece.component.outer = scale_ring(piece.component.outer, -exponent);
          for (Ring& hole : piece.component.holes) hole = scale_ring(hole, -exponent);
          piece.hull = scale_ring(piece.hull, -exponent);
          piece.concavity = std::ldexp(piece.concavity, -exponent);
        }
        expect_contract(regions[0], pieces, tau, measure, what, 100);
        EXPECT_LE(pieces.size(), unscaled_count * 11 / 10) << what;
        EXPECT_GE(pieces.size(), unscaled_count * 9 / 10) << what;
      }
    }
  }
}

}  // namespace
}  // namespace hullcook
