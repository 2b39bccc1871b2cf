// Sprites drawn by the stress tests (issue 16): the art on which hole resolution gave up
// (tilesets, frames, UI buttons whose holes nearly fill them, one-pixel walls, a 1000x1000 sheet
// of 400 cells), each drawn from one 64-bit seed, with hard 0/255 alpha edges but for the soft
// family.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook::stress {

enum class ImageFamily {
  tileset,          // opaque frame lines 1-3 px around transparent cells, 6 to 80 holes
  frame,            // picture and window frames, portholes
  button,           // rounded buttons with 1-3 holes nearly filling them, some notched
  one_pixel_walls,  // mazes, diamond lattices and combs of 1 px walls
  grid_sheet,       // 1000x1000 px, 20x20 cells of 48 px behind 2 px lines: 400 holes
  mosaic,           // the other families' sprites side by side, 640 px a side or more: one
                    // image large enough that its tracing takes the cook's threads (issue 17)
  soft_edges,       // rippled radial falloffs of alpha, often cut by the image's border, where
                    // an edge traced at a low threshold runs a hundredth of a pixel from straight
  noise_disc,       // a disc of value noise whose rim wobbles, holed where the noise is low: holes
                    // walled in by others, whose vertices see no vertex of the rim (issue 17's
                    // noise texture, tex16.png)
  long_outline,     // a comb of 200-600 teeth or a spiral of 4-12 turns: rings of thousands of
                    // traced vertices, simplified by the search over a tree of blocks
};

// How many of a family's images a run of `wanted` per family draws: one grid sheet (every seed
// draws the same), a tenth as many mosaics (each holds some thirty sprites), else all.
std::size_t images_to_draw(ImageFamily family, std::size_t wanted);

const std::vector<ImageFamily>& all_image_families();
const char* image_family_name(ImageFamily family);
std::optional<ImageFamily> parse_image_family(std::string_view name);

struct DrawnImage {
  ImageFamily family = ImageFamily::tileset;
  std::uint64_t seed = 0;
  std::string description;
  int width = 0, height = 0;
  std::vector<std::uint8_t> alpha;  // row-major, 0 or 255 but in soft_edges
};

DrawnImage draw_image(ImageFamily family, std::uint64_t seed);

// The image as an RGBA PNG file's bytes.
std::string encode_png(const DrawnImage& image);

}  // namespace hullcook::stress
