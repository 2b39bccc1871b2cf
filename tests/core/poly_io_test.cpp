// Reading .poly files, and refusing bad ones with a message naming the file, ring and problem.
#include "hullcook/core/poly_io.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace hullcook {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("hullcook_core_" + name);
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& name, const std::string& text) {
  const auto path = write_temp(name, text);
  try {
    read_poly_file(path);
  } catch (const InputError& e) {
    std::filesystem::remove(path);
    return e.what();
  }
  std::filesystem::remove(path);
  return "no error";
}

TEST(PolyIo, ReadsTheFormatExample) {
  const auto path = std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/polygons/POLY_FORMAT.txt";
  std::ifstream file(path);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  auto regions = parse_poly(text, "POLY_FORMAT.txt");
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].outer, (Ring{{10, 10}, {0, 10}, {0, 0}}));  // the order line "3 2 1"
  ASSERT_EQ(regions[0].holes.size(), 1u);
  EXPECT_EQ(regions[1].outer.size(), 4u);
  // The example's hole has two corners on the triangle's diagonal: refused, naming the ring.
  try {
    clean_and_validate(regions, "POLY_FORMAT.txt");
    ADD_FAILURE() << "touching hole accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("region 1 hole 1"), HasSubstr("touches")));
  }
  regions[0].holes[0] = {{1, 2}, {2, 3}, {1, 3}};
  const auto cleaned = clean_and_validate(regions, "POLY_FORMAT.txt");
  EXPECT_GT(signed_area(cleaned[0].outer), 0.0);
  EXPECT_LT(signed_area(cleaned[0].holes[0]), 0.0);  // holes come out clockwise
  EXPECT_DOUBLE_EQ(region_area(cleaned[0]), 50.0 - 0.5);
}

TEST(PolyIo, FollowsTheIndexOrderAndRoundTrips) {
  const auto regions = clean_and_validate(
      parse_poly("1\n4 out # comment\n0 0\n1 1\n1 0\n0 1\n1 3 2 4\n", "x.poly"), "x.poly");
  ASSERT_EQ(regions[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(region_area(regions[0]), 1.0);
  const auto again = parse_poly(format_poly(regions), "y.poly");
  EXPECT_EQ(again[0].outer, regions[0].outer);
}

// As Windows editors save them: a byte order mark, CRLF line ends, tabs and commas.
TEST(PolyIo, ReadsAFileSavedWithAByteOrderMarkAndCrlf) {
  const std::string square = "1\r\n4\tout\r\n0 0\r\n2,0\r\n2 2\r\n0 2\r\n1 2 3 4\r\n";
  const auto plain = parse_poly(square, "plain.poly");
  const auto marked = parse_poly("\xEF\xBB\xBF" + square, "marked.poly");
  ASSERT_EQ(marked.size(), 1u);
  EXPECT_EQ(marked[0].outer, plain[0].outer);
  EXPECT_EQ(marked[0].outer, (Ring{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  // Only at the very start: elsewhere those bytes are a bad token, named with its line.
  EXPECT_THAT(error_of("mark_inside.poly",
                       "1\n\xEF\xBB\xBF"
                       "4 out\n0 0\n2 0\n2 2\n0 2\n1 2 3 4\n"),
              HasSubstr("mark_inside.poly:2"));
}

TEST(PolyIo, CleansRepeatedAndCollinearVertices) {
  const auto regions = clean_and_validate(
      {Region{{{0, 0}, {1, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 1}, {0, 0}}, {}}}, "m");
  EXPECT_EQ(regions[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(signed_area(regions[0].outer), 4.0);
}

TEST(PolyIo, RefusesBadInputNamingFileRingAndProblem) {
  const std::string square = "4 out\n0 0\n10 0\n10 10\n0 10\n1 2 3 4\n";
  EXPECT_THAT(error_of("few.poly", "1\n3 out\n0 0\n1 1\n0 0\n1 2 3\n"),
              AllOf(HasSubstr("few.poly"), HasSubstr("region 1 outer boundary"),
                    HasSubstr("fewer than 3")));
  EXPECT_THAT(error_of("line.poly", "1\n4 out\n0 0\n1 1\n2 2\n3 3\n1 2 3 4\n"),
              AllOf(HasSubstr("line.poly"), HasSubstr("fewer than 3")));
  EXPECT_THAT(error_of("bowtie.poly", "1\n4 out\n0 0\n2 2\n2 0\n0 2\n1 2 3 4\n"),
              AllOf(HasSubstr("bowtie.poly"), HasSubstr("region 1 outer boundary"),
                    HasSubstr("self-intersection")));
  EXPECT_THAT(error_of("eight.poly",
                       "1\n8 out\n0 0\n1 0\n1 1\n0 1\n0 0\n0 -1\n-1 -1\n-1 0\n"
                       "1 2 3 4 5 6 7 8\n"),
              AllOf(HasSubstr("eight.poly"), HasSubstr("region 1 outer boundary")));
  EXPECT_THAT(error_of("nan.poly", "1\n3 out\n0 0\nnan 0\n1 1\n1 2 3\n"),
              AllOf(HasSubstr("nan.poly"), HasSubstr("region 1 outer boundary"),
                    HasSubstr("NaN or infinite")));
  EXPECT_THAT(error_of("inf.poly", "1\n3 out\n0 0\n1e999 0\n1 1\n1 2 3\n"),
              HasSubstr("NaN or infinite"));
  EXPECT_THAT(error_of("outside.poly", "2\n" + square + "3 in\n20 20\n21 20\n21 21\n1 2 3\n"),
              AllOf(HasSubstr("outside.poly"), HasSubstr("region 1 hole 1"), HasSubstr("outside")));
  EXPECT_THAT(error_of("cross.poly", "2\n" + square + "3 in\n5 5\n15 5\n5 7\n1 2 3\n"),
              AllOf(HasSubstr("region 1 hole 1"), HasSubstr("outer boundary")));
  EXPECT_THAT(error_of("holes.poly", "3\n" + square + "4 in\n1 1\n5 1\n5 5\n1 5\n1 2 3 4\n" +
                                         "3 in\n4 4\n7 4\n7 7\n1 2 3\n"),
              AllOf(HasSubstr("region 1"), HasSubstr("holes 1 and 2")));
  EXPECT_THAT(error_of("nested.poly", "3\n" + square + "4 in\n1 1\n8 1\n8 8\n1 8\n1 2 3 4\n" +
                                          "3 in\n2 2\n3 2\n3 3\n1 2 3\n"),
              AllOf(HasSubstr("holes 1 and 2"), HasSubstr("overlap")));
  // Stop 57: the holes' boxes are paired through a grid, and the first overlapping pair by index
  // is named, among 400 holes (the outer ring's locator and the grid both at work), though a
  // later pair lies first in x and in y.
  {
    std::string many = "403\n" + square;
    for (int row = 0; row < 20; ++row) {
      for (int column = 0; column < 20; ++column) {
        const double x = 0.2 + 0.45 * column, y = 0.2 + 0.45 * row;
        many += "4 in\n" + std::to_string(x) + " " + std::to_string(y) + "\n" +
                std::to_string(x + 0.2) + " " + std::to_string(y) + "\n" + std::to_string(x + 0.2) +
                " " + std::to_string(y + 0.2) + "\n" + std::to_string(x) + " " +
                std::to_string(y + 0.2) + "\n1 2 3 4\n";
      }
    }
    // Hole 401 inside hole 381 (row 19, column 0: at the least x), and hole 402 inside hole 20
    // (row 0, column 19: at the least y): the pair named is (20, 402), the first by index.
    many += "3 in\n0.25 8.8\n0.3 8.8\n0.3 8.85\n1 2 3\n";
    many += "3 in\n8.8 0.25\n8.85 0.25\n8.85 0.3\n1 2 3\n";
    EXPECT_THAT(error_of("many.poly", many),
                AllOf(HasSubstr("many.poly"), HasSubstr("holes 20 and 402"), HasSubstr("overlap")));
  }
  EXPECT_THAT(error_of("holeself.poly", "2\n" + square + "4 in\n1 1\n3 3\n3 1\n1 3\n1 2 3 4\n"),
              AllOf(HasSubstr("region 1 hole 1"), HasSubstr("self-intersection")));
  EXPECT_THAT(error_of("truncated.poly", "1\n4 out\n0 0\n10 0\n10 10\n"),
              AllOf(HasSubstr("truncated.poly"), HasSubstr("file ends")));
  EXPECT_THAT(error_of("malformed.poly", "1\n3 out\n0 0\n1 x\n1 1\n1 2 3\n"),
              AllOf(HasSubstr("malformed.poly:4"), HasSubstr("'x'")));
  EXPECT_THAT(error_of("count.poly", "2\n" + square), HasSubstr("count.poly"));
  EXPECT_THAT(error_of("extra.poly", "1\n" + square + "3 in\n1 1\n2 1\n2 2\n1 2 3\n"),
              AllOf(HasSubstr("extra.poly"), HasSubstr("chain count")));
  EXPECT_THAT(error_of("index.poly", "1\n3 out\n0 0\n1 0\n1 1\n1 2 4\n"),
              AllOf(HasSubstr("index.poly"), HasSubstr("not in 1..3")));
  EXPECT_THAT(error_of("tag.poly", "1\n3 up\n0 0\n1 0\n1 1\n1 2 3\n"), HasSubstr("'out' or 'in'"));
  EXPECT_THAT(error_of("empty.poly", "# nothing\n"), HasSubstr("empty.poly"));
  EXPECT_THAT(error_of("missing.poly/nope", ""), HasSubstr("missing.poly"));
}

// Below a span of 1e-140 the orientation tests' products of differences reach the subnormal range:
// such rings were cleaned away as "fewer than 3 distinct points", or decomposed into pieces that
// broke the output's contract (exit 4). They are refused by name, and rings just above are kept.
TEST(PolyIo, RefusesRingsTooSmallToOrientExactly) {
  EXPECT_THAT(error_of("tiny.poly",
                       "1\n4 out\n0 0\n3e-170 0\n3e-170 1e-170\n1e-170 2e-170\n"
                       "1 2 3 4\n"),
              AllOf(HasSubstr("tiny.poly"), HasSubstr("region 1 outer boundary: too small"),
                    HasSubstr("3e-170")));
  EXPECT_THAT(error_of("tinyhole.poly",
                       "2\n4 out\n-1 -1\n1 -1\n1 1\n-1 1\n1 2 3 4\n"
                       "3 in\n0 0\n0 1e-150\n1e-150 0\n1 2 3\n"),
              AllOf(HasSubstr("tinyhole.poly"), HasSubstr("region 1 hole 1: too small"),
                    HasSubstr("1e-150")));
  const auto small = write_temp("small.poly",
                                "2\n4 out\n0 0\n4e-140 0\n4e-140 4e-140\n0 4e-140\n1 2 3 4\n"
                                "4 in\n1e-140 1e-140\n1e-140 3e-140\n3e-140 3e-140\n"
                                "3e-140 1e-140\n1 2 3 4\n");
  const std::vector<Region> regions = read_poly_file(small);
  std::filesystem::remove(small);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].outer.size(), 4u);
  ASSERT_EQ(regions[0].holes.size(), 1u);
  EXPECT_EQ(regions[0].holes[0].size(), 4u);
  EXPECT_GT(region_area(regions[0]), 0.0);
}

// The description of the value expected is built only when a token is wrong (issue 22: building
// it for every number was most of a .poly's parsing time); each still names its token.
TEST(PolyIo, Issue22_EachWrongTokenIsNamedByLineChainAndPlace) {
  const std::string square = "4 out\n0 0\n10 0\n10 10\n0 10\n1 2 3 4\n";
  EXPECT_EQ(error_of("n.poly", "one\n" + square),
            std::filesystem::temp_directory_path().string() +
                "/hullcook_core_n.poly:1: expected the number of chains, found 'one'");
  EXPECT_THAT(error_of("count.poly", "2\n" + square + "four in\n"),
              HasSubstr("count.poly:8: expected the vertex count of chain 2, found 'four'"));
  EXPECT_THAT(error_of("x.poly", "1\n4 out\n0 0\n10 0\nten 10\n0 10\n1 2 3 4\n"),
              HasSubstr("x.poly:5: expected x of vertex 3 of chain 1, found 'ten'"));
  EXPECT_THAT(error_of("y.poly", "1\n4 out\n0 0\n10 0\n10 10\n0 ten\n1 2 3 4\n"),
              HasSubstr("y.poly:6: expected y of vertex 4 of chain 1, found 'ten'"));
  EXPECT_THAT(error_of("order.poly", "1\n4 out\n0 0\n10 0\n10 10\n0 10\n1 2 three 4\n"),
              HasSubstr("order.poly:7: expected index 3 of the order of chain 1, found 'three'"));
  EXPECT_THAT(
      error_of("short.poly", "1\n4 out\n0 0\n10 0\n10 10\n0 10\n1 2 3\n"),
      HasSubstr("short.poly:8: file ends where index 4 of the order of chain 1 was expected"));
  // A number missing shifts every later one, and the error surfaces lines later (stop 54's
  // sweep): it points back at the line that held a vertex's x without its y.
  EXPECT_THAT(error_of("missing.poly", "1\n4 out\n0 0\n10\n10 10\n0 10\n1 2 3 4\n"),
              HasSubstr("missing.poly:8: file ends where index 4 of the order of chain 1 was "
                        "expected (line 4 holds a vertex's x without its y: is a number missing "
                        "there?)"));
  // Numbers split across lines on purpose read as before, and are not blamed for a later error.
  EXPECT_EQ(parse_poly("1\n4 out\n0\n0\n10\n0\n10 10\n0 10\n1 2 3 4\n", "split.poly").size(), 1u);
  EXPECT_THAT(error_of("split.poly", "1\n4 out\n0\n0\n10\n0\n10\n10\n0\n10\n1 2 3 x\n"),
              AllOf(HasSubstr("found 'x'"), Not(HasSubstr("without its y"))));
  EXPECT_THAT(error_of("one.poly", "one\n" + square), Not(HasSubstr("without its y")));
}

// The crossing check on zigzags of long diagonal teeth, where each edge's box covers a large part
// of the grid (it once entered every edge in every cell of its box, and took cubic time). The
// expected answer is found by testing every pair: the first edge in ring order that meets a
// non-adjacent edge, and the first edge it meets.

// n teeth of height `height` leaning by `lean`, d apart, closed below: long parallel diagonals.
Ring zigzag(int teeth, double d, double lean, double height) {
  Ring ring;
  for (int k = 0; k < teeth; ++k) {
    ring.push_back({k * d, 0.0});
    ring.push_back({k * d + lean, height});
  }
  const double right = teeth * d + lean + 1.0;
  ring.push_back({right, height});
  ring.push_back({right, -1.0});
  ring.push_back({0.0, -1.0});             // not on the first tooth's line
  std::reverse(ring.begin(), ring.end());  // counter-clockwise, as validation leaves it
  return ring;
}

void move_vertex(Ring& ring, Vec2 from, Vec2 to) {
  const auto at = std::find(ring.begin(), ring.end(), from);
  ASSERT_NE(at, ring.end());
  *at = to;
}

std::string point_text(Vec2 p) {
  char buffer[80];
  std::snprintf(buffer, sizeof buffer, "(%.9g, %.9g)", p.x, p.y);
  return buffer;
}

// The message's "(edge ... meets edge ...)" for the first crossing of every pair, or "" when the
// cleaned ring has none.
std::string crossing_by_every_pair(const Ring& input) {
  Ring ring = remove_degenerate_vertices(input);
  if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent across the seam
      const Vec2 a = ring[i], b = ring[(i + 1) % n], c = ring[j], d = ring[(j + 1) % n];
      if (segments_intersect(a, b, c, d)) {
        return "(edge " + point_text(a) + "-" + point_text(b) + " meets edge " + point_text(c) +
               "-" + point_text(d) + ")";
      }
    }
  }
  return "";
}

std::string validation_error(const Ring& ring) {
  try {
    clean_and_validate({Region{ring, {}}}, "zig.poly");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CrossingCheck, ValidZigzagOfLongDiagonalTeethValidatesUnchanged) {
  const Ring ring = zigzag(400, 2.5, 1000.0, 1000.0);
  const auto regions = clean_and_validate({Region{ring, {}}}, "zig.poly");
  EXPECT_EQ(regions[0].outer, ring);
}

TEST(CrossingCheck, ZigzagWithOneCrossingIsRefusedNamingTheTwoEdges) {
  Ring ring = zigzag(400, 2.5, 1000.0, 1000.0);
  // Tooth 200's tip moves past tooth 199's: both its edges cross that tooth's rising edge, far
  // from any vertex.
  move_vertex(ring, {1500.0, 1000.0}, {1496.0, 1000.0});
  const std::string expected = crossing_by_every_pair(ring);
  EXPECT_EQ(expected, "(edge (502.5, 0)-(1496, 1000) meets edge (500, 0)-(1497.5, 1000))");
  EXPECT_THAT(validation_error(ring),
              AllOf(HasSubstr("zig.poly"), HasSubstr("region 1 outer boundary: self-intersection"),
                    HasSubstr(expected)));
}

// A zigzag of `teeth` 45-degree teeth whose grid cells (floor(sqrt(edges)) a side over the
// vertices' box) have integer sides, so that lattice points can sit on cell boundaries and on the
// teeth's edges at once. Needs floor(sqrt(2 teeth + 3)) to divide 2 teeth.
struct AlignedZigzag {
  Ring ring;
  int side;
  double cell_width, cell_height;
};
AlignedZigzag aligned_zigzag(int teeth, int cell_height) {
  const int side = static_cast<int>(std::sqrt(2.0 * teeth + 3.0));
  const double height = side * cell_height - 1.0;
  AlignedZigzag z{zigzag(teeth, 2.0, height, height), side, 0.0, double(cell_height)};
  z.cell_width = (2.0 * teeth + height + 1.0) / side;
  return z;
}

// Touching at a vertex, touching inside an edge, and collinear overlap, with the meeting points
// on cell boundaries and corners.
TEST(CrossingCheck, TouchingAndCollinearOverlapsOnCellBoundariesAreRefused) {
  const AlignedZigzag z = aligned_zigzag(36, 16);  // 8 cells a side, 25 by 16
  ASSERT_EQ(z.side, 8);
  ASSERT_EQ(z.cell_width, 25.0);
  ASSERT_EQ(crossing_by_every_pair(z.ring), "");
  EXPECT_EQ(validation_error(z.ring), "");
  // Tooth k rises from its valley (2k, 0) to its tip (2k + 127, 127); x = 25i and y = 16j - 1
  // are cell boundaries, and (25, 15) is a cell corner on tooth 5's rising edge.
  auto moved = [&](Vec2 from, Vec2 to) {
    Ring ring = z.ring;
    move_vertex(ring, from, to);
    return ring;
  };
  struct Case {
    const char* what;
    Ring ring;
  };
  const Case cases[] = {
      {"tip on a tooth's edge at a cell corner", moved({133.0, 127.0}, {25.0, 15.0})},
      {"valley on a tooth's edge at a cell corner", moved({20.0, 0.0}, {25.0, 15.0})},
      {"vertex on a vertex", moved({40.0, 0.0}, {50.0, 0.0})},
      {"tip on the bottom edge at a cell boundary", moved({137.0, 127.0}, {100.0, -1.0})},
      // Edges 1 and 5 overlap along x = 5, the boundary between the grid's 2 columns; edge 4
      // ends on edge 1.
      {"collinear overlap along a cell boundary",
       {{0, 0}, {5, 0}, {5, 4}, {10, 4}, {10, 1}, {5, 1}, {5, 3}, {0, 5}}},
  };
  for (const Case& c : cases) {
    const std::string expected = crossing_by_every_pair(c.ring);
    EXPECT_THAT(expected, HasSubstr("meets edge")) << c.what;
    EXPECT_THAT(validation_error(c.ring),
                AllOf(HasSubstr("region 1 outer boundary: self-intersection"), HasSubstr(expected)))
        << c.what;
  }
}

// Many aligned zigzags with one vertex moved to a lattice point on another edge, on a cell
// corner, or anywhere: the check names the same crossing as testing every pair, and accepts
// exactly when every pair does.
TEST(CrossingCheck, AgreesWithEveryPairOnLatticeZigzags) {
  unsigned state = 12345;
  auto next = [&](int bound) {
    state = state * 1103515245u + 12345u;
    return static_cast<int>((state >> 8) % static_cast<unsigned>(bound));
  };
  int refused = 0, accepted = 0;
  for (int trial = 0; trial < 400; ++trial) {
    int teeth = 20 + next(60);
    while ((2 * teeth) % static_cast<int>(std::sqrt(2.0 * teeth + 3.0)) != 0) ++teeth;
    const AlignedZigzag z = aligned_zigzag(teeth, 1 + next(12));
    Ring ring = z.ring;
    const double height = z.cell_height * z.side - 1.0;
    const std::size_t moved = static_cast<std::size_t>(next(static_cast<int>(ring.size())));
    switch (next(3)) {
      case 0: {  // onto a point of a tooth's rising edge
        const double m = next(static_cast<int>(height) + 1);
        ring[moved] = {2.0 * next(teeth) + m, m};
        break;
      }
      case 1:  // onto a cell corner
        ring[moved] = {z.cell_width * next(z.side + 1), -1.0 + z.cell_height * next(z.side + 1)};
        break;
      default:
        ring[moved] = {1.0 * next(static_cast<int>(z.cell_width * z.side) + 1),
                       -1.0 + next(static_cast<int>(height) + 2)};
    }
    if (remove_degenerate_vertices(ring).size() < 3) continue;
    const std::string expected = crossing_by_every_pair(ring);
    const std::string error = validation_error(ring);
    if (expected.empty()) {
      ++accepted;
      EXPECT_THAT(error, Not(HasSubstr("meets edge"))) << trial;
    } else {
      ++refused;
      EXPECT_THAT(error, HasSubstr(expected)) << trial;
    }
  }
  EXPECT_GT(refused, 200);
  EXPECT_GT(accepted, 10);
}

// One huge image's regions are validated on several threads when asked (issue 17): the same
// regions, and the same error (the first region's) when several are broken, whatever the count.
TEST(CrossingCheck, Issue17_ThreadsGiveTheSameRegionsAndTheFirstRegionsError) {
  std::vector<Region> regions;
  for (int k = 0; k < 40; ++k) {
    const Vec2 at{10.0 * k, 0};
    Ring outer{at,
               at + Vec2{8, 0},
               at + Vec2{8, 4},
               at + Vec2{4, 4},
               at + Vec2{4, 4},  // repeated
               at + Vec2{0, 4}};
    Ring hole{at + Vec2{1, 1}, at + Vec2{1, 2}, at + Vec2{2, 2}, at + Vec2{2, 1}};
    regions.push_back(Region{outer, {hole}});
  }
  const std::vector<Region> one = clean_and_validate(regions, "many.poly");
  for (unsigned threads : {2u, 3u, 8u}) {
    const std::vector<Region> many = clean_and_validate(regions, "many.poly", threads);
    ASSERT_EQ(many.size(), one.size());
    for (std::size_t r = 0; r < one.size(); ++r) {
      EXPECT_EQ(many[r].outer, one[r].outer) << threads << " threads, region " << r;
      EXPECT_EQ(many[r].holes, one[r].holes) << threads << " threads, region " << r;
    }
  }
  // Regions 13 and 31 self-intersect (a bow tie): region 13 is named, whatever the count.
  for (int k : {12, 30}) std::swap(regions[k].outer[1], regions[k].outer[2]);
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    try {
      clean_and_validate(regions, "many.poly", threads);
      ADD_FAILURE() << threads << " threads: accepted";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr("many.poly: region 13 outer boundary: self-intersection"))
          << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace hullcook
