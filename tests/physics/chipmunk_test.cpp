// Cooked hulls in a real Chipmunk 7 space, through hullcook::chipmunk.
#include "physics_scene.h"

#include "hullcook/chipmunk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hullcook {
namespace {

using runtime::Bundle;
using runtime::Status;

// Chipmunk lets shapes overlap by its collision slop; we set it to Box2D's 5 mm.
constexpr double kCollisionSlop = 0.005;

struct Scene {
  std::string bytes = test::scene_bundle();
  Bundle bundle;
  cpSpace* space = cpSpaceNew();
  Scene() {
    EXPECT_EQ(bundle.open(bytes.data(), bytes.size()), Status::ok);
    cpSpaceSetGravity(space, cpv(0, -10));
    cpSpaceSetCollisionSlop(space, kCollisionSlop);
    cpSpaceSetIterations(space, 20);
    cpSpaceSetSleepTimeThreshold(space, 0.5);
  }
  ~Scene() { hullcook::chipmunk::free_space_and_contents(space); }

  cpBody* body(const char* name, cpVect position, bool is_static,
               chipmunk::ShapeReport* out = nullptr) {
    cpBody* created =
        is_static ? cpSpaceGetStaticBody(space) : cpSpaceAddBody(space, cpBodyNew(0, 0));
    const runtime::Asset asset = bundle.find(name);
    EXPECT_TRUE(asset) << name;
    if (!is_static) cpBodySetPosition(created, position);
    const chipmunk::ShapeReport report =
        chipmunk::add_shapes(space, created, asset, asset.level(0));
    EXPECT_EQ(report.altered, 0u) << name;
    EXPECT_EQ(report.created, asset.level(0).hull_count()) << name;
    if (out) *out = report;
    return created;
  }
  void settle(double seconds) {
    for (int step = 0; step < static_cast<int>(seconds * 60); ++step) cpSpaceStep(space, 1.0 / 60);
  }
};

TEST(Chipmunk, BodiesComeToRestOnTheTerrainAtThePredictedHeight) {
  Scene scene;
  scene.body("terrain/ground.png", cpvzero, true);
  cpBody* house = scene.body("props/house.png", cpv(-3, 2), false);
  cpBody* ell = scene.body("props/ell.png", cpv(3, 3), false);
  scene.settle(6.0);
  for (cpBody* body : {house, ell}) {
    EXPECT_LT(cpvlength(cpBodyGetVelocity(body)), 0.02);
    EXPECT_NEAR(cpBodyGetAngle(body), 0.0, 0.01);
    EXPECT_NEAR(cpBodyGetPosition(body).y, 0.5, test::kTau + kCollisionSlop);
  }
  EXPECT_NEAR(cpBodyGetPosition(house).x, -3.0, 0.05);
  EXPECT_NEAR(cpBodyGetPosition(ell).x, 3.0, 0.05);
}

TEST(Chipmunk, SegmentQueriesHitWhereTheSilhouetteIs) {
  Scene scene;
  scene.body("terrain/ground.png", cpvzero, true);
  cpBody* house = scene.body("props/house.png", cpv(2, 0.5), false);
  cpBodySetType(house, CP_BODY_TYPE_KINEMATIC);
  cpSpaceReindexShapesForBody(scene.space, house);
  const double error = scene.bundle.find("props/house.png").quantization_error();
  for (double x = -0.45; x <= 0.45; x += 0.05) {
    cpSegmentQueryInfo info{};
    ASSERT_TRUE(cpSpaceSegmentQueryFirst(scene.space, cpv(2 + x, 10), cpv(2 + x, -10), 0,
                                         CP_SHAPE_FILTER_ALL, &info));
    EXPECT_NEAR(info.point.y, 0.5 + test::house_top(x), 2 * error + 1e-6) << "x " << x;
  }
  cpSegmentQueryInfo info{};
  ASSERT_TRUE(cpSpaceSegmentQueryFirst(scene.space, cpv(5, 10), cpv(5, -10), 0, CP_SHAPE_FILTER_ALL,
                                       &info));
  EXPECT_NEAR(info.point.y, 0.0, 1e-4);
}

TEST(Chipmunk, MassMomentAndCentroidFromTheHullsMatchTheSilhouette) {
  Scene scene;
  for (const auto& [name, silhouette, density] :
       {std::tuple{"props/house.png", test::house_silhouette(), 2.0},
        std::tuple{"props/ell.png", test::ell_silhouette(), 1.0}}) {
    chipmunk::ShapeReport report;
    cpBody* body = scene.body(name, cpvzero, false, &report);
    const double error = scene.bundle.find(name).quantization_error();
    const double area = test::ring_area(silhouette);
    EXPECT_NEAR(report.area, area, test::ring_perimeter(silhouette) * error * 2) << name;
    EXPECT_NEAR(cpBodyGetMass(body), density * area,
                density * test::ring_perimeter(silhouette) * error * 2)
        << name;
    const Vec2 centroid = test::ring_centroid(silhouette);
    EXPECT_NEAR(cpBodyGetCenterOfGravity(body).x, centroid.x, 4 * error) << name;
    EXPECT_NEAR(cpBodyGetCenterOfGravity(body).y, centroid.y, 4 * error) << name;
    // The moment about the centroid of the whole silhouette (a polygon's, by cpMomentForPoly).
    std::vector<cpVect> vertices;
    for (const Vec2& p : silhouette) vertices.push_back(cpv(p.x - centroid.x, p.y - centroid.y));
    // cpMomentForPoly needs a convex polygon: sum the hulls of the exact decomposition instead.
    const auto hulls =
        std::string(name) == "props/house.png" ? test::house_hulls() : test::ell_hulls();
    double moment = 0;
    for (const Ring& hull : hulls) {
      std::vector<cpVect> v;
      for (const Vec2& p : hull) v.push_back(cpv(p.x, p.y));
      const double mass = density * test::ring_area(hull);
      moment += cpMomentForPoly(mass, static_cast<int>(v.size()), v.data(),
                                cpv(-centroid.x, -centroid.y), 0);
    }
    EXPECT_NEAR(cpBodyGetMoment(body), moment, 0.01 * moment) << name;
  }
}

// A review (hunt of stop 49): add_shapes gave Chipmunk the first 64 vertices of a hull of more
// (a bundle cooked with --max-verts 0), and Chipmunk made a smaller hull of them.
TEST(Chipmunk, ReviewHullsOfHundredsOfVerticesKeepEveryVertex) {
  const std::vector<Ring> hulls{test::regular_polygon({0, 0}, 5.0, 65),
                                test::regular_polygon({20, 0}, 5.0, 300)};
  const test::HullsBundle round("round", hulls);
  ASSERT_TRUE(round.opened);
  const runtime::Asset& asset = round.asset;
  Scene scene;
  cpBody* body = cpSpaceAddBody(scene.space, cpBodyNew(0, 0));
  const chipmunk::ShapeReport report =
      chipmunk::add_shapes(scene.space, body, asset, asset.level(0));
  EXPECT_EQ(report.created, 2u);
  EXPECT_EQ(report.altered, 0u);
  EXPECT_EQ(report.skipped, 0u);
  const double area = test::ring_area(hulls[0]) + test::ring_area(hulls[1]);
  EXPECT_NEAR(report.area, area, 1e-4 * area);  // the bundle's grid rounds the vertices
}

TEST(Chipmunk, EveryHullIsAcceptedUnchanged) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Ring> hulls;
  for (int i = 0; i < 300; ++i) {
    const int sides = 3 + static_cast<int>(random() % 14);
    hulls.push_back(test::regular_polygon({10 * unit(random), 10 * unit(random)},
                                          0.05 + 1.5 * unit(random), sides, unit(random) * 6.28));
  }
  const test::HullsBundle random_hulls("random", hulls);
  ASSERT_TRUE(random_hulls.opened);
  const runtime::Asset& asset = random_hulls.asset;
  Scene scene;
  cpBody* body = cpSpaceAddBody(scene.space, cpBodyNew(0, 0));
  EXPECT_EQ(chipmunk::add_shapes(nullptr, body, asset, asset.level(0)).created, 0u);
  const chipmunk::ShapeReport report =
      chipmunk::add_shapes(scene.space, body, asset, asset.level(0));
  EXPECT_EQ(report.created, hulls.size());
  EXPECT_EQ(report.altered, 0u);
  // And each shape, hull by hull: Chipmunk kept every vertex.
  struct Check {
    const runtime::Level level;
    std::size_t shapes = 0, mismatches = 0;
  } check{asset.level(0)};
  cpBodyEachShape(
      body,
      [](cpBody*, cpShape* shape, void* data) {
        auto* c = static_cast<Check*>(data);
        ++c->shapes;
        bool matched = false;
        {
          // Chipmunk may rotate the vertex list: find the hull holding the shape's first vertex
          // and compare the counts.
          for (std::size_t h = 0; h < c->level.hull_count() && !matched; ++h)
            for (std::size_t v = 0; v < c->level.hull(h).vertex_count() && !matched; ++v)
              matched =
                  static_cast<std::size_t>(cpPolyShapeGetCount(shape)) ==
                      c->level.hull(h).vertex_count() &&
                  cpvdist(cpPolyShapeGetVert(shape, 0),
                          cpv(c->level.hull(h).vertex(v).x, c->level.hull(h).vertex(v).y)) < 1e-9;
        }
        c->mismatches += !matched;
      },
      &check);
  EXPECT_EQ(check.shapes, hulls.size());
  EXPECT_EQ(check.mismatches, 0u);
}

}  // namespace
}  // namespace hullcook
