// Sprites drawn by the tests (issue 16): the shapes that strain the engine limits at 1 and 100 px
// per unit - bars a pixel or two thin at odd angles, specks near the weld size beside larger
// shapes, thin rings.
#pragma once

#include "../cli/png_writer.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace hullcook::test {

struct DrawnSprite {
  std::string name;
  int width = 0, height = 0;
  std::vector<std::uint8_t> alpha;  // row-major; 255 opaque, 0 transparent

  DrawnSprite(std::string sprite_name, int w, int h)
      : name(std::move(sprite_name)), width(w), height(h), alpha(std::size_t(w) * h, 0) {}

  // Makes opaque every pixel whose centre satisfies inside.
  void paint(const std::function<bool(glm::dvec2)>& inside) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (inside(glm::dvec2{x + 0.5, y + 0.5})) alpha[std::size_t(y) * width + x] = 255;
      }
    }
  }

  void bar(glm::dvec2 from, glm::dvec2 to, double thickness) {
    paint([=](glm::dvec2 p) {
      glm::dvec2 along = to - from;
      double t = std::clamp(glm::dot(p - from, along) / glm::dot(along, along), 0.0, 1.0);
      return glm::length(p - (from + along * t)) <= 0.5 * thickness;
    });
  }

  void ring(glm::dvec2 centre, double radius, double thickness) {
    paint([=](glm::dvec2 p) {
      return std::abs(glm::length(p - centre) - radius) <= 0.5 * thickness;
    });
  }

  void disc(glm::dvec2 centre, double radius) {
    paint([=](glm::dvec2 p) { return glm::length(p - centre) <= radius; });
  }

  void box(int x, int y, int w, int h) {
    paint([=](glm::dvec2 p) { return p.x > x && p.x < x + w && p.y > y && p.y < y + h; });
  }

  std::string png() const {
    std::vector<std::uint8_t> rgba;
    rgba.reserve(alpha.size() * 4);
    for (std::uint8_t a : alpha) rgba.insert(rgba.end(), {255, 255, 255, a});
    return make_png(std::uint32_t(width), std::uint32_t(height), 6, rgba);
  }
};

// The drawn set, the same on every run.
inline std::vector<DrawnSprite> drawn_sprites() {
  std::vector<DrawnSprite> sprites;
  {
    DrawnSprite s("thin_bars.png", 96, 96);
    for (int k = 0; k < 6; ++k) {
      double angle = 0.17 + 0.27 * k, thickness = 1.0 + 0.35 * (k % 3);
      glm::dvec2 centre{20.0 + 28 * (k % 3), 24.0 + 44 * (k / 3)};
      glm::dvec2 half = 18.0 * glm::dvec2{std::cos(angle), std::sin(angle)};
      s.bar(centre - half, centre + half, thickness);
    }
    sprites.push_back(std::move(s));
  }
  {
    // Specks of 2 to 3 px beside a larger shape, a pixel or two from it or touching it.
    DrawnSprite s("specks.png", 64, 64);
    s.disc({32, 32}, 14);
    s.box(47, 30, 2, 2);
    s.box(15, 31, 2, 3);
    s.box(31, 16, 3, 2);
    s.box(44, 43, 2, 2);
    s.box(5, 5, 2, 2);
    s.box(56, 8, 3, 3);
    sprites.push_back(std::move(s));
  }
  {
    DrawnSprite s("rings.png", 96, 64);
    s.ring({18, 18}, 12, 1.2);
    s.ring({52, 20}, 15, 2.0);
    s.ring({80, 46}, 10, 1.5);
    s.ring({30, 48}, 9, 3.0);
    sprites.push_back(std::move(s));
  }
  {
    // A fan of one-pixel spokes from a hub: slivers where the spokes meet.
    DrawnSprite s("spokes.png", 80, 80);
    s.disc({40, 40}, 5);
    for (int k = 0; k < 12; ++k) {
      double angle = 0.26 * k + 0.05;
      s.bar({40, 40}, glm::dvec2{40, 40} + 36.0 * glm::dvec2{std::cos(angle), std::sin(angle)},
            1.1);
    }
    sprites.push_back(std::move(s));
  }
  return sprites;
}

// count sprites of random discs, bars, rings and specks, the same for a seed on every platform
// (std::mt19937's output is specified; the distributions are not, so none is used).
inline std::vector<DrawnSprite> random_sprites(std::uint32_t seed, int count) {
  std::mt19937 random(seed);
  auto uniform = [&](double low, double high) {
    return low + (high - low) * (static_cast<double>(random()) / 4294967296.0);
  };
  std::vector<DrawnSprite> sprites;
  for (int n = 0; n < count; ++n) {
    DrawnSprite s("random" + std::to_string(n) + ".png", int(uniform(40, 120)),
                  int(uniform(40, 120)));
    for (int shapes = int(uniform(2, 9)), k = 0; k < shapes; ++k) {
      glm::dvec2 centre{uniform(0, s.width), uniform(0, s.height)};
      switch (int(uniform(0, 4))) {
        case 0:
          s.disc(centre, uniform(2, 16));
          break;
        case 1: {
          double angle = uniform(0, 6.3), length = uniform(5, 40);
          glm::dvec2 half = 0.5 * length * glm::dvec2{std::cos(angle), std::sin(angle)};
          s.bar(centre - half, centre + half, uniform(0.8, 3));
          break;
        }
        case 2:
          s.ring(centre, uniform(4, 20), uniform(0.8, 3));
          break;
        default:
          s.box(int(centre.x), int(centre.y), int(uniform(1, 5)), int(uniform(1, 5)));
          break;
      }
    }
    sprites.push_back(std::move(s));
  }
  return sprites;
}

}  // namespace hullcook::test
