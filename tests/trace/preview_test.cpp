// The preview: a PNG of the expected size with the drawing on it, or an SVG with the polygons.
#include "hullcook/cook/preview.h"
#include "hullcook/core/error.h"
#include "trace_test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace hullcook {
namespace {

using ::testing::HasSubstr;

// A 32×32 sprite cooked at 32 px per unit around its centre, y up: the square [4, 28]² px cut
// into two pieces at x = 16 px.
CookedAsset hand_made_asset() {
  CookedAsset asset;
  asset.name = "pipe_ur.png";
  asset.image_width = asset.image_height = 32;
  asset.pixels_per_unit = 32;
  asset.transform = {1.0 / 32, {16, 16}, true};
  auto ring = [&](std::initializer_list<Vec2> pixels) {
    Ring out;
    for (Vec2 p : pixels) out.push_back(asset.transform.apply(p));
    return out;
  };
  asset.regions.push_back({ring({{4, 4}, {4, 28}, {28, 28}, {28, 4}}), {}});
  Ring left = ring({{4, 4}, {4, 28}, {16, 28}, {16, 4}});
  Ring right = ring({{16, 4}, {16, 28}, {28, 28}, {28, 4}});
  asset.pieces.push_back({{left, {}}, left, 0.0});
  asset.pieces.push_back({{right, {}}, right, 0.0});
  return asset;
}

const std::filesystem::path kSprite =
    test::sprites_dir() / "pingus__groundpieces__ground__industrial__pipe_ur.png";

TEST(Preview, PngIsScaledUpWithTheDrawingOverTheSprite) {
  const auto dir = test::scratch_dir("preview_png");
  render_preview(kSprite, hand_made_asset(), dir / "drawn.png");
  render_preview(kSprite, CookedAsset{}, dir / "bare.png");
  cv::Mat drawn = cv::imread((dir / "drawn.png").string(), cv::IMREAD_UNCHANGED);
  cv::Mat bare = cv::imread((dir / "bare.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(drawn.empty());
  // 32 px scaled by 16 to reach 512, plus a 16 px margin on each side.
  EXPECT_EQ(drawn.cols, 32 * 16 + 32);
  EXPECT_EQ(drawn.rows, 32 * 16 + 32);
  ASSERT_EQ(bare.size(), drawn.size());
  cv::Mat difference;
  cv::absdiff(drawn, bare, difference);
  cv::Mat grey;
  cv::extractChannel(difference, grey, 2);
  EXPECT_GT(cv::countNonZero(grey), 2000);  // outlines and translucent hulls changed pixels
  // The outline's left edge x = 4 px lands at canvas x = 16 + 4 * 16 = 80, drawn in red.
  cv::Vec3b on_outline = drawn.at<cv::Vec3b>(300, 80);
  EXPECT_GT(on_outline[2], 150);
  EXPECT_LT(on_outline[1], 120);
  EXPECT_LT(on_outline[0], 120);
  // Far outside every hull the canvas is untouched.
  EXPECT_EQ(drawn.at<cv::Vec3b>(5, 5), bare.at<cv::Vec3b>(5, 5));
}

TEST(Preview, SvgContainsThePolygonsInCanvasCoordinates) {
  const auto dir = test::scratch_dir("preview_svg");
  render_preview(kSprite, hand_made_asset(), dir / "drawn.svg");
  std::string svg = test::read_bytes(dir / "drawn.svg");
  EXPECT_THAT(svg,
              HasSubstr("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"544\" height=\"544\""));
  EXPECT_THAT(svg, HasSubstr("data:image/png;base64,"));
  // The outline square [4, 28]² px → canvas [80, 464]².
  EXPECT_THAT(svg, HasSubstr("M80.00 80.00 L80.00 464.00 L464.00 464.00 L464.00 80.00 Z"));
  // The cut at x = 16 px → canvas x = 272, in the components group.
  EXPECT_THAT(svg, HasSubstr("M272.00 80.00 L272.00 464.00"));
  std::size_t hulls = 0;
  for (std::size_t at = svg.find("fill-opacity");
       (at = svg.find("<path fill=", at)) != std::string::npos; ++at)
    ++hulls;
  EXPECT_EQ(hulls, 2u);
  EXPECT_THAT(svg, HasSubstr("</svg>"));
}

TEST(Preview, PolygonAssetWithoutImageIsFramed) {
  const auto dir = test::scratch_dir("preview_poly");
  render_preview({}, hand_made_asset(), dir / "poly.png");
  cv::Mat drawn = cv::imread((dir / "poly.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(drawn.empty());
  EXPECT_EQ(std::max(drawn.cols, drawn.rows), 512 + 32);
}

TEST(Preview, BadRequestsLeaveNoFile) {
  const auto dir = test::scratch_dir("preview_bad");
  EXPECT_THROW(render_preview(kSprite, hand_made_asset(), dir / "drawn.jpg"), UsageError);
  EXPECT_THROW(render_preview(dir / "missing.png", hand_made_asset(), dir / "drawn.png"),
               InputError);
  EXPECT_THROW(render_preview(kSprite, hand_made_asset(), dir / "no" / "such" / "drawn.png"),
               OutputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace hullcook
