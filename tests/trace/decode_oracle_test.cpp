// The decoders against OpenCV 4.6's imdecode(IMREAD_UNCHANGED), which hullcook used before it read
// images itself: on every sample sprite and on synthetic PNG, BMP and WebP files of every colour
// type and bit depth, the alpha (with and without a colour key) and the colours must be the ones
// OpenCV gave, so that cooked outputs do not change.
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"
#include "trace_test_util.h"

#include <gtest/gtest.h>
#include <png.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <csetjmp>
#include <random>

namespace hullcook {
namespace {

// OpenCV's decoding as hullcook's loader used it: 16 bits to 8 with convertTo(1/257).
cv::Mat opencv_decode(const std::string& bytes) {
  cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
  cv::Mat raw = cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
  if (!raw.empty() && raw.depth() == CV_16U) {
    cv::Mat eight;
    raw.convertTo(eight, CV_8U, 1.0 / 257.0);
    raw = eight;
  }
  return raw;
}

// The alpha the old loader computed from OpenCV's pixels.
std::vector<std::uint8_t> opencv_alpha(const cv::Mat& mat,
                                       std::optional<std::array<std::uint8_t, 3>> key) {
  std::vector<std::uint8_t> alpha;
  const int channels = mat.channels();
  const bool has_alpha = channels == 4 || channels == 2;
  for (int y = 0; y < mat.rows; ++y) {
    for (int x = 0; x < mat.cols; ++x) {
      const std::uint8_t* p = mat.ptr<std::uint8_t>(y) + static_cast<std::size_t>(x) * channels;
      std::uint8_t a = has_alpha ? p[channels == 2 ? 1 : 3] : 255;
      if (key) {
        const auto& k = *key;
        const bool keyed = channels <= 2 ? (p[0] == k[0] && p[0] == k[1] && p[0] == k[2])
                                         : (p[2] == k[0] && p[1] == k[1] && p[0] == k[2]);
        if (keyed) a = 0;
      }
      alpha.push_back(a);
    }
  }
  return alpha;
}

// Checks one file: alpha without key (or the "no alpha channel" refusal), alpha with a colour key
// taken from the image, and the RGBA colours, against OpenCV's reading of as_read (by default the
// file itself; for a form OpenCV read wrongly, the same pixels in a form it reads).
void expect_same_as_opencv(const std::string& name, const std::string& bytes,
                           const std::string& as_read = {}) {
  SCOPED_TRACE(name);
  const cv::Mat reference = opencv_decode(as_read.empty() ? bytes : as_read);
  ASSERT_FALSE(reference.empty()) << "OpenCV cannot read the test file";
  const int channels = reference.channels();
  const bool has_alpha = channels == 4 || channels == 2;
  if (has_alpha) {
    AlphaImage image = decode_alpha(bytes, name, TraceSettings{});
    EXPECT_EQ(image.width, reference.cols);
    EXPECT_EQ(image.height, reference.rows);
    EXPECT_TRUE(image.alpha == opencv_alpha(reference, std::nullopt));
  } else {
    EXPECT_THROW(decode_alpha(bytes, name, TraceSettings{}), InputError);
  }
  // Keys from a few pixels of the image, so that some pixels are keyed.
  for (int k = 0; k < 3; ++k) {
    const int x = (k * 7) % reference.cols, y = (k * 5) % reference.rows;
    const std::uint8_t* p = reference.ptr<std::uint8_t>(y) + static_cast<std::size_t>(x) * channels;
    const std::array<std::uint8_t, 3> key = channels <= 2
                                                ? std::array<std::uint8_t, 3>{p[0], p[0], p[0]}
                                                : std::array<std::uint8_t, 3>{p[2], p[1], p[0]};
    TraceSettings keyed;
    keyed.color_key = key;
    EXPECT_TRUE(decode_alpha(bytes, name, keyed).alpha == opencv_alpha(reference, key)) << k;
  }
  // A directory per test: ctest runs the tests of this file in parallel processes.
  const auto dir = std::filesystem::path(HULLCOOK_BINARY_DIR) / "test-scratch" /
                   ("decode_oracle_" +
                    std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::create_directories(dir);
  const auto path = dir / std::filesystem::path(name).filename();
  test::write_bytes(path, bytes);
  const RgbaImage rgba = load_rgba(path, 1ull << 40);
  ASSERT_EQ(rgba.rgba.size(), reference.total() * 4);
  bool same = true;
  for (int y = 0; y < reference.rows && same; ++y) {
    for (int x = 0; x < reference.cols && same; ++x) {
      const std::uint8_t* p =
          reference.ptr<std::uint8_t>(y) + static_cast<std::size_t>(x) * channels;
      const std::uint8_t* q = rgba.rgba.data() + (static_cast<std::size_t>(y) * rgba.width + x) * 4;
      const std::array<std::uint8_t, 4> expected =
          channels <= 2
              ? std::array<std::uint8_t, 4>{p[0], p[0], p[0], has_alpha ? p[1] : std::uint8_t(255)}
              : std::array<std::uint8_t, 4>{p[2], p[1], p[0], has_alpha ? p[3] : std::uint8_t(255)};
      same = std::equal(expected.begin(), expected.end(), q);
      EXPECT_TRUE(same) << "first difference at " << x << ", " << y;
    }
  }
}

TEST(DecodeOracle, EverySampleSpriteAsOpenCV) {
  for (const auto& path : test::all_sprites()) {
    expect_same_as_opencv(path.filename().string(), test::read_bytes(path));
  }
}

// ---- Synthetic PNGs through libpng's writer: every colour type, bit depth, tRNS, interlace. ----

struct PngForm {
  int colour_type;
  int bit_depth;
  bool transparency;
  bool interlaced;
};

void append(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), size);
}

// Only libpng calls after setjmp.
bool libpng_write(png_structp png, png_infop info, std::string& out, const PngForm& form, int width,
                  int height, png_bytep* rows, std::vector<png_color>& palette,
                  std::vector<png_byte>& alphas, png_color_16& colour) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, width, height, form.bit_depth, form.colour_type,
               form.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (form.colour_type == PNG_COLOR_TYPE_PALETTE) {
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    if (form.transparency) {
      png_set_tRNS(png, info, alphas.data(), static_cast<int>(alphas.size()), nullptr);
    }
  } else if (form.transparency) {
    png_set_tRNS(png, info, nullptr, 0, &colour);
  }
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

// rows and colour, when given, receive the samples written and the tRNS colour.
std::string write_png(const PngForm& form, int width, int height, std::mt19937& random,
                      std::vector<std::vector<png_byte>>* rows_written = nullptr,
                      png_color_16* transparent = nullptr) {
  const int channels = form.colour_type == PNG_COLOR_TYPE_RGB          ? 3
                       : form.colour_type == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                       : form.colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                       : 1;
  const std::size_t row_bytes =
      (static_cast<std::size_t>(width) * channels * form.bit_depth + 7) / 8;
  std::vector<std::vector<png_byte>> rows(height, std::vector<png_byte>(row_bytes));
  for (int y = 0; y < height; ++y) {
    for (std::size_t i = 0; i < row_bytes; ++i) rows[y][i] = static_cast<png_byte>(random());
    // Runs of equal samples, so that tRNS colours and keys repeat.
    if (y % 3 == 1) rows[y] = rows[y - 1];
  }
  const int palette_size = form.bit_depth < 8 ? (1 << form.bit_depth) : 200;
  if (form.colour_type == PNG_COLOR_TYPE_PALETTE && form.bit_depth == 8) {
    for (auto& row : rows) {
      for (auto& index : row) index = static_cast<png_byte>(index % palette_size);
    }
  }
  std::vector<png_color> palette(palette_size);
  std::vector<png_byte> alphas(palette_size * 3 / 4);
  png_color_16 colour{};
  if (form.colour_type == PNG_COLOR_TYPE_PALETTE) {
    for (auto& c : palette) {
      c = {static_cast<png_byte>(random()), static_cast<png_byte>(random()),
           static_cast<png_byte>(random())};
    }
    palette[1] = {77, 77, 77};  // a grey entry
    for (auto& a : alphas) a = static_cast<png_byte>(random());
  } else if (form.transparency) {
    // The colour of the first pixel, so that it is transparent.
    const png_byte* p = rows[0].data();
    auto sample = [&](int k) -> png_uint_16 {
      if (form.bit_depth == 16) return static_cast<png_uint_16>(p[2 * k] << 8 | p[2 * k + 1]);
      if (form.bit_depth == 8) return p[k];
      return static_cast<png_uint_16>(p[0] >> (8 - form.bit_depth));
    };
    if (form.colour_type == PNG_COLOR_TYPE_GRAY) {
      colour.gray = sample(0);
    } else {
      colour.red = sample(0), colour.green = sample(1), colour.blue = sample(2);
    }
  }
  std::vector<png_bytep> pointers;
  for (auto& row : rows) pointers.push_back(row.data());
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  const bool written =
      libpng_write(png, info, out, form, width, height, pointers.data(), palette, alphas, colour);
  png_destroy_write_struct(&png, &info);
  EXPECT_TRUE(written) << "libpng could not write the test image";
  if (rows_written) *rows_written = rows;
  if (transparent) *transparent = colour;
  return out;
}

TEST(DecodeOracle, EveryPngColourTypeAndBitDepthAsOpenCV) {
  std::mt19937 random(17);
  std::vector<PngForm> forms;
  for (bool interlaced : {false, true}) {
    for (int depth : {1, 2, 4, 8, 16}) {
      forms.push_back({PNG_COLOR_TYPE_GRAY, depth, false, interlaced});
      forms.push_back({PNG_COLOR_TYPE_GRAY, depth, true, interlaced});
      if (depth <= 8) {
        forms.push_back({PNG_COLOR_TYPE_PALETTE, depth, false, interlaced});
        forms.push_back({PNG_COLOR_TYPE_PALETTE, depth, true, interlaced});
      }
      if (depth >= 8) {
        forms.push_back({PNG_COLOR_TYPE_RGB, depth, false, interlaced});
        forms.push_back({PNG_COLOR_TYPE_RGB, depth, true, interlaced});
        forms.push_back({PNG_COLOR_TYPE_GRAY_ALPHA, depth, false, interlaced});
        forms.push_back({PNG_COLOR_TYPE_RGB_ALPHA, depth, false, interlaced});
      }
    }
  }
  for (const PngForm& form : forms) {
    const std::string name =
        "type" + std::to_string(form.colour_type) + "_" + std::to_string(form.bit_depth) + "bit" +
        (form.transparency ? "_trns" : "") + (form.interlaced ? "_adam7" : "") + ".png";
    // OpenCV reads grey with tRNS as opaque grey: see GreyWithATransparentValueHasAlpha.
    if (form.colour_type == PNG_COLOR_TYPE_GRAY && form.transparency) continue;
    expect_same_as_opencv(name, write_png(form, 67, 41, random));
  }
}

// Grey with a transparent value (tRNS), at every bit depth: the grey OpenCV reads, transparent
// where the sample is the tRNS value. It was refused as having no alpha channel, as OpenCV reads
// it (Shattered Pixel Dungeon's 1-bit wall_blocking.png, two of ValyriaTear's sprites).
TEST(DecodeOracle, GreyWithATransparentValueHasAlpha) {
  std::mt19937 random(29);
  for (bool interlaced : {false, true}) {
    for (int depth : {1, 2, 4, 8, 16}) {
      const PngForm form{PNG_COLOR_TYPE_GRAY, depth, true, interlaced};
      const std::string name =
          "grey_" + std::to_string(depth) + "bit_trns" + (interlaced ? "_adam7" : "") + ".png";
      SCOPED_TRACE(name);
      constexpr int kWidth = 67, kHeight = 41;
      std::vector<std::vector<png_byte>> rows;
      png_color_16 transparent{};
      const std::string bytes = write_png(form, kWidth, kHeight, random, &rows, &transparent);
      const cv::Mat grey = opencv_decode(bytes);
      ASSERT_EQ(grey.channels(), 1);
      auto sample = [&](int x, int y) -> int {
        const png_byte* row = rows[static_cast<std::size_t>(y)].data();
        if (depth == 16) return row[2 * x] << 8 | row[2 * x + 1];
        const int bit = x * depth;
        return row[bit / 8] >> (8 - depth - bit % 8) & ((1 << depth) - 1);
      };
      std::vector<std::uint8_t> alpha(kWidth * kHeight);
      std::size_t clear = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const bool is_clear = sample(x, y) == transparent.gray;
          alpha[static_cast<std::size_t>(y * kWidth + x)] = is_clear ? 0 : 255;
          clear += is_clear;
        }
      }
      ASSERT_GT(clear, 0u);
      ASSERT_LT(clear, alpha.size());
      EXPECT_TRUE(decode_alpha(bytes, name, TraceSettings{}).alpha == alpha);
      // A colour key on top: the key's grey is transparent too.
      const std::uint8_t key = grey.at<std::uint8_t>(0, 1);
      TraceSettings keyed;
      keyed.color_key = std::array<std::uint8_t, 3>{key, key, key};
      std::vector<std::uint8_t> keyed_alpha = alpha;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          if (grey.at<std::uint8_t>(y, x) == key) keyed_alpha[y * kWidth + x] = 0;
        }
      }
      EXPECT_TRUE(decode_alpha(bytes, name, keyed).alpha == keyed_alpha);
      // As RGBA: the grey, with that alpha.
      const auto dir =
          std::filesystem::path(HULLCOOK_BINARY_DIR) / "test-scratch" / "decode_oracle_grey_trns";
      std::filesystem::create_directories(dir);
      test::write_bytes(dir / name, bytes);
      const RgbaImage rgba = load_rgba(dir / name, 1ull << 40);
      EXPECT_TRUE(rgba.has_alpha);
      bool same = rgba.rgba.size() == alpha.size() * 4;
      for (std::size_t i = 0; i < alpha.size() && same; ++i) {
        const std::uint8_t g = grey.data[i];
        same = rgba.rgba[4 * i] == g && rgba.rgba[4 * i + 1] == g && rgba.rgba[4 * i + 2] == g &&
               rgba.rgba[4 * i + 3] == alpha[i];
      }
      EXPECT_TRUE(same);
    }
  }
}

TEST(DecodeOracle, EverySixteenBitValueRoundsAsOpenCV) {
  // 256 x 256 grey + alpha: the alpha sample takes every 16-bit value once.
  std::vector<std::string> rows;
  for (int y = 0; y < 256; ++y) {
    std::string row;
    for (int x = 0; x < 256; ++x) {
      row += static_cast<char>(x), row += static_cast<char>(y);  // grey
      row += static_cast<char>(y), row += static_cast<char>(x);  // alpha = y * 256 + x
    }
    rows.push_back(row);
  }
  expect_same_as_opencv("every16.png", test::encode_png(256, 256, 16, 4, rows));
}

// ---- BMP: every form OpenCV reads (32-bit alpha forms are hullcook's own, tested elsewhere). ----

std::string le(std::uint32_t v, int bytes) {
  std::string s;
  for (int i = 0; i < bytes; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}

// A BMP with a 40-byte info header (plus masks when given), palette and pixel data as given.
std::string bmp(int width, int height, int bits, int compression, const std::string& palette,
                const std::string& pixels, const std::string& masks = {}) {
  const std::uint32_t offset = static_cast<std::uint32_t>(54 + masks.size() + palette.size());
  return "BM" + le(offset + static_cast<std::uint32_t>(pixels.size()), 4) + le(0, 4) +
         le(offset, 4) + le(40, 4) + le(static_cast<std::uint32_t>(width), 4) +
         le(static_cast<std::uint32_t>(height), 4) + le(1, 2) + le(bits, 2) + le(compression, 4) +
         le(static_cast<std::uint32_t>(pixels.size()), 4) + le(2835, 4) + le(2835, 4) +
         le(static_cast<std::uint32_t>(palette.size() / 4), 4) + le(0, 4) + masks + palette +
         pixels;
}

std::string random_bytes(std::mt19937& random, std::size_t count) {
  std::string s;
  for (std::size_t i = 0; i < count; ++i) s += static_cast<char>(random());
  return s;
}

TEST(DecodeOracle, EveryBmpFormAsOpenCV) {
  std::mt19937 random(23);
  const int width = 37, height = 11;
  auto pitch = [&](int bits) { return ((width * bits + 7) / 8 + 3) / 4 * 4; };
  std::vector<std::pair<std::string, std::string>> files;
  for (int bits : {1, 4, 8}) {
    std::string colour = random_bytes(random, 4u << bits), grey;
    for (int i = 0; i < (1 << bits); ++i) grey += std::string(3, static_cast<char>(i * 3)) + '\0';
    const std::string data = random_bytes(random, static_cast<std::size_t>(pitch(bits)) * height);
    files.emplace_back("palette" + std::to_string(bits) + ".bmp",
                       bmp(width, height, bits, 0, colour, data));
    files.emplace_back("grey" + std::to_string(bits) + ".bmp",
                       bmp(width, -height, bits, 0, grey, data));
  }
  const std::string data16 = random_bytes(random, static_cast<std::size_t>(pitch(16)) * height);
  files.emplace_back("rgb555.bmp", bmp(width, height, 16, 0, {}, data16));
  files.emplace_back("bitfields555.bmp", bmp(width, height, 16, 3, {}, data16,
                                             le(0x7c00, 4) + le(0x3e0, 4) + le(0x1f, 4)));
  files.emplace_back("bitfields565.bmp", bmp(width, -height, 16, 3, {}, data16,
                                             le(0xf800, 4) + le(0x7e0, 4) + le(0x1f, 4)));
  files.emplace_back("rgb24.bmp",
                     bmp(width, height, 24, 0, {},
                         random_bytes(random, static_cast<std::size_t>(pitch(24)) * height)));
  files.emplace_back("bitfields32_rgba_masks.bmp",
                     bmp(width, height, 32, 3, {},
                         random_bytes(random, static_cast<std::size_t>(pitch(32)) * height),
                         le(0xff, 4) + le(0xff00, 4) + le(0xff0000, 4)));
  // Run-length encoded: runs, absolute runs (odd and even), end of line, delta, end of bitmap.
  const std::string palette = random_bytes(random, 4 * 256);
  std::string rle8, rle4;
  for (int y = 0; y < height - 4; ++y) {
    rle8 += std::string("\x05", 1) + static_cast<char>(y + 1);            // run of 5
    rle8 += std::string("\x00\x03", 2) + random_bytes(random, 3) + '\0';  // absolute, odd
    rle8 += std::string("\x00\x04", 2) + random_bytes(random, 4);         // absolute, even
    if (y % 3 == 0) rle8 += std::string("\x00\x02\x02\x00", 4);           // delta: 2 right
    if (y == 4) rle8 += std::string("\x00\x02\x01\x01", 4);               // delta: down one row
    rle8 += std::string("\x00\x00", 2);                                   // end of line
  }
  for (int y = 0; y < height - 2; ++y) {
    rle4 += std::string("\x07", 1) + static_cast<char>(0x1f + y);         // run of 7 alternating
    rle4 += std::string("\x00\x05", 2) + random_bytes(random, 3) + '\0';  // absolute, 5 pixels
    rle4 += std::string("\x00\x00", 2);
  }
  rle8 += std::string("\x25\x09", 2);  // a whole row: wraps to the next
  rle8 += std::string("\x00\x00", 2);  // end of line right after a wrap: no empty row
  rle8 += std::string("\x03\x07", 2);
  rle8 += std::string("\x00\x01", 2);  // end of bitmap: the rest takes palette[0]
  rle4 += std::string("\x25\x12", 2) + std::string("\x00\x00", 2);
  rle4 += std::string("\x03\x45", 2) + std::string("\x00\x00", 2);
  files.emplace_back("rle8.bmp", bmp(width, height, 8, 1, palette, rle8));
  files.emplace_back("rle4.bmp", bmp(width, height, 4, 2, palette.substr(0, 64), rle4));
  for (const auto& [name, bytes] : files) expect_same_as_opencv(name, bytes);
}

// Stop 58, a helper's sweep of real sprites: OpenCV read OS/2 BMPs (12-byte header, three-byte
// palette entries) as grey, so a --color-key keyed nothing and the whole image was the shape; and
// it looked for a 16-bit image's masks after a V5 header, where they are inside it, refusing a
// game's 5-6-5 sprite. Each now reads as the same pixels with a 40-byte header, as OpenCV reads.
TEST(DecodeOracle, Stop58_BmpFormsOpenCVReadWronglyReadAsTheirPixels) {
  std::mt19937 random(58);
  const int width = 37, height = 11;
  auto pitch = [&](int bits) { return ((width * bits + 7) / 8 + 3) / 4 * 4; };
  const std::string pixels24 = random_bytes(random, static_cast<std::size_t>(pitch(24)) * height);
  expect_same_as_opencv("os2_24.bmp",
                        "BM" + le(26 + static_cast<std::uint32_t>(pixels24.size()), 4) + le(0, 4) +
                            le(26, 4) + le(12, 4) + le(width, 2) + le(height, 2) + le(1, 2) +
                            le(24, 2) + pixels24,
                        bmp(width, height, 24, 0, {}, pixels24));
  const std::string palette3 = random_bytes(random, 3 * 256);
  std::string palette4;
  for (int i = 0; i < 256; ++i) palette4 += palette3.substr(3 * std::size_t(i), 3) + '\0';
  const std::string indices = random_bytes(random, static_cast<std::size_t>(pitch(8)) * height);
  expect_same_as_opencv("os2_8.bmp",
                        "BM" + le(0, 4) + le(0, 4) + le(26 + 768, 4) + le(12, 4) + le(width, 2) +
                            le(height, 2) + le(1, 2) + le(8, 2) + palette3 + indices,
                        bmp(width, height, 8, 0, palette4, indices));
  // V5 header (124 bytes): the three masks at its bytes 40 to 51, then the alpha mask, colour
  // space, end points, gammas, intent, profile and a reserved word.
  const std::string pixels16 = random_bytes(random, static_cast<std::size_t>(pitch(16)) * height);
  for (const auto& [name, masks] : std::vector<std::pair<std::string, std::string>>{
           {"v5_bitfields565.bmp", le(0xf800, 4) + le(0x7e0, 4) + le(0x1f, 4)},
           {"v5_bitfields555.bmp", le(0x7c00, 4) + le(0x3e0, 4) + le(0x1f, 4)}}) {
    const std::uint32_t offset = 14 + 124;
    const std::string v5 = "BM" + le(offset + static_cast<std::uint32_t>(pixels16.size()), 4) +
                           le(0, 4) + le(offset, 4) + le(124, 4) + le(width, 4) +
                           le(static_cast<std::uint32_t>(-height), 4) + le(1, 2) + le(16, 2) +
                           le(3, 4) + le(static_cast<std::uint32_t>(pixels16.size()), 4) +
                           le(2835, 4) + le(2835, 4) + le(0, 4) + le(0, 4) + masks + le(0, 4) +
                           "BGRs" + std::string(36 + 12 + 16, '\0') + pixels16;
    ASSERT_EQ(v5.size(), offset + pixels16.size());
    expect_same_as_opencv(name, v5, bmp(width, -height, 16, 3, {}, pixels16, masks));
  }
}

// Stop 59, a helper's sweep of real sprites: a 16-bit BMP's alpha mask (GIMP exports A1R5G5B5 and
// A4R4G4B4) was ignored, so an A1R5G5B5 sprite had no alpha and was refused (or, keyed, traced
// with its transparent pixels), and OpenCV refused A4R4G4B4 as unsupported. Each reads as the
// PNG of the pixels its masks give: alpha from the alpha mask, colours scaled to 8 bits (5-5-5
// as OpenCV scaled it, by a shift). An alpha mask whose bits are all 0 is unused.
TEST(DecodeOracle, Stop59_A16BitBmpsAlphaMaskIsItsAlpha) {
  std::mt19937 random(59);
  const int width = 37, height = 11;
  const int pitch = (width * 16 + 31) / 32 * 4;
  struct Form {
    std::string name;
    std::uint32_t red, green, blue, alpha;
    int header;  // 124 (V5) or 56 (V3)
  };
  for (const Form& form :
       std::vector<Form>{{"a1r5g5b5.bmp", 0x7c00, 0x3e0, 0x1f, 0x8000, 124},
                         {"a1r5g5b5_v3.bmp", 0x7c00, 0x3e0, 0x1f, 0x8000, 56},
                         {"a4r4g4b4.bmp", 0xf00, 0xf0, 0xf, 0xf000, 124},
                         {"x4r4g4b4.bmp", 0xf00, 0xf0, 0xf, 0, 124},
                         {"a1r5g5b5_unused.bmp", 0x7c00, 0x3e0, 0x1f, 0x8000, 124}}) {
    SCOPED_TRACE(form.name);
    const bool unused = form.name.find("unused") != std::string::npos;
    std::string pixels;
    cv::Mat expected(height, width, CV_8UC4);
    auto channel = [](unsigned v, std::uint32_t mask, bool shifted) {
      int shift = 0;
      while (!(mask >> shift & 1)) ++shift;
      const unsigned top = mask >> shift, value = (v & mask) >> shift;
      // OpenCV's 5-5-5: the five bits shifted up, the low three 0.
      return static_cast<std::uint8_t>(shifted ? value << 3 : (value * 255 + top / 2) / top);
    };
    const bool opencv_scale = form.red == 0x7c00;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        unsigned v = random() & 0xffff;
        if (unused) v &= ~form.alpha;
        // Whole rows transparent and opaque, so that both kinds appear.
        if (form.alpha && !unused && y % 3 == 0) v &= ~form.alpha;
        if (form.alpha && !unused && y % 3 == 1) v |= form.alpha;
        pixels += le(v, 2);
        cv::Vec4b& out = expected.at<cv::Vec4b>(y, x);
        out[0] = channel(v, form.blue, opencv_scale);
        out[1] = channel(v, form.green, opencv_scale);
        out[2] = channel(v, form.red, opencv_scale);
        out[3] = form.alpha && !unused ? channel(v, form.alpha, false) : 255;
      }
      pixels += std::string(static_cast<std::size_t>(pitch - 2 * width), '\0');
    }
    const std::uint32_t offset = 14 + static_cast<std::uint32_t>(form.header);
    std::string file = "BM" + le(offset + static_cast<std::uint32_t>(pixels.size()), 4) + le(0, 4) +
                       le(offset, 4) + le(static_cast<std::uint32_t>(form.header), 4) +
                       le(width, 4) + le(static_cast<std::uint32_t>(-height), 4) + le(1, 2) +
                       le(16, 2) + le(3, 4) + le(static_cast<std::uint32_t>(pixels.size()), 4) +
                       le(2835, 4) + le(2835, 4) + le(0, 4) + le(0, 4) + le(form.red, 4) +
                       le(form.green, 4) + le(form.blue, 4) + le(form.alpha, 4);
    file += std::string(offset - file.size(), '\0') + pixels;
    cv::Mat reference = expected;
    if (!form.alpha || unused) cv::cvtColor(expected, reference, cv::COLOR_BGRA2BGR);
    std::vector<std::uint8_t> png;
    ASSERT_TRUE(cv::imencode(".png", reference, png));
    expect_same_as_opencv(form.name, file, {png.begin(), png.end()});
  }
}

TEST(DecodeOracle, WebpAsOpenCV) {
  if (!cv::haveImageWriter(".webp")) GTEST_SKIP() << "OpenCV cannot write WebP here";
  cv::Mat bgra =
      cv::imread((test::sprites_dir() / "teeworlds__deadtee.png").string(), cv::IMREAD_UNCHANGED);
  cv::Mat bgr;
  cv::cvtColor(bgra, bgr, cv::COLOR_BGRA2BGR);
  for (int quality : {101, 80}) {
    for (const cv::Mat* image : {&bgra, &bgr}) {
      std::vector<std::uint8_t> encoded;
      ASSERT_TRUE(cv::imencode(".webp", *image, encoded, {cv::IMWRITE_WEBP_QUALITY, quality}));
      expect_same_as_opencv(
          "q" + std::to_string(quality) + "_" + std::to_string(image->channels()) + ".webp",
          {encoded.begin(), encoded.end()});
    }
  }
}

}  // namespace
}  // namespace hullcook
