// Issue 19: hostile images. Every prefix of a file of each format, and files with bits flipped or
// bytes overwritten, are either decoded and traced or refused with an InputError naming the file;
// nothing else escapes (under the sanitizers, no read or write out of bounds either).
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"
#include "trace_test_util.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <random>
#include <string>
#include <vector>

namespace hullcook {
namespace {

// The sprite in each format the loader reads (WebP lossless keeps the alpha).
std::vector<std::pair<std::string, std::string>> every_format() {
  const std::string png = test::read_bytes(test::sprites_dir() / "teeworlds__deadtee.png");
  const cv::Mat bgra =
      cv::imdecode(std::vector<uchar>(png.begin(), png.end()), cv::IMREAD_UNCHANGED);
  std::vector<std::pair<std::string, std::string>> files{{"sprite.png", png}};
  const std::pair<const char*, std::vector<int>> encodings[] = {
      {".bmp", {}}, {".webp", {cv::IMWRITE_WEBP_QUALITY, 101}}};
  for (const auto& [extension, parameters] : encodings) {
    std::vector<uchar> bytes;
    EXPECT_TRUE(cv::imencode(extension, bgra, bytes, parameters));
    files.emplace_back(std::string("sprite") + extension, std::string(bytes.begin(), bytes.end()));
  }
  // TGA, uncompressed 32-bit, bottom-up: written here (OpenCV has no TGA writer).
  std::string tga(18, '\0');
  tga[2] = 2;
  tga[12] = static_cast<char>(bgra.cols & 0xFF), tga[13] = static_cast<char>(bgra.cols >> 8);
  tga[14] = static_cast<char>(bgra.rows & 0xFF), tga[15] = static_cast<char>(bgra.rows >> 8);
  tga[16] = 32;
  tga[17] = 8;
  for (int y = bgra.rows - 1; y >= 0; --y) {
    tga.append(reinterpret_cast<const char*>(bgra.ptr(y)), static_cast<std::size_t>(bgra.cols) * 4);
  }
  files.emplace_back("sprite.tga", tga);
  return files;
}

// Decodes and traces bytes as the file name; true when accepted. Fails the test on anything
// but success or an InputError naming the file.
bool accepted(const std::string& bytes, const std::string& name) {
  TraceSettings settings;
  settings.max_pixels = 1u << 20;
  try {
    const AlphaImage image = decode_alpha(bytes, name, settings);
    trace_alpha(image, settings);
    return true;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
    return false;
  } catch (const std::exception& error) {
    ADD_FAILURE() << name << ": not an InputError: " << error.what();
    return false;
  }
}

TEST(HostileImages, Issue19_EveryTruncatedFileIsRefusedOrDecoded) {
  for (const auto& [name, bytes] : every_format()) {
    ASSERT_TRUE(accepted(bytes, name)) << name;
    // Every prefix of the headers, then prefixes a few hundred apart.
    const std::size_t step = std::max<std::size_t>(1, bytes.size() / 300);
    int refused = 0;
    for (std::size_t length = 0; length < bytes.size(); length += length < 128 ? 1 : step) {
      if (!accepted(bytes.substr(0, length), name + " cut at " + std::to_string(length))) {
        ++refused;
      }
    }
    EXPECT_GT(refused, 128) << name << ": its truncations were not refused";
  }
}

TEST(HostileImages, Issue19_FlippedBitsAndOverwrittenBytesAreRefusedOrDecoded) {
  std::mt19937 random(19);
  for (const auto& [name, bytes] : every_format()) {
    std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
    for (int trial = 0; trial < 300; ++trial) {
      std::string damaged = bytes;
      if (trial % 3 == 0) {
        // A run of 4 bytes set to extremes: sizes and counts in headers become huge or zero.
        const std::size_t at = position(random);
        for (std::size_t k = at; k < std::min(at + 4, damaged.size()); ++k) {
          damaged[k] = trial % 2 ? '\xff' : '\0';
        }
      } else {
        const std::size_t at = trial % 3 == 1 ? position(random) % 64 : position(random);
        damaged[at] = static_cast<char>(damaged[at] ^ (1 << (random() % 8)));
      }
      accepted(damaged, name + " trial " + std::to_string(trial));
    }
  }
}

TEST(HostileImages, Issue19_OnePixelAndUniformImagesAreTracedOrWarned) {
  for (int alpha : {0, 255}) {
    const std::string one =
        test::encode_png(1, 1, 8, 6, {std::string("\x10\x20\x30", 3) + static_cast<char>(alpha)});
    EXPECT_TRUE(accepted(one, "one_pixel.png"));
    std::vector<std::string> rows(
        64, std::string(64 * 4, static_cast<char>(alpha)));  // every channel = alpha
    TraceSettings settings;
    const TraceResult traced = trace_alpha(
        decode_alpha(test::encode_png(64, 64, 8, 6, rows), "uniform.png", settings), settings);
    if (alpha == 0) {
      EXPECT_TRUE(traced.regions.empty());
      EXPECT_FALSE(traced.warnings.empty());
    } else {
      // Fully opaque: one region, the image's frame (within the half pixel the tracer's edge
      // placement takes at the border).
      ASSERT_EQ(traced.regions.size(), 1u);
      EXPECT_TRUE(traced.regions[0].holes.empty());
      EXPECT_GT(std::abs(test::ring_area(traced.regions[0].outer)), 63.0 * 63.0);
      for (Vec2 p : traced.regions[0].outer) {
        EXPECT_TRUE(p.x >= 0 && p.x <= 64 && p.y >= 0 && p.y <= 64) << p.x << " " << p.y;
      }
    }
  }
}

}  // namespace
}  // namespace hullcook
