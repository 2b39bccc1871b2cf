// Tracing every sample sprite: the outline agrees with the alpha mask, the rings are valid, the
// topology matches the mask's connected components and simplification stays within its bound.
#include "hullcook/trace/trace.h"
#include "trace_test_util.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <iostream>

namespace hullcook {
namespace {

using test::all_rings;
using test::sprites_dir;

cv::Mat mask_of(const AlphaImage& image, int threshold) {
  cv::Mat alpha(image.height, image.width, CV_8U, const_cast<std::uint8_t*>(image.alpha.data()));
  cv::Mat mask;
  cv::compare(alpha, threshold, mask, cv::CMP_GE);  // 255 where opaque
  return mask;
}

// Every ring simple, no ring meeting another, valid vertices, orientation, holes inside their
// outer ring and outside each other, regions outside each other's solid.
void expect_valid_regions(const std::vector<Region>& regions, const std::string& name) {
  std::vector<const Ring*> rings = all_rings(regions);
  struct Edge {
    std::size_t ring, index;
    Vec2 a, b;
  };
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    ASSERT_GE(ring.size(), 3u) << name;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      Vec2 previous = ring[(i + n - 1) % n], here = ring[i], next = ring[(i + 1) % n];
      Vec2 in = here - previous, out = next - here;
      ASSERT_NE(here, next) << name << ": repeated vertex";
      ASSERT_GT(std::abs(hullcook::cross(in, out)), 1e-12 * glm::length(in) * glm::length(out))
          << name << ": collinear vertex at (" << here.x << ", " << here.y << ")";
      edges.push_back({r, i, here, next});
    }
  }
  for (std::size_t s = 0; s < edges.size(); ++s) {
    const Edge& e = edges[s];
    Vec2 low = glm::min(e.a, e.b), high = glm::max(e.a, e.b);
    for (std::size_t t = s + 1; t < edges.size(); ++t) {
      const Edge& f = edges[t];
      if (std::max(f.a.x, f.b.x) < low.x - 1e-6 || std::min(f.a.x, f.b.x) > high.x + 1e-6 ||
          std::max(f.a.y, f.b.y) < low.y - 1e-6 || std::min(f.a.y, f.b.y) > high.y + 1e-6) {
        continue;
      }
      std::size_t n = rings[e.ring]->size();
      bool adjacent =
          e.ring == f.ring && ((e.index + 1) % n == f.index || (f.index + 1) % n == e.index);
      if (adjacent) continue;  // the collinearity check above excludes folds
      ASSERT_FALSE(test::segments_meet(e.a, e.b, f.a, f.b))
          << name << ": edges meet near (" << e.a.x << ", " << e.a.y << ")";
    }
  }
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const Region& region = regions[i];
    EXPECT_GT(test::ring_area(region.outer), 0) << name;
    for (std::size_t h = 0; h < region.holes.size(); ++h) {
      const Ring& hole = region.holes[h];
      EXPECT_LT(test::ring_area(hole), 0) << name;
      EXPECT_TRUE(test::point_in_ring(hole[0], region.outer)) << name << ": hole outside";
      for (std::size_t k = 0; k < region.holes.size(); ++k) {
        if (k != h) {
          EXPECT_FALSE(test::point_in_ring(hole[0], region.holes[k])) << name;
        }
      }
    }
    for (std::size_t j = 0; j < regions.size(); ++j) {
      if (i == j || !test::point_in_ring(region.outer[0], regions[j].outer)) continue;
      bool in_a_hole = false;
      for (const Ring& hole : regions[j].holes)
        in_a_hole |= test::point_in_ring(region.outer[0], hole);
      EXPECT_TRUE(in_a_hole) << name << ": region " << i << " overlaps region " << j;
    }
  }
}

// The acceptance check: pixels more than 2 px from the mask's boundary that the traced
// outline classifies differently stay under 0.2% of the mask.
TEST(TraceSprites, OutlineMatchesMaskAwayFromBoundaryOnEverySprite) {
  TraceSettings settings;  // defaults: alpha 128, simplify 0.5 px, specks below 4 px²
  double worst = 0;
  std::string worst_name;
  double decode_ms = 0, trace_ms = 0;
  for (const auto& path : test::all_sprites()) {
    const std::string name = path.filename().string();
    AlphaImage image = load_alpha(path, settings);
    TraceResult result = trace_image(path, settings);
    decode_ms += result.decode_ms;
    trace_ms += result.trace_ms;
    ASSERT_EQ(result.width, image.width);
    expect_valid_regions(result.regions, name);

    cv::Mat mask = mask_of(image, settings.alpha);
    cv::Mat padded, inside_distance, outside_distance, inverse;
    cv::copyMakeBorder(mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
    cv::distanceTransform(padded, inside_distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    cv::bitwise_not(padded, inverse);
    cv::distanceTransform(inverse, outside_distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    std::vector<std::uint8_t> traced = test::rasterize(result.regions, image.width, image.height);
    std::size_t wrong = 0, far = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        bool opaque = mask.at<std::uint8_t>(y, x) != 0;
        // Centre-to-centre distance to the other class; the boundary is half a pixel nearer.
        float distance = opaque ? inside_distance.at<float>(y + 1, x + 1)
                                : outside_distance.at<float>(y + 1, x + 1);
        if (distance - 0.5f <= 2.0f) continue;
        ++far;
        if ((traced[static_cast<std::size_t>(y) * image.width + x] != 0) != opaque) ++wrong;
      }
    }
    const double mask_pixels = cv::countNonZero(mask);
    const double ratio = mask_pixels > 0 ? wrong / mask_pixels : 0.0;
    EXPECT_LT(ratio, 0.002) << name << ": " << wrong << " of " << far << " far pixels wrong";
    if (ratio >= worst) worst = ratio, worst_name = name;
  }
  std::cout << "[ figures  ] worst misclassified ratio " << worst << " (" << worst_name
            << "); decode " << decode_ms << " ms, trace " << trace_ms << " ms for all sprites\n";
}

int components(const cv::Mat& binary, int connectivity) {
  cv::Mat labels;
  return cv::connectedComponents(binary, labels, connectivity) - 1;  // minus the zero label
}

// Regions = 8-connected opaque components; holes = 4-connected transparent components not
// reaching the image border (the image is padded with transparency).
TEST(TraceSprites, RegionsAndHolesMatchConnectedComponents) {
  const std::vector<std::string> chosen{
      "pingus__groundpieces__bridge__space__grid1.png",        // a lattice: 24 holes
      "frozen-bubble__menu__fblogo-mask.png",                  // lettering with holes
      "frozen-bubble__font.png",                               // many glyphs, holes, specks
      "pingus__traps__spike.png",                              // many blobs with holes
      "pingus__worldobjs__teleporter.png",                     // thin, semi-transparent
      "pingus__textures__green_tendrils.png",                  // holes and diagonal contacts
      "teeworlds__game.png",                                   // a sprite sheet
      "pingus__groundpieces__ground__signposts__danger.png"};  // 2-bit palette
  TraceSettings settings;
  settings.min_blob_area = 0;
  settings.min_hole_area = 0;
  for (const std::string& name : chosen) {
    AlphaImage image = load_alpha(sprites_dir() / name, settings);
    TraceResult result = trace_alpha(image, settings);
    cv::Mat padded;
    cv::copyMakeBorder(mask_of(image, settings.alpha), padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
    cv::Mat background;
    cv::bitwise_not(padded, background);
    std::size_t holes = 0;
    for (const Region& region : result.regions) holes += region.holes.size();
    EXPECT_EQ(static_cast<int>(result.regions.size()), components(padded, 8)) << name;
    EXPECT_EQ(static_cast<int>(holes), components(background, 4) - 1) << name;
    expect_valid_regions(result.regions, name);
  }
}

// Every point of the unsimplified outline lies within eps of the simplified one.
TEST(TraceSprites, SimplificationErrorIsBounded) {
  const std::vector<std::string> chosen{
      "teeworlds__skins__body__standard.png", "frozen-bubble__menu__fblogo-mask.png",
      "pingus__groundpieces__ground__jungle__carabatree.png", "pingus__hotspots__space__engine.png",
      "frozen-bubble__balls__bubble-1-mini.png"};
  for (const std::string& name : chosen) {
    AlphaImage image = load_alpha(sprites_dir() / name, TraceSettings{});
    TraceSettings exact;
    exact.simplify = 0;
    TraceResult original = trace_alpha(image, exact);
    for (double eps : {0.5, 2.0}) {
      TraceSettings settings;
      settings.simplify = eps;
      TraceResult simplified = trace_alpha(image, settings);
      ASSERT_EQ(simplified.regions.size(), original.regions.size()) << name;
      std::vector<const Ring*> rings = all_rings(simplified.regions);
      double worst = 0;
      for (const Ring* ring : all_rings(original.regions)) {
        for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
          Vec2 midpoint = ((*ring)[i] + (*ring)[(i + 1) % n]) / 2.0;
          worst = std::max({worst, test::distance_to_rings((*ring)[i], rings),
                            test::distance_to_rings(midpoint, rings)});
        }
      }
      EXPECT_LE(worst, eps + 1e-9) << name << " eps " << eps;
      std::size_t vertices = 0;
      for (const Ring* ring : rings) vertices += ring->size();
      EXPECT_LT(vertices, original.traced_vertices) << name << ": simplification removed nothing";
      expect_valid_regions(simplified.regions, name);
    }
  }
}

// An outline simplified with a bound larger than the sprite drops most of its vertices: an outer
// boundary whose chord passed on the far side of one of its holes left that hole outside it, to
// its right, where the nesting check (the first ring met leftwards) still took the outer boundary
// for its parent, and the cook refused the image as invalid ("hole 1 is outside the outer
// boundary"). Found by --simplify 64 and --simplify 1e9 on these three sprites.
TEST(TraceSprites, CoarseSimplificationKeepsEveryHoleInsideItsOuterBoundary) {
  const std::vector<std::string> chosen{"pingus__groundpieces__ground__foliage__oak1.png",
                                        "pingus__hotspots__space__engine.png",
                                        "teeworlds__mapres__jungle_midground.png"};
  for (const std::string& name : chosen) {
    AlphaImage image = load_alpha(sprites_dir() / name, TraceSettings{});
    const TraceResult original = trace_alpha(image, TraceSettings{});
    for (double eps : {64.0, 1e9}) {
      TraceSettings settings;
      settings.simplify = eps;
      TraceResult simplified = trace_alpha(image, settings);
      ASSERT_EQ(simplified.regions.size(), original.regions.size()) << name << " eps " << eps;
      // (Regions are ordered by their top-left vertex, which simplification moves.)
      EXPECT_EQ(all_rings(simplified.regions).size(), all_rings(original.regions).size()) << name;
      expect_valid_regions(simplified.regions, name + " eps " + std::to_string(eps));
    }
  }
}

}  // namespace
}  // namespace hullcook
