// fuzz_make_seeds SOURCE_DIR OUT_DIR: the fuzz targets' seed corpora, made from samples/ into the
// build tree (scripts/fuzz): OUT_DIR/poly (the small sample polygons and the core tests' data),
// OUT_DIR/image (the small sample sprites as they are, and every sprite shrunk to at most
// kSeedSide px a side as PNG, BMP, TGA and WebP), OUT_DIR/bundle (bundles cooked from those
// polygons and images, one asset each, and one with several assets, levels and physics),
// OUT_DIR/fragment (fragments of some of them, for link's reader) and OUT_DIR/sheet (sprite
// sheets' JSON in each form the importers read).
#include "canvas.h"  // tool/cook/src: encode_png
#include "fuzz_limits.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/fragment.h"
#include "hullcook/core/error.h"
#include "hullcook/core/poly_io.h"
#include "hullcook/trace/trace.h"

#include <webp/encode.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace hullcook;

constexpr int kSeedSide = 48;

std::string read_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

std::string little_endian(std::uint32_t value, int bytes) {
  std::string out;
  for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xFF);
  return out;
}

std::vector<fs::path> files_under(const fs::path& dir, const std::string& extension) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Nearest-neighbour shrinking by a whole factor, so that the long side is at most kSeedSide.
RgbaImage shrunk(const RgbaImage& image) {
  const int factor = (std::max(image.width, image.height) + kSeedSide - 1) / kSeedSide;
  RgbaImage small;
  small.width = std::max(1, image.width / factor);
  small.height = std::max(1, image.height / factor);
  small.has_alpha = image.has_alpha;
  for (int y = 0; y < small.height; ++y) {
    for (int x = 0; x < small.width; ++x) {
      const std::size_t from =
          (std::size_t(y) * factor * image.width + std::size_t(x) * factor) * 4;
      small.rgba.insert(small.rgba.end(), image.rgba.begin() + std::ptrdiff_t(from),
                        image.rgba.begin() + std::ptrdiff_t(from + 4));
    }
  }
  return small;
}

std::string bgra_pixel(const RgbaImage& image, int x, int y) {
  const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
  return {char(p[2]), char(p[1]), char(p[0]), char(p[3])};
}

// 32-bit BI_RGB, bottom-up: the fourth byte is alpha.
std::string bmp32(const RgbaImage& image) {
  const std::uint32_t data_size = std::uint32_t(image.width) * image.height * 4;
  std::string bytes = "BM" + little_endian(54 + data_size, 4) + little_endian(0, 4) +
                      little_endian(54, 4) + little_endian(40, 4) + little_endian(image.width, 4) +
                      little_endian(image.height, 4) + little_endian(1, 2) + little_endian(32, 2) +
                      little_endian(0, 4) + little_endian(data_size, 4) + std::string(16, '\0');
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) bytes += bgra_pixel(image, x, y);
  }
  return bytes;
}

// 32-bit true colour, run-length encoded (type 10) or not (type 2), top-down.
std::string tga32(const RgbaImage& image, bool rle) {
  std::string bytes(18, '\0');
  bytes[2] = static_cast<char>(rle ? 10 : 2);
  bytes.replace(12, 2, little_endian(image.width, 2));
  bytes.replace(14, 2, little_endian(image.height, 2));
  bytes[16] = 32;
  bytes[17] = static_cast<char>(8 | 0x20);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width;) {
      int run = 1;
      while (rle && x + run < image.width && run < 128 &&
             bgra_pixel(image, x + run, y) == bgra_pixel(image, x, y)) {
        ++run;
      }
      if (rle) bytes += static_cast<char>(0x80 | (run - 1));
      bytes += bgra_pixel(image, x, y);
      x += run;
    }
  }
  return bytes;
}

std::string webp_lossless(const RgbaImage& image) {
  std::uint8_t* output = nullptr;
  const std::size_t size = WebPEncodeLosslessRGBA(image.rgba.data(), image.width, image.height,
                                                  image.width * 4, &output);
  std::string bytes(reinterpret_cast<const char*>(output), size);
  WebPFree(output);
  return bytes;
}

std::vector<fs::path> make_poly_seeds(const fs::path& source, const fs::path& out) {
  std::vector<fs::path> written;
  std::vector<fs::path> polys = files_under(source / "samples" / "polygons", ".poly");
  for (const fs::path& path : files_under(source / "tests" / "core" / "data", ".poly")) {
    polys.push_back(path);
  }
  for (const fs::path& path : polys) {
    if (fuzz::vertex_count(read_poly_file(path)) > fuzz::kMaxPolyVertices) continue;
    written.push_back(out / path.filename());
    fs::copy_file(path, written.back(), fs::copy_options::overwrite_existing);
  }
  return written;
}

std::vector<fs::path> make_image_seeds(const fs::path& source, const fs::path& out) {
  std::vector<fs::path> written;
  auto write = [&](const std::string& name, const std::string& bytes) {
    written.push_back(out / name);
    write_bytes(written.back(), bytes);
  };
  for (const fs::path& path : files_under(source / "samples" / "sprites", ".png")) {
    const RgbaImage image = load_rgba(path, 1ull << 40);
    const std::string stem = path.stem().string();
    if (std::uint64_t(image.width) * image.height <= fuzz::kMaxImagePixels) {
      write(stem + ".png", read_bytes(path));
    }
    const RgbaImage small = shrunk(image);
    write(stem + ".small.png",
          preview_detail::encode_png(small.rgba.data(), small.width, small.height, 4));
    write(stem + ".bmp", bmp32(small));
    write(stem + ".tga", tga32(small, false));
    write(stem + ".rle.tga", tga32(small, true));
    write(stem + ".webp", webp_lossless(small));
  }
  return written;
}

void cook_bundle(const std::vector<fs::path>& inputs, const fs::path& out, Settings settings) {
  try {
    write_output(cook(inputs, settings), out, settings);
  } catch (const InputError&) {
    // A seed image that traces to nothing cookable gives no bundle; the others are enough.
  }
}

void make_bundle_seeds(const std::vector<fs::path>& polys, const std::vector<fs::path>& images,
                       const fs::path& out) {
  Settings settings;
  settings.threads = 1;
  for (const fs::path& poly : polys) {
    Settings relative = settings;
    relative.tau = Tolerance::parse("2%");
    cook_bundle({poly}, out / (poly.stem().string() + ".hcb"), relative);
  }
  std::vector<fs::path> pngs;
  for (const fs::path& image : images) {
    if (image.extension() != ".png" || image.stem().extension() != ".small") continue;
    pngs.push_back(image);
    cook_bundle({image}, out / (image.stem().stem().string() + ".hcb"), settings);
  }
  Settings rich = settings;
  rich.lods = {Tolerance::parse("4"), Tolerance::parse("8")};
  rich.physics = PhysicsProperties{2.5f, 0.4f, 0.1f, true, 0x0002, 0x00FD};
  rich.pixels_per_unit = 32;
  rich.y_down = true;
  rich.measure = "sp";
  pngs.resize(std::min<std::size_t>(pngs.size(), 4));
  if (!polys.empty()) pngs.push_back(polys.front());
  cook_bundle(pngs, out / "several_assets_levels_physics.hcb", rich);
}

// Fragments (link's input) of the same polygons and small images, and one of several assets with
// levels and physics.
void make_fragment_seeds(const std::vector<fs::path>& polys, const std::vector<fs::path>& images,
                         const fs::path& out) {
  Settings settings;
  settings.threads = 1;
  auto write_fragment_of = [&](const std::vector<fs::path>& inputs, const std::string& name,
                               const Settings& with) {
    try {
      write_bytes(out / name, write_fragment(cook(inputs, with).assets, with));
    } catch (const InputError&) {
      // As for bundles: an input that cooks to nothing is no seed.
    }
  };
  std::vector<fs::path> pngs;
  for (const fs::path& image : images) {
    if (image.extension() == ".png" && image.stem().extension() == ".small") pngs.push_back(image);
  }
  for (std::size_t i = 0; i < pngs.size(); i += 4) {
    write_fragment_of({pngs[i]}, pngs[i].stem().stem().string() + ".hcf", settings);
  }
  for (std::size_t i = 0; i < polys.size(); i += 3) {
    Settings relative = settings;
    relative.tau = Tolerance::parse("2%");
    write_fragment_of({polys[i]}, polys[i].stem().string() + ".hcf", relative);
  }
  Settings rich = settings;
  rich.lods = {Tolerance::parse("4")};
  rich.physics = PhysicsProperties{2.5f, 0.4f, 0.1f, true, 0x0002, 0x00FD};
  rich.pixels_per_unit = 32;
  pngs.resize(std::min<std::size_t>(pngs.size(), 3));
  write_fragment_of(pngs, "several_assets_levels_physics.hcf", rich);
}

// Sprite sheets in the three forms the importers read, describing the small seed images laid out
// in a row: a TexturePacker hash (trimmed, rotated, pivots), a TexturePacker array and an Aseprite
// hash with slices whose keys give pivots.
void make_sheet_seeds(const fs::path& out) {
  const std::string texturepacker_hash = R"({"frames": {
  "walk/01.png": {"frame": {"x": 0, "y": 0, "w": 12, "h": 20}, "rotated": false, "trimmed": true,
    "spriteSourceSize": {"x": 2, "y": 1, "w": 12, "h": 20}, "sourceSize": {"w": 16, "h": 24},
    "pivot": {"x": 0.5, "y": 1}},
  "walk/02.png": {"frame": {"x": 12, "y": 0, "w": 12, "h": 20}, "rotated": true, "trimmed": true,
    "spriteSourceSize": {"x": 0, "y": 3, "w": 12, "h": 20}, "sourceSize": {"w": 12, "h": 24}},
  "idle.png": {"frame": {"x": 0, "y": 20, "w": 8, "h": 8}, "rotated": false, "trimmed": false,
    "spriteSourceSize": {"x": 0, "y": 0, "w": 8, "h": 8}, "sourceSize": {"w": 8, "h": 8}}},
 "meta": {"image": "hero.png", "size": {"w": 32, "h": 28}, "scale": "1"}})";
  const std::string texturepacker_array = R"({"frames": [
  {"filename": "coin/0", "frame": {"x": 0, "y": 0, "w": 10, "h": 10}, "rotated": false,
   "trimmed": false, "spriteSourceSize": {"x": 0, "y": 0, "w": 10, "h": 10},
   "sourceSize": {"w": 10, "h": 10}, "pivot": {"x": 0.5, "y": 0.5}},
  {"filename": "coin/1", "frame": {"x": 10, "y": 0, "w": 6, "h": 10}, "rotated": false,
   "trimmed": true, "spriteSourceSize": {"x": 2, "y": 0, "w": 6, "h": 10},
   "sourceSize": {"w": 10, "h": 10}}],
 "meta": {"image": "coins.png", "size": {"w": 16, "h": 10}}})";
  const std::string aseprite = R"({"frames": {
  "bat 0.aseprite": {"frame": {"x": 0, "y": 0, "w": 16, "h": 16}, "rotated": false,
    "trimmed": false, "spriteSourceSize": {"x": 0, "y": 0, "w": 16, "h": 16},
    "sourceSize": {"w": 16, "h": 16}, "duration": 100},
  "bat 1.aseprite": {"frame": {"x": 16, "y": 0, "w": 16, "h": 16}, "rotated": false,
    "trimmed": false, "spriteSourceSize": {"x": 0, "y": 0, "w": 16, "h": 16},
    "sourceSize": {"w": 16, "h": 16}, "duration": 100}},
 "meta": {"app": "https://www.aseprite.org/", "image": "bat.png", "size": {"w": 32, "h": 16},
  "frameTags": [], "layers": [],
  "slices": [{"name": "body", "color": "#0000ffff", "keys": [
    {"frame": 0, "bounds": {"x": 2, "y": 2, "w": 12, "h": 12}, "pivot": {"x": 6, "y": 11}},
    {"frame": 1, "bounds": {"x": 3, "y": 2, "w": 10, "h": 12}, "pivot": {"x": 5, "y": 11}}]}]}})";
  write_bytes(out / "texturepacker_hash.json", texturepacker_hash);
  write_bytes(out / "texturepacker_array.json", texturepacker_array);
  write_bytes(out / "aseprite_slices.json", aseprite);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fuzz_make_seeds SOURCE_DIR OUT_DIR\n");
    return 1;
  }
  const fs::path source = argv[1], out = argv[2];
  try {
    const char* corpora[] = {"poly", "image", "bundle", "fragment", "sheet"};
    for (const char* corpus : corpora) fs::create_directories(out / corpus);
    const std::vector<fs::path> polys = make_poly_seeds(source, out / "poly");
    const std::vector<fs::path> images = make_image_seeds(source, out / "image");
    make_bundle_seeds(polys, images, out / "bundle");
    make_fragment_seeds(polys, images, out / "fragment");
    make_sheet_seeds(out / "sheet");
    for (const char* corpus : corpora) {
      const auto count = std::distance(fs::directory_iterator(out / corpus), {});
      std::printf("fuzz_make_seeds: %s: %td seeds\n", corpus, count);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_make_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
