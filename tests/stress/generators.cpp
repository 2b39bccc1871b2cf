#include "generators.h"

#include "random.h"
#include "shapes.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/core/predicates.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <sstream>

namespace hullcook::stress {
namespace {

constexpr double kPi = std::numbers::pi;

// A shape in its own units before placement.
struct Shape {
  std::vector<Region> regions;
  std::ostringstream description;
  double thinnest = 0;  // the narrowest wall, gap or margin drawn
};

enum class HoleShape { rectangle, rounded, octagon, diamond, circle, hexagon };

const char* hole_shape_name(HoleShape shape) {
  switch (shape) {
    case HoleShape::rectangle:
      return "rectangle";
    case HoleShape::rounded:
      return "rounded";
    case HoleShape::octagon:
      return "octagon";
    case HoleShape::diamond:
      return "diamond";
    case HoleShape::circle:
      return "circle";
    case HoleShape::hexagon:
      return "hexagon";
  }
  return "?";
}

// The parameters of one kind of hole, drawn once per case so that a row or grid repeats them.
struct HoleStyle {
  HoleShape shape = HoleShape::rectangle;
  double corner = 0.3;  // rounded: radius, octagon: chamfer, as a fraction of the shorter side
  int segments = 3;     // rounded: edges per corner; circle: sides
  double phase = 0.0;   // hexagon, circle: angle of the first vertex
};

HoleStyle draw_style(Random& random, HoleShape shape) {
  HoleStyle style;
  style.shape = shape;
  style.corner = random.uniform(0.1, 0.45);
  style.segments = shape == HoleShape::circle ? random.integer(8, 40) : random.integer(1, 6);
  style.phase =
      shape == HoleShape::hexagon ? (random.chance(0.5) ? 0.0 : kPi / 6) : random.uniform(0, kPi);
  return style;
}

// A counter-clockwise ring inside box (touching it on at least one side).
Ring hole_in(const Box& box, const HoleStyle& style) {
  const double side = std::min(box.width(), box.height());
  switch (style.shape) {
    case HoleShape::rectangle:
      return rectangle(box);
    case HoleShape::rounded:
      return rounded_rectangle(box, style.corner * side, style.segments);
    case HoleShape::octagon:
      return octagon(box, style.corner * side);
    case HoleShape::diamond:
      return diamond(box);
    case HoleShape::circle:
      return regular_polygon(box.center(), side / 2, style.segments, style.phase);
    case HoleShape::hexagon:
      return regular_polygon(box.center(), side / 2, 6, style.phase);
  }
  return rectangle(box);
}

// A wall thickness: the thin value d, or an ordinary one.
double wall(Random& random, double d, double ordinary_low, double ordinary_high) {
  return random.chance(0.5) ? d : random.uniform(ordinary_low, ordinary_high);
}

Shape thin_wall(Random& random) {
  Shape shape;
  const double d = random.pick(std::vector<double>{0.01, 0.1, 0.3, 1.0, 3.0});
  const int columns = random.integer(1, 4), rows = random.integer(1, 2);
  const HoleShape kind = random.pick(std::vector<HoleShape>{HoleShape::rectangle,
                                                            HoleShape::octagon, HoleShape::diamond,
                                                            HoleShape::circle, HoleShape::rounded});
  const HoleStyle style = draw_style(random, kind);
  // The walls across (left margin, gaps, right margin), then up (bottom, gaps, top): each d or
  // ordinary, and one at least d.
  std::vector<double> walls(static_cast<std::size_t>(columns + rows) + 2);
  for (double& w : walls) w = wall(random, d, 0.5, 4.0);
  walls[static_cast<std::size_t>(random.integer(0, columns + rows + 1))] = d;
  const double* across = walls.data();
  const double* up = walls.data() + columns + 1;
  std::vector<double> widths(static_cast<std::size_t>(columns)),
      heights(static_cast<std::size_t>(rows));
  for (double& w : widths) w = random.uniform(3, 12);
  for (double& h : heights) h = random.uniform(3, 12);
  Region region;
  double y = up[0];
  for (int j = 0; j < rows; ++j) {
    double x = across[0];
    for (int i = 0; i < columns; ++i) {
      region.holes.push_back(reversed(hole_in({x, y, x + widths[i], y + heights[j]}, style)));
      x += widths[i] + across[i + 1];
    }
    y += heights[j] + up[j + 1];
    if (j + 1 == rows) region.outer = rectangle({0, 0, x, y});
  }
  shape.thinnest = *std::min_element(walls.begin(), walls.end());
  shape.description << "d " << d << ", " << columns << "x" << rows << " " << hole_shape_name(kind)
                    << " holes";
  shape.regions.push_back(std::move(region));
  return shape;
}

Shape grid(Random& random) {
  Shape shape;
  const int columns = random.integer(1, 20);
  const int rows = random.integer(1, 20);
  const HoleShape kind = random.pick(
      std::vector<HoleShape>{HoleShape::rectangle, HoleShape::rounded, HoleShape::octagon});
  const HoleStyle style = draw_style(random, kind);
  const double cell_w = random.uniform(1.5, 10), cell_h = random.uniform(1.5, 10);
  const double w = random.uniform(0.5, 4);       // between holes
  const double margin = random.uniform(0.5, 4);  // to the outer boundary
  const bool jitter = random.chance(0.3);        // holes of different sizes in their cells
  Region region;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const Box cell{margin + i * (cell_w + w), margin + j * (cell_h + w),
                     margin + i * (cell_w + w) + cell_w, margin + j * (cell_h + w) + cell_h};
      Box box = cell;
      if (jitter) {
        const double fx = random.uniform(0.7, 1.0), fy = random.uniform(0.7, 1.0);
        box = {cell.x0, cell.y0, cell.x0 + fx * cell_w, cell.y0 + fy * cell_h};
      }
      region.holes.push_back(reversed(hole_in(box, style)));
    }
  }
  region.outer = rectangle({0, 0, 2 * margin + columns * cell_w + (columns - 1) * w,
                            2 * margin + rows * cell_h + (rows - 1) * w});
  shape.thinnest = std::min(w, margin);
  shape.description << columns << "x" << rows << " " << hole_shape_name(kind) << " holes " << cell_w
                    << "x" << cell_h << ", wall " << w << ", margin " << margin
                    << (jitter ? ", jittered" : "");
  shape.regions.push_back(std::move(region));
  return shape;
}

Shape row(Random& random) {
  Shape shape;
  const HoleShape kind = random.pick(
      std::vector<HoleShape>{HoleShape::diamond, HoleShape::hexagon, HoleShape::circle});
  const HoleStyle style = draw_style(random, kind);
  const int count = random.integer(2, 12);
  const int rows = random.integer(1, 3);
  const double size = random.uniform(2, 10);
  const double stretch = kind == HoleShape::diamond ? random.uniform(0.5, 2.0) : 1.0;
  const double gap = random.chance(0.2) ? random.uniform(0.05, 0.3) : random.uniform(0.3, 4);
  const double margin = random.uniform(0.3, 4);
  const bool honeycomb = rows > 1 && random.chance(0.5);
  const double step_x = size + gap, step_y = size * stretch + gap;
  Region region;
  for (int j = 0; j < rows; ++j) {
    const double shift = honeycomb && j % 2 == 1 ? step_x / 2 : 0.0;
    for (int i = 0; i < count; ++i) {
      const double x = margin + shift + i * step_x, y = margin + j * step_y;
      region.holes.push_back(reversed(hole_in({x, y, x + size, y + size * stretch}, style)));
    }
  }
  const double width = 2 * margin + count * step_x - gap + (honeycomb ? step_x / 2 : 0.0);
  region.outer = rectangle({0, 0, width, 2 * margin + rows * step_y - gap});
  shape.thinnest = std::min(gap, margin);
  shape.description << rows << " rows of " << count << " " << hole_shape_name(kind) << "s, size "
                    << size << ", gap " << gap << ", margin " << margin
                    << (honeycomb ? ", honeycomb" : "");
  shape.regions.push_back(std::move(region));
  return shape;
}

Shape ring(Random& random) {
  Shape shape;
  const int outer_sides = random.chance(0.4) ? 4 : random.integer(3, 64);
  const int hole_sides = random.chance(0.4) ? 4 : random.integer(3, 64);
  const double radius = random.uniform(5, 50);
  const double outer_phase = outer_sides == 4 ? kPi / 4 : random.uniform(0, kPi);
  const double inscribed = radius * std::cos(kPi / outer_sides);
  const double thickness = random.chance(0.3) ? random.pick(std::vector<double>{0.01, 0.1, 0.3})
                                              : random.uniform(0.5, 0.6 * inscribed);
  // The hole's circumcircle keeps thickness from the outer ring's incircle; an eccentric hole
  // moves towards one side, leaving the thin wall there.
  const double eccentric = random.chance(0.4) ? random.uniform(0, 1) : 0.0;
  const double free = inscribed - thickness;
  const double hole_radius = free * random.uniform(0.5, 1.0);
  const double shift = (free - hole_radius) * eccentric;
  const double direction = random.uniform(0, 2 * kPi);
  const Vec2 hole_center = shift * Vec2{std::cos(direction), std::sin(direction)};
  const double hole_phase = hole_sides == 4 ? kPi / 4 : random.uniform(0, kPi);
  shape.regions.push_back(
      {regular_polygon({0, 0}, radius, outer_sides, outer_phase),
       {reversed(regular_polygon(hole_center, hole_radius, hole_sides, hole_phase))}});
  const double hole_inscribed = hole_radius * std::cos(kPi / hole_sides);
  shape.thinnest = std::min(thickness, hole_inscribed);
  const bool disc = random.chance(0.3) && hole_inscribed > 2;
  if (disc) {  // an island in the hole: a second region
    const double gap = random.uniform(0.1, 0.5) * hole_inscribed;
    shape.regions.push_back(
        {regular_polygon(hole_center, hole_inscribed - gap, random.integer(3, 32), 0.0), {}});
    shape.thinnest = std::min(shape.thinnest, gap);
  }
  shape.description << outer_sides << "-gon ring radius " << radius << " around a " << hole_sides
                    << "-gon hole radius " << hole_radius << ", thickness " << thickness
                    << ", shift " << shift << (disc ? ", island" : "");
  return shape;
}

// Distance from the origin to the closest point of the closed ring.
double distance_to_ring(const Ring& ring) {
  double best = INFINITY;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    best = std::min(best, point_segment_distance({0, 0}, ring[i], ring[(i + 1) % ring.size()]));
  }
  return best;
}

Ring random_star(Random& random, Vec2 center, double radius, int vertices, double inner) {
  std::vector<double> angles, radii;
  for (int i = 0; i < vertices; ++i) {
    angles.push_back(2 * kPi * (i + random.uniform(0, 0.8)) / vertices);
    radii.push_back(radius * random.uniform(inner, 1.0));
  }
  return star(center, angles, radii);
}

Shape star_with_holes(Random& random) {
  Shape shape;
  const int vertices = random.integer(5, 60);
  const double radius = random.uniform(10, 60);
  const double inner = random.uniform(0.3, 0.7);
  Region region{random_star(random, {0, 0}, radius, vertices, inner), {}};
  // Holes go in the disc that the star's edges keep clear of around its centre.
  const double clear = distance_to_ring(region.outer);
  const int wanted = random.integer(0, 8);
  const double margin = random.uniform(0.05, 2.0);
  std::vector<std::pair<Vec2, double>> placed;
  for (int attempt = 0; attempt < 20 * wanted && static_cast<int>(placed.size()) < wanted;
       ++attempt) {
    const double hole_radius = random.uniform(0.5, std::max(0.5, clear / 3));
    const double reach = clear - hole_radius - margin;
    if (reach <= 0) break;
    const double r = reach * std::sqrt(random.uniform()), a = random.uniform(0, 2 * kPi);
    const Vec2 center = r * Vec2{std::cos(a), std::sin(a)};
    const bool clear_of_others = std::all_of(placed.begin(), placed.end(), [&](const auto& p) {
      return std::hypot(p.first.x - center.x, p.first.y - center.y) >=
             p.second + hole_radius + margin;
    });
    if (!clear_of_others) continue;
    placed.emplace_back(center, hole_radius);
    Ring hole =
        random.chance(0.5)
            ? regular_polygon(center, hole_radius, random.integer(3, 12), random.uniform(0, kPi))
            : random_star(random, center, hole_radius, random.integer(5, 12), 0.4);
    region.holes.push_back(reversed(std::move(hole)));
  }
  shape.thinnest = margin;
  shape.description << vertices << "-vertex star radius " << radius << " (inner " << inner
                    << ") with " << placed.size() << " holes, margin " << margin;
  shape.regions.push_back(std::move(region));
  return shape;
}

Shape button(Random& random) {
  Shape shape;
  const double width = random.uniform(30, 80), height = random.uniform(10, 24);
  const double t = random.uniform(0.2, 1.5);  // wall between the holes and the outer boundary
  const double outer_chamfer = random.chance(0.5) ? random.uniform(0.3, 2.0) : 0.0;
  const int holes = random.integer(1, 3);
  const double bar = random.uniform(0.3, 4);
  const double hole_width = (width - 2 * t - (holes - 1) * bar) / holes;
  const double hole_height = height - 2 * t;
  // A hole's corner must clear the outer boundary's chamfer line by a positive wall.
  const double chamfer = std::min(std::max(0.0, outer_chamfer - 2 * t) + random.uniform(0.2, 1.0),
                                  0.3 * std::min(hole_width, hole_height));
  Region region;
  region.outer = outer_chamfer > 0 ? octagon({0, 0, width, height}, outer_chamfer)
                                   : rectangle({0, 0, width, height});
  int notches = 0;
  for (int i = 0; i < holes; ++i) {
    const Box box{t + i * (hole_width + bar), t, t + i * (hole_width + bar) + hole_width,
                  height - t};
    Ring hole = octagon(box, chamfer);
    if (random.chance(0.5)) {  // material reaching into the hole from its right side
      ++notches;
      const double depth = random.uniform(0.3, 0.45) * hole_width;
      const double tall = random.uniform(0.2, 0.5) * (hole_height - 2 * chamfer);
      const double y = box.center().y;
      Ring notched;
      for (std::size_t k = 0; k < hole.size(); ++k) {
        notched.push_back(hole[k]);
        if (k == 2) {  // between the right side's two vertices
          notched.push_back({box.x1, y - tall / 2});
          notched.push_back({box.x1 - depth, y - tall / 2});
          notched.push_back({box.x1 - depth, y + tall / 2});
          notched.push_back({box.x1, y + tall / 2});
        }
      }
      hole = std::move(notched);
    }
    region.holes.push_back(reversed(std::move(hole)));
  }
  shape.thinnest = std::min(t, bar);
  shape.description << width << "x" << height << " button, " << holes << " holes (" << notches
                    << " notched), wall " << t << ", bar " << bar << ", outer chamfer "
                    << outer_chamfer;
  shape.regions.push_back(std::move(region));
  return shape;
}

// The least distance from a vertex of ring to an edge not at that vertex.
double least_vertex_edge_distance(const Ring& ring) {
  const std::size_t n = ring.size();
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t e = 0; e < n; ++e) {
      const std::size_t f = (e + 1) % n;
      if (e == v || f == v) continue;
      least = std::min(least, point_segment_distance(ring[v], ring[e], ring[f]));
    }
  }
  return least;
}

// Removes the vertices that (nearly) touch an edge they are not an end of, as thin_wall_defect
// measures it: points on a decimal grid are collinear often, 2-opt does not look at adjacent edges
// (a spike of no width), and an inserted vertex can land on another edge. The contract refuses
// such input as too thin (its sides touch at its resolution), and a case is meant to be valid.
// Where the vertex is next to that edge, the spike's tip (the edge's end between them) goes.
void remove_near_touches(Ring& ring) {
  for (bool removed = true; removed && ring.size() > 3;) {
    removed = false;
    const std::size_t n = ring.size();
    Vec2 low = ring[0], high = ring[0];
    for (Vec2 p : ring) low = glm::min(low, p), high = glm::max(high, p);
    const double reach = 1e-8 * std::max(high.x - low.x, high.y - low.y);
    for (std::size_t v = 0; v < n && !removed; ++v) {
      for (std::size_t e = 0; e < n && !removed; ++e) {
        const std::size_t f = (e + 1) % n;
        if (v == e || v == f) continue;
        if (point_segment_distance(ring[v], ring[e], ring[f]) > reach) continue;
        const std::size_t gone = v == (e + n - 1) % n ? e : v == (f + 1) % n ? f : v;
        ring.erase(ring.begin() + std::ptrdiff_t(gone));
        removed = true;
      }
    }
  }
}

// Hundreds to thousands of nearly collinear vertices: a circle (its radii jittered or not) or a
// rectangle whose sides bulge out by a hair, mostly with a few dense round holes. Their hulls keep
// every vertex, which the engine limits mend and reduce one edge at a time (issue 17: a 4000-vertex
// square took minutes).
Shape dense(Random& random) {
  Shape shape;
  const int count = random.integer(300, 1500);
  Ring outer;
  double half_width = 0, half_height = 0, feature = 0;
  if (random.chance(0.5)) {
    const double radius = random.uniform(5, 200);
    const double jitter = random.pick(std::vector<double>{0.0, 1e-9, 1e-6}) * radius;
    for (int i = 0; i < count; ++i) {
      const double angle = 2 * kPi * i / count;
      outer.push_back((radius + jitter * random.uniform(-1, 1)) *
                      Vec2{std::cos(angle), std::sin(angle)});
    }
    half_width = half_height = radius / std::sqrt(2.0);
    feature = jitter;
    shape.description << count << "-vertex circle radius " << radius << ", jitter " << jitter;
  } else {
    half_width = random.uniform(2.5, 100), half_height = random.uniform(2.5, 100);
    const double bulge =
        random.pick(std::vector<double>{1e-9, 1e-6, 1e-3}) * std::min(half_width, half_height);
    const Vec2 corners[4] = {{-half_width, -half_height},
                             {half_width, -half_height},
                             {half_width, half_height},
                             {-half_width, half_height}};
    const int per_side = count / 4;
    for (int c = 0; c < 4; ++c) {
      const Vec2 from = corners[c], to = corners[(c + 1) % 4];
      const Vec2 outward = glm::normalize(Vec2{to.y - from.y, from.x - to.x});
      for (int i = 0; i < per_side; ++i) {
        const double t = static_cast<double>(i) / per_side;
        outer.push_back(from + (to - from) * t + outward * (bulge * std::sin(kPi * t)));
      }
    }
    feature = bulge;
    shape.description << 2 * half_width << " x " << 2 * half_height << " rectangle, " << per_side
                      << " vertices a side bulging " << bulge;
  }
  // Holes side by side along x, inside the box the outer boundary holds.
  std::vector<Ring> holes;
  double thinnest = std::min(half_width, half_height);
  if (random.chance(0.95)) {
    const int count_of_holes = random.integer(1, 3);
    const double slot = 2 * half_width / count_of_holes;
    const double radius = std::min(slot, 2 * half_height) * random.uniform(0.15, 0.4);
    const int sides = random.integer(60, 600);
    for (int h = 0; h < count_of_holes; ++h) {
      const Vec2 center{-half_width + slot * (h + 0.5), 0.0};
      holes.push_back(reversed(regular_polygon(center, radius, sides, random.uniform(0, kPi))));
    }
    thinnest = std::min({half_height - radius, slot / 2 - radius, radius});
    shape.description << ", " << count_of_holes << " holes of " << sides << " sides, radius "
                      << radius;
  }
  shape.regions.push_back({outer, holes});
  // The placement's rounding keeps the jitter or bulge.
  shape.thinnest = feature > 0 ? std::min(thinnest, feature) : thinnest;
  return shape;
}

// Random points (distinct, on a decimal grid of 1/100 or 1/1000, or anywhere) joined in random
// order, then untangled by 2-opt: while two edges meet (exactly, touching included), the path
// between them is reversed. Some edges then get vertices inserted at a third or a half of their
// length, rounded to the grid: collinear in decimal, a fraction of an ulp off the line in binary
// (the seed that found a contract false alarm and an unplaceable piece at τ 0 had three such
// vertices), or half a grid step off it where the fraction does not fall on the grid.
Shape random_simple(Random& random) {
  Shape shape;
  const int wanted = random.integer(6, 48);
  const int grid = random.pick(std::vector<int>{0, 100, 100, 1000});
  auto on_grid = [&](double x) { return grid > 0 ? std::round(x * grid) / grid : x; };
  Ring points;
  for (int attempt = 0; attempt < 50 * wanted && static_cast<int>(points.size()) < wanted;
       ++attempt) {
    const Vec2 p{on_grid(random.uniform()), on_grid(random.uniform())};
    if (std::find(points.begin(), points.end(), p) == points.end()) points.push_back(p);
  }
  const std::size_t n = points.size();
  for (std::size_t i = n; i > 1; --i) {
    std::swap(points[i - 1], points[static_cast<std::size_t>(random.integer(0, int(i) - 1))]);
  }
  // Each reversal of a crossing shortens the ring, so this ends; the bound is a safeguard (the
  // case is then refused by clean_and_validate and counted as rejected).
  bool tangled = true;
  for (std::size_t pass = 0; pass < 20 * n && tangled; ++pass) {
    tangled = false;
    for (std::size_t i = 0; i < n && !tangled; ++i) {
      for (std::size_t j = i + 2; j < n && !tangled; ++j) {
        if (i == 0 && j == n - 1) continue;
        if (segments_intersect(points[i], points[i + 1], points[j], points[(j + 1) % n])) {
          std::reverse(points.begin() + std::ptrdiff_t(i) + 1,
                       points.begin() + std::ptrdiff_t(j) + 1);
          tangled = true;
        }
      }
    }
  }
  Ring ring;
  int inserted = 0;
  const double insert_chance = random.chance(0.7) ? random.uniform(0.1, 0.5) : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = points[i], b = points[(i + 1) % n];
    ring.push_back(a);
    if (!random.chance(insert_chance)) continue;
    const double t = random.pick(std::vector<double>{0.5, 1.0 / 3, 2.0 / 3});
    const Vec2 p{on_grid(a.x + (b.x - a.x) * t), on_grid(a.y + (b.y - a.y) * t)};
    if (p != a && p != b) ring.push_back(p), ++inserted;
  }
  remove_near_touches(ring);
  if (signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
  shape.thinnest = least_vertex_edge_distance(ring);
  shape.description << n << " random points";
  if (grid > 0) shape.description << " on a 1/" << grid << " grid";
  shape.description << ", untangled" << (tangled ? " (not fully)" : "") << ", " << inserted
                    << " vertices inserted along edges";
  shape.regions.push_back({std::move(ring), {}});
  return shape;
}

// Long teeth or spikes on a spine or core that holds a few holes: a comb (teeth 2 to 300 times
// as long as wide, gaps 0.05 to 2) or a star (8 to 300 spikes 5 to 500 long around a core of
// radius 10). Each cut peels off one tooth, after the holes are opened: the shapes on which the
// decomposition tree held a copy of the comb per tooth, and validation and the thin-wall check
// tested every pair of the spikes' long edges (stop 42).
Shape teeth(Random& random) {
  Shape shape;
  Region region;
  if (random.chance(0.5)) {
    const int count = random.integer(3, 120);
    const double gap = random.pick(std::vector<double>{0.05, 0.3, 1.0, 2.0});
    const double length = random.pick(std::vector<double>{2.0, 10.0, 50.0, 300.0});
    const double spine = random.uniform(3, 8), width = 1.0;
    auto left = [&](int t) { return t * (width + gap); };
    const double right = left(count - 1) + width;
    Ring& outer = region.outer;
    outer = {{0, 0}, {right, 0}};
    for (int t = count - 1; t >= 0; --t) {
      outer.push_back({left(t) + width, spine + length});
      outer.push_back({left(t), spine + length});
      if (t > 0) {
        outer.push_back({left(t), spine});
        outer.push_back({left(t - 1) + width, spine});
      }
    }
    // Square holes in the spine, at least half a side apart and a quarter side from its ends.
    const double side = std::min(spine / 3, right / 3);
    const int holes =
        std::min(random.integer(1, 5), std::max(1, static_cast<int>(right / (1.5 * side))));
    const double pitch = right / holes;
    for (int h = 0; h < holes; ++h) {
      const double x = pitch * h + (pitch - side) / 2;
      region.holes.push_back(reversed(rectangle(Box{x, side, x + side, 2 * side})));
    }
    shape.thinnest = std::min({gap, width, side / 4});
    shape.description << "comb of " << count << " teeth " << length << " long, gaps " << gap
                      << ", spine " << spine << ", " << region.holes.size() << " holes";
  } else {
    const int count = random.integer(8, 300);
    const double core = 10.0;
    const double length = random.pick(std::vector<double>{5.0, 50.0, 500.0});
    for (int i = 0; i < count; ++i) {
      const double tip = 2 * kPi * i / count, notch = 2 * kPi * (i + 0.5) / count;
      region.outer.push_back({(core + length) * std::cos(tip), (core + length) * std::sin(tip)});
      region.outer.push_back({core * std::cos(notch), core * std::sin(notch)});
    }
    const int holes = random.integer(1, 4);
    for (int h = 0; h < holes; ++h) {
      const double angle = 2 * kPi * h / holes;
      region.holes.push_back(
          reversed(regular_polygon({4.0 * std::cos(angle), 4.0 * std::sin(angle)}, 1.5,
                                   random.integer(3, 12), random.uniform(0, kPi))));
    }
    shape.thinnest = std::min(2 * core * std::sin(kPi / count), 1.0);
    shape.description << "star of " << count << " spikes " << length << " long, " << holes
                      << " holes";
  }
  shape.regions.push_back(std::move(region));
  return shape;
}

// An arm of width `width` wound round the origin: its outer side at radius pitch (1 + θ / 2π),
// from θ = 0 to 2π turns, and back along its inner side `width` nearer. Between turns its sides
// are pitch - width apart; a turn of few vertices cuts its curves short by up to
// r (1 - cos(π / per_turn)), so the turns are limited to keep that under half the gap (and
// under a third of the margin round the holes, which sit on the arm's centre line).
Shape spiral(Random& random) {
  Shape shape;
  Region region;
  const double pitch = 1.0;
  const double width = pitch * random.uniform(0.25, 0.75), gap = pitch - width;
  const double hole_radius = width / 5, margin = width / 2 - hole_radius;
  // The most turns whose outer radius pitch (1 + turns) keeps the cut within the limits; a turn
  // of too few vertices for one turn gets twice as many (review 52).
  int per_turn = random.pick(std::vector<int>{12, 24, 64, 200});
  auto turns_within = [&] {
    return std::min(gap / 2, margin / 3) / (1 - std::cos(kPi / per_turn)) / pitch - 1;
  };
  while (turns_within() < 1) per_turn *= 2;
  const double turns = std::min(random.uniform(1, 10), std::floor(turns_within() * 4) / 4);
  const bool jittered = random.chance(0.3);
  const double jitter = jittered ? pitch * random.pick(std::vector<double>{1e-9, 1e-6, 1e-3}) : 0;
  const int steps = static_cast<int>(std::ceil(turns * per_turn));
  auto radius = [&](double angle) { return pitch * (1 + angle / (2 * kPi)); };
  Ring inner;
  for (int i = 0; i <= steps; ++i) {
    const double angle = 2 * kPi * turns * i / steps, r = radius(angle);
    const double outward = jitter * (random.uniform() - 0.5);
    region.outer.push_back({(r + outward) * std::cos(angle), (r + outward) * std::sin(angle)});
    inner.push_back({(r - width) * std::cos(angle), (r - width) * std::sin(angle)});
  }
  region.outer.insert(region.outer.end(), inner.rbegin(), inner.rend());
  const int holes = random.integer(1, 4);
  for (int h = 0; h < holes; ++h) {
    // Along the arm, away from its ends.
    const double angle = 2 * kPi * turns * (h + 0.5) / holes;
    const double r = radius(angle) - width / 2;
    region.holes.push_back(
        reversed(regular_polygon({r * std::cos(angle), r * std::sin(angle)}, hole_radius,
                                 random.integer(3, 16), random.uniform(0, kPi))));
  }
  shape.thinnest = std::min({gap, margin, width}) / 2;
  shape.description << "spiral of " << turns << " turns, " << per_turn << " vertices a turn, arm "
                    << width << " wide, " << holes << " holes";
  if (jittered) shape.description << ", outer side jittered by " << jitter;
  shape.regions.push_back(std::move(region));
  return shape;
}

Placement draw_placement(Random& random, double thinnest) {
  Placement placement;
  if (random.chance(0.3)) placement.rotation = random.uniform(0, 2 * kPi);
  if (random.chance(0.5)) placement.scale = std::pow(10.0, random.uniform(-2, 3));
  if (random.chance(0.3)) {
    placement.offset = {random.chance(0.5) ? 1e5 : -1e5, random.chance(0.5) ? 1e5 : -1e5};
  }
  if (random.chance(0.3)) {
    // Fine enough that the thinnest wall survives (a step below an eighth of it), coarse enough
    // to move regular shapes' vertices off their lines.
    const double finest = thinnest * placement.scale / 8;
    placement.rounding = std::pow(10.0, std::floor(std::log10(finest)) - random.integer(0, 2));
  }
  return placement;
}

// x rounded to a multiple of step as a decimal file would hold it: printed and read back.
double round_to(double x, double step) {
  if (step >= 1) return std::round(x / step) * step;
  const int digits = static_cast<int>(std::lround(-std::log10(step)));
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, x);
  return std::strtod(text, nullptr);
}

}  // namespace

const std::vector<Family>& all_families() {
  static const std::vector<Family> families{
      Family::thin_wall, Family::grid,          Family::row,   Family::ring,  Family::star,
      Family::button,    Family::random_simple, Family::dense, Family::teeth, Family::spiral};
  return families;
}

const char* family_name(Family family) {
  switch (family) {
    case Family::thin_wall:
      return "thin_wall";
    case Family::grid:
      return "grid";
    case Family::row:
      return "row";
    case Family::ring:
      return "ring";
    case Family::star:
      return "star";
    case Family::button:
      return "button";
    case Family::random_simple:
      return "random_simple";
    case Family::dense:
      return "dense";
    case Family::teeth:
      return "teeth";
    case Family::spiral:
      return "spiral";
  }
  return "?";
}

std::optional<Family> parse_family(std::string_view name) {
  for (Family family : all_families()) {
    if (name == family_name(family)) return family;
  }
  return std::nullopt;
}

std::vector<Region> place(const std::vector<Region>& regions, const Placement& placement) {
  const double c = std::cos(placement.rotation), s = std::sin(placement.rotation);
  auto move = [&](Vec2 p) {
    Vec2 q = placement.rotation != 0 ? Vec2{c * p.x - s * p.y, s * p.x + c * p.y} : p;
    q = q * placement.scale + placement.offset;
    if (placement.rounding > 0) {
      q = {round_to(q.x, placement.rounding), round_to(q.y, placement.rounding)};
    }
    return q;
  };
  std::vector<Region> placed = regions;
  for (Region& region : placed) {
    for (Vec2& p : region.outer) p = move(p);
    for (Ring& hole : region.holes) {
      for (Vec2& p : hole) p = move(p);
    }
  }
  return placed;
}

GeneratedCase generate_case(Family family, std::uint64_t seed) {
  Random random(mix_seed(seed, static_cast<std::uint64_t>(family) + 1));
  Shape shape;
  switch (family) {
    case Family::thin_wall:
      shape = thin_wall(random);
      break;
    case Family::grid:
      shape = grid(random);
      break;
    case Family::row:
      shape = row(random);
      break;
    case Family::ring:
      shape = ring(random);
      break;
    case Family::star:
      shape = star_with_holes(random);
      break;
    case Family::button:
      shape = button(random);
      break;
    case Family::random_simple:
      shape = random_simple(random);
      break;
    case Family::dense:
      shape = dense(random);
      break;
    case Family::teeth:
      shape = teeth(random);
      break;
    case Family::spiral:
      shape = spiral(random);
      break;
  }
  const Placement placement = draw_placement(random, shape.thinnest);
  GeneratedCase generated;
  generated.family = family;
  generated.seed = seed;
  generated.thinnest_feature = shape.thinnest * placement.scale;
  std::ostringstream description;
  description << shape.description.str() << "; scale " << placement.scale << ", rotation "
              << placement.rotation << ", offset (" << placement.offset.x << ", "
              << placement.offset.y << "), rounding " << placement.rounding;
  generated.description = description.str();
  try {
    generated.regions = clean_and_validate(place(shape.regions, placement), family_name(family));
  } catch (const InputError& error) {
    generated.rejection = error.what();
  }
  return generated;
}

}  // namespace hullcook::stress
