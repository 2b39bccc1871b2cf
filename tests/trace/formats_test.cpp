// Image reading: every PNG form games ship, TGA, BMP and WebP give the same alpha; bad images
// give an InputError naming the file and the problem.
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"
#include "trace_test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <webp/encode.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace hullcook {
namespace {

using test::write_bytes;
using ::testing::HasSubstr;

// An anti-aliased sprite with a translucent edge, as 8-bit BGRA.
cv::Mat reference_sprite() {
  cv::Mat bgra =
      cv::imread((test::sprites_dir() / "teeworlds__deadtee.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(bgra.type(), CV_8UC4);
  return bgra;
}

std::vector<std::uint8_t> alpha_of(const cv::Mat& bgra) {
  std::vector<std::uint8_t> alpha;
  for (int y = 0; y < bgra.rows; ++y) {
    for (int x = 0; x < bgra.cols; ++x) alpha.push_back(bgra.at<cv::Vec4b>(y, x)[3]);
  }
  return alpha;
}

std::string little_endian(std::uint32_t v, int bytes) {
  std::string s;
  for (int i = 0; i < bytes; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}

std::string grey_alpha_png(const cv::Mat& bgra, int bits) {
  std::vector<std::string> rows;
  for (int y = 0; y < bgra.rows; ++y) {
    std::string row;
    for (int x = 0; x < bgra.cols; ++x) {
      cv::Vec4b p = bgra.at<cv::Vec4b>(y, x);
      for (int v : {static_cast<int>(p[1]), static_cast<int>(p[3])}) {
        if (bits == 16) row += static_cast<char>(v);  // v * 257: high byte = low byte = v
        row += static_cast<char>(v);
      }
    }
    rows.push_back(row);
  }
  return test::encode_png(bgra.cols, bgra.rows, bits, 4, rows);
}

// Palette entry i is grey i with alpha i, so the index is the alpha value.
std::string palette_png(const cv::Mat& bgra) {
  std::string palette, transparency;
  for (int i = 0; i < 256; ++i) {
    palette += std::string(3, static_cast<char>(i));
    transparency += static_cast<char>(i);
  }
  std::vector<std::string> rows;
  for (int y = 0; y < bgra.rows; ++y) {
    std::string row;
    for (int x = 0; x < bgra.cols; ++x) row += static_cast<char>(bgra.at<cv::Vec4b>(y, x)[3]);
    rows.push_back(row);
  }
  return test::encode_png(bgra.cols, bgra.rows, 8, 3, rows, palette, transparency);
}

std::string tga(const cv::Mat& bgra, bool rle, bool top_left) {
  std::string bytes(18, '\0');
  bytes[2] = static_cast<char>(rle ? 10 : 2);
  bytes.replace(12, 2, little_endian(bgra.cols, 2));
  bytes.replace(14, 2, little_endian(bgra.rows, 2));
  bytes[16] = 32;
  bytes[17] = static_cast<char>(8 | (top_left ? 0x20 : 0));
  for (int i = 0; i < bgra.rows; ++i) {
    int y = top_left ? i : bgra.rows - 1 - i;
    for (int x = 0; x < bgra.cols;) {
      const cv::Vec4b p = bgra.at<cv::Vec4b>(y, x);
      int run = 1;
      while (rle && x + run < bgra.cols && run < 128 && bgra.at<cv::Vec4b>(y, x + run) == p) ++run;
      if (rle) bytes += static_cast<char>(0x80 | (run - 1));
      bytes.append(reinterpret_cast<const char*>(&p[0]), 4);
      x += run;
    }
  }
  return bytes;
}

std::string bmp32(const cv::Mat& bgra) {
  const std::uint32_t data_size = static_cast<std::uint32_t>(bgra.total() * 4);
  std::string bytes = "BM" + little_endian(54 + data_size, 4) + little_endian(0, 4) +
                      little_endian(54, 4) + little_endian(40, 4) + little_endian(bgra.cols, 4) +
                      little_endian(bgra.rows, 4) + little_endian(1, 2) + little_endian(32, 2) +
                      little_endian(0, 4) + little_endian(data_size, 4) + std::string(16, '\0');
  for (int y = bgra.rows - 1; y >= 0; --y) {
    bytes.append(reinterpret_cast<const char*>(bgra.ptr(y)),
                 static_cast<std::size_t>(bgra.cols) * 4);
  }
  return bytes;
}

std::string encoded(const std::string& extension, const cv::Mat& image,
                    const std::vector<int>& parameters = {}) {
  std::vector<std::uint8_t> buffer;
  EXPECT_TRUE(cv::imencode(extension, image, buffer, parameters)) << extension;
  return {buffer.begin(), buffer.end()};
}

TEST(TraceFormats, EveryFormGivesTheSameAlpha) {
  const cv::Mat bgra = reference_sprite();
  const std::vector<std::uint8_t> expected = alpha_of(bgra);
  cv::Mat sixteen;
  bgra.convertTo(sixteen, CV_16U, 257.0);
  std::vector<std::pair<std::string, std::string>> variants{
      {"rgba8.png", encoded(".png", bgra)},
      {"rgba16.png", encoded(".png", sixteen)},
      {"grey_alpha8.png", grey_alpha_png(bgra, 8)},
      {"grey_alpha16.png", grey_alpha_png(bgra, 16)},
      {"palette_trns.png", palette_png(bgra)},
      {"uncompressed_bottom_up.tga", tga(bgra, false, false)},
      {"rle_top_down.TGA", tga(bgra, true, true)},
      {"alpha32.bmp", bmp32(bgra)},
  };
  if (cv::haveImageWriter(".webp")) {
    variants.emplace_back("lossless.webp", encoded(".webp", bgra, {cv::IMWRITE_WEBP_QUALITY, 101}));
  }
  const auto dir = test::scratch_dir("trace_formats");
  const TraceResult reference = trace_alpha({bgra.cols, bgra.rows, expected}, TraceSettings{});
  ASSERT_EQ(reference.regions.size(), 1u);
  for (const auto& [name, bytes] : variants) {
    write_bytes(dir / name, bytes);
    EXPECT_TRUE(is_image_file(dir / name)) << name;
    AlphaImage image = load_alpha(dir / name, TraceSettings{});
    EXPECT_EQ(image.width, bgra.cols) << name;
    EXPECT_EQ(image.height, bgra.rows) << name;
    EXPECT_EQ(image.alpha, expected) << name;
    TraceResult result = trace_image(dir / name, TraceSettings{});
    ASSERT_EQ(result.regions.size(), 1u) << name;
    EXPECT_EQ(result.regions[0].outer, reference.regions[0].outer) << name;
  }
}

TEST(TraceFormats, ColourKeyTracesImagesWithoutAlpha) {
  cv::Mat bgr(40, 60, CV_8UC3, cv::Scalar(255, 0, 255));  // magenta background (B, G, R)
  cv::circle(bgr, {30, 20}, 12, cv::Scalar(20, 200, 40), cv::FILLED);
  const auto dir = test::scratch_dir("trace_colour_key");
  write_bytes(dir / "rgb.png", encoded(".png", bgr));
  try {
    load_alpha(dir / "rgb.png", TraceSettings{});
    ADD_FAILURE() << "an image without alpha and without colour key was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr((dir / "rgb.png").string()));
    EXPECT_THAT(e.what(), HasSubstr("no alpha channel"));
    EXPECT_THAT(e.what(), HasSubstr("--color-key"));
  }
  TraceSettings keyed;
  keyed.color_key = std::array<std::uint8_t, 3>{255, 0, 255};
  TraceResult result = trace_image(dir / "rgb.png", keyed);
  ASSERT_EQ(result.regions.size(), 1u);
  EXPECT_TRUE(result.regions[0].holes.empty());
  EXPECT_NEAR(test::ring_area(result.regions[0].outer), 3.14159 * 12 * 12, 15.0);

  cv::Mat grey(10, 10, CV_8U, cv::Scalar(0));
  write_bytes(dir / "grey.png", encoded(".png", grey));
  EXPECT_THROW(load_alpha(dir / "grey.png", TraceSettings{}), InputError);
}

// Loads path and expects an InputError whose message names the file and contains problem.
void expect_refused(const std::filesystem::path& path, const std::string& problem,
                    const TraceSettings& settings = {}) {
  try {
    trace_image(path, settings);
    ADD_FAILURE() << path << " was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string())) << e.what();
    EXPECT_THAT(e.what(), HasSubstr(problem)) << e.what();
  }
}

TEST(TraceFormats, BadImagesGiveAnInputErrorNamingTheFileAndTheProblem) {
  const auto dir = test::scratch_dir("trace_bad_images");
  const std::string good = test::read_bytes(test::sprites_dir() / "teeworlds__deadtee.png");

  write_bytes(dir / "truncated.png", good.substr(0, good.size() / 2));
  expect_refused(dir / "truncated.png", "truncated PNG");
  write_bytes(dir / "header_only.png", good.substr(0, 20));
  expect_refused(dir / "header_only.png", "truncated PNG (the file ends inside the IHDR header)");
  // Where the file ends, as the sweep of stop 54 asked: after the signature alone it ended
  // "inside the IHDR header", and one byte short it ended "before the IEND chunk", which was
  // there but for its checksum's last byte.
  write_bytes(dir / "signature_only.png", good.substr(0, 8));
  expect_refused(dir / "signature_only.png",
                 "truncated PNG (the file ends after the signature, before the IHDR header)");
  write_bytes(dir / "one_byte_short.png", good.substr(0, good.size() - 1));
  expect_refused(dir / "one_byte_short.png",
                 "truncated PNG (the file ends at byte " + std::to_string(good.size() - 1) +
                     ", inside the IEND chunk at byte " + std::to_string(good.size() - 12) +
                     ", the end of the image)");

  // A palette's tRNS longer than the palette is invalid, and libpng sets it aside: the image was
  // refused as "no alpha channel" (stop 54's sweep), which its author would not recognise.
  const std::string palette("\x00\x00\x00\xff\xff\xff", 6);  // 2 colours
  write_bytes(dir / "long_trns.png",
              test::encode_png(2, 2, 8, 3, {std::string("\x00\x01", 2), std::string("\x01\x00", 2)},
                               palette, std::string("\x00\xff\x80", 3)));
  expect_refused(dir / "long_trns.png",
                 "its tRNS chunk (the transparency of a palette, grey or "
                 "RGB image) is invalid and was ignored");
  // With a valid one (as long as the palette) the same image traces.
  write_bytes(dir / "valid_trns.png",
              test::encode_png(2, 2, 8, 3, {std::string("\x00\x01", 2), std::string("\x01\x00", 2)},
                               palette, std::string("\x00\xff", 2)));
  EXPECT_NO_THROW(load_alpha(dir / "valid_trns.png", TraceSettings{}));

  write_bytes(dir / "empty.png", test::encode_png(0, 0, 8, 6, {}));
  expect_refused(dir / "empty.png", "empty image (0x0");

  // Only the header: anything that tried to allocate 10^10 pixels first would fail differently.
  write_bytes(dir / "huge.png", "\x89PNG\r\n\x1a\n" + test::png_ihdr(100000, 100000, 8, 6) +
                                    test::png_chunk("IEND", ""));
  expect_refused(dir / "huge.png", "100000x100000 = 10000000000 pixels is more than --max-pixels");
  TraceSettings small;
  small.max_pixels = 64 * 64 - 1;
  write_bytes(dir / "limit.png", good);
  expect_refused(dir / "limit.png", "more than --max-pixels 4095", small);

  write_bytes(dir / "text.png", "this is not an image\n");
  expect_refused(dir / "text.png", "not a PNG file");
  write_bytes(dir / "nothing.png", "");
  expect_refused(dir / "nothing.png", "empty file");
  write_bytes(dir / "text.tga", "tiny");
  expect_refused(dir / "text.tga", "truncated TGA");

  std::string bad_checksum = good;
  bad_checksum[good.size() / 2] = static_cast<char>(bad_checksum[good.size() / 2] ^ 0x55);
  write_bytes(dir / "checksum.png", bad_checksum);
  expect_refused(dir / "checksum.png", "bad checksum");

  // Valid chunks, but the image data is too short for the header's size.
  std::vector<std::string> rows(4, std::string(4 * 4, '\x7f'));
  std::string short_data = test::encode_png(4, 4, 8, 6, rows);
  std::string claims_more =
      short_data.substr(0, 8) + test::png_ihdr(40, 40, 8, 6) + short_data.substr(33);
  write_bytes(dir / "short_data.png", claims_more);
  expect_refused(dir / "short_data.png", "corrupt or unsupported PNG data");

  std::string bmp = "BM" + std::string(24, '\0');
  bmp[14] = 40;
  bmp[18] = 8;
  bmp[22] = 8;
  write_bytes(dir / "short.bmp", bmp);
  expect_refused(dir / "short.bmp", "BMP");

  std::string tga_header(18, '\0');
  tga_header[2] = 2;
  tga_header[12] = 16;
  tga_header[14] = 16;
  tga_header[16] = 32;
  write_bytes(dir / "short.tga", tga_header + std::string(100, '\x10'));
  expect_refused(dir / "short.tga", "truncated TGA (pixel data ends after 25 of 256 pixels)");

  expect_refused(dir / "missing.png", "cannot open");
  expect_refused(dir, "is a directory");

  cv::Mat bgr(8, 8, CV_8UC3, cv::Scalar(1, 2, 3));
  write_bytes(dir / "no_alpha.png", encoded(".png", bgr));
  expect_refused(dir / "no_alpha.png", "no alpha channel");
}

// A lossless WebP's header ends at byte 25, and a small or uniform image's file can end soon
// after (godot-demo-projects has 28-byte previews, fully transparent): such files were refused
// as truncated, while every shorter prefix of a WebP still is.
int append_bytes(const std::uint8_t* data, std::size_t size, const WebPPicture* picture) {
  static_cast<std::string*>(picture->custom_ptr)->append(reinterpret_cast<const char*>(data), size);
  return 1;
}

TEST(TraceFormats, ShortLosslessWebpIsDecodedAndItsPrefixesRefused) {
  const auto dir = test::scratch_dir("trace_short_webp");
  // libwebp's simple lossless format (the VP8L chunk alone), packed hardest.
  WebPConfig config;
  ASSERT_TRUE(WebPConfigInit(&config));
  config.lossless = 1, config.method = 6, config.quality = 100;
  WebPPicture picture;
  ASSERT_TRUE(WebPPictureInit(&picture));
  picture.use_argb = 1, picture.width = 64, picture.height = 64;
  ASSERT_TRUE(WebPPictureAlloc(&picture));
  std::fill(picture.argb, picture.argb + 64 * 64, 0u);  // fully transparent
  std::string webp;
  picture.writer = append_bytes, picture.custom_ptr = &webp;
  const bool written = WebPEncode(&config, &picture);
  WebPPictureFree(&picture);
  ASSERT_TRUE(written);
  ASSERT_EQ(webp.compare(12, 4, "VP8L"), 0);
  ASSERT_LT(webp.size(), 30u) << "libwebp wrote a longer file: the test needs another image";

  write_bytes(dir / "clear.webp", webp);
  const AlphaImage image = load_alpha(dir / "clear.webp", TraceSettings{});
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 64);
  EXPECT_TRUE(std::all_of(image.alpha.begin(), image.alpha.end(),
                          [](std::uint8_t alpha) { return alpha == 0; }));
  for (std::size_t length = 0; length < webp.size(); ++length) {
    write_bytes(dir / "cut.webp", webp.substr(0, length));
    expect_refused(dir / "cut.webp", length == 0   ? "empty file"
                                     : length < 12 ? "not a WebP file"
                                                   : "truncated WebP");
  }
}

TEST(TraceFormats, FullyTransparentImageGivesAWarningAndNoRegion) {
  const auto dir = test::scratch_dir("trace_transparent");
  cv::Mat clear(16, 24, CV_8UC4, cv::Scalar(200, 100, 50, 0));
  write_bytes(dir / "clear.png", encoded(".png", clear));
  TraceResult result = trace_image(dir / "clear.png", TraceSettings{});
  EXPECT_TRUE(result.regions.empty());
  EXPECT_EQ(result.width, 24);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_THAT(result.warnings[0], HasSubstr((dir / "clear.png").string()));
  EXPECT_THAT(result.warnings[0], HasSubstr("fully transparent"));
}

// Stop 53's sweep of SuperTux Advance's sprites: a CRT overlay whose every pixel has alpha 1-127
// was called "fully transparent", and a sheet of lone opaque pixels said "every blob is smaller
// than --min-blob-area 4 px²" and then "nothing opaque"; --min-blob-area 1 still dropped them (a
// lone pixel traces to half a px²). The warnings now give the figure that decides: the most
// opaque pixel's alpha, and the largest blob's area.
TEST(TraceFormats, FaintImagesAndSpecksAreToldWithTheFigureThatDecides) {
  const auto dir = test::scratch_dir("trace_faint");
  // Traces the image at the defaults: no region and one warning, which has the figure; then
  // traced with the setting the figure suggests, regions regions.
  auto expect_told = [&](const char* name, const cv::Mat& image, const std::string& figure,
                         const TraceSettings& suggested, std::size_t regions) {
    write_bytes(dir / name, encoded(".png", image));
    const TraceResult result = trace_image(dir / name, TraceSettings{});
    EXPECT_TRUE(result.regions.empty()) << name;
    ASSERT_EQ(result.warnings.size(), 1u) << name;
    EXPECT_THAT(result.warnings[0], HasSubstr(figure));
    EXPECT_EQ(trace_image(dir / name, suggested).regions.size(), regions) << name;
  };
  TraceSettings at_100;
  at_100.alpha = 100;
  expect_told("faint.png", cv::Mat(16, 24, CV_8UC4, cv::Scalar(200, 100, 50, 100)),
              "no pixel reaches --alpha 128 (the most opaque has alpha 100): no region traced",
              at_100, 1);
  cv::Mat specks(16, 24, CV_8UC4, cv::Scalar(200, 100, 50, 0));
  for (int y = 1; y < 16; y += 4)
    for (int x = 1; x < 24; x += 4) specks.at<cv::Vec4b>(y, x)[3] = 255;
  TraceSettings keeping;
  keeping.min_blob_area = 0.5;
  expect_told("specks.png", specks,
              "every blob is smaller than --min-blob-area 4 px² (the largest is 0.5 px²)", keeping,
              24);
}

// Stop 57's image sweep: libpng's default limit of a million pixels a side refused a valid
// 1,000,001 x 1 image as "corrupt or unsupported PNG data (Invalid IHDR data)"; --max-pixels
// bounds images instead. And a corrupt chunk's type reached the terminal as raw bytes (an escape
// sequence among them): a byte that is not printable ASCII is shown as \xNN.
TEST(TraceFormats, Stop57_AMillionPixelWideImageDecodesAndChunkTypesArePrintable) {
  const auto dir = test::scratch_dir("trace_stop57");
  constexpr int kWide = 1'000'001;
  std::string row(std::size_t{kWide} * 4, '\0');
  for (int x = 999'990; x < kWide; ++x) row[std::size_t(x) * 4 + 3] = '\xff';
  write_bytes(dir / "wide.png", test::encode_png(kWide, 1, 8, 6, {row}));
  const AlphaImage wide = load_alpha(dir / "wide.png", TraceSettings{});
  EXPECT_EQ(wide.width, kWide);
  EXPECT_EQ(wide.height, 1);
  EXPECT_EQ(wide.alpha[999'989], 0);
  EXPECT_EQ(wide.alpha[kWide - 1], 255);

  std::string escaped =
      test::encode_png(4, 4, 8, 6, std::vector<std::string>(4, std::string(16, 'a')));
  // A chunk after IHDR (at byte 33) typed ESC [ 3 1, its checksum left as it was.
  const std::string chunk = test::png_chunk("tEXt", "a");
  escaped.insert(33, chunk);
  escaped.replace(33 + 4, 4, "\x1b[31");
  write_bytes(dir / "escape.png", escaped);
  expect_refused(dir / "escape.png", "bad checksum in the \\x1b[31 chunk at byte 33");

  // A header of 100000 x 100000 pixels over 4x4's image data, with --max-pixels raised past it:
  // refused by the data's size (deflate packs at most 1032 bytes into one) before the 40 GB image
  // is allocated (which filled 9.8 GB before libpng found the data short).
  const std::string small =
      test::encode_png(4, 4, 8, 6, std::vector<std::string>(4, std::string(16, 'a')));
  write_bytes(dir / "claims_huge.png",
              small.substr(0, 8) + test::png_ihdr(100000, 100000, 8, 6) + small.substr(33));
  TraceSettings unbounded;
  unbounded.max_pixels = 1'000'000'000'000'000;
  expect_refused(dir / "claims_huge.png",
                 "truncated PNG (its image data, 79 bytes, is too short for 100000x100000 pixels)",
                 unbounded);
}

TEST(TraceFormats, ImageFilesAreToldByExtension) {
  for (const char* name : {"a.png", "b.PNG", "c.tga", "d.bmp", "e.WebP"})
    EXPECT_TRUE(is_image_file(name));
  for (const char* name : {"a.poly", "b.jpg", "png", "c.png.txt"})
    EXPECT_FALSE(is_image_file(name));
}

}  // namespace
}  // namespace hullcook
