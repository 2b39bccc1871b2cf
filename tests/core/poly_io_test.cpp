// Reading .poly files, and refusing bad ones with a message naming the file, ring and problem.
#include "hullcook/core/poly_io.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace hullcook {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

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

}  // namespace
}  // namespace hullcook
