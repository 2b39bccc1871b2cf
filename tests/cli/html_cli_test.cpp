// --html report.html: a card per asset whose drawing shows the pixels the cook traced (a --grid
// cell's, a sheet frame's turned upright and placed in its untrimmed frame), names escaped, and
// bytes that depend on nothing but the times. Chromium renders the page in tests/cli/run_html.sh.
#include "png_writer.h"
#include "run_command.h"
#include "test_directory.h"

#include "hullcook/trace/trace.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hullcook {
namespace {

namespace fs = std::filesystem;
using test::read_bytes;
using test::run_hullcook;

// A pixel's colour in the test images: every pixel its own, so a cutout taken from the wrong
// place or turned the wrong way draws other colours.
std::array<std::uint8_t, 4> colour(int x, int y, int salt) {
  return {static_cast<std::uint8_t>(40 + 20 * x), static_cast<std::uint8_t>(30 + 25 * y),
          static_cast<std::uint8_t>(60 * salt), 255};
}

// An image of width x height, transparent but for the opaque pixels opaque(x, y) says, coloured
// by colour(x, y, salt) of their position in the sprite.
template <typename Opaque>
std::string sprite_png(int width, int height, int salt, Opaque opaque) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 4, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!opaque(x, y)) continue;
      const auto c = colour(x, y, salt);
      std::copy(c.begin(), c.end(), pixels.begin() + (y * width + x) * 4);
    }
  }
  return test::make_png(width, height, 6, pixels);
}

// An L in a 10 x 10 cell, different per salt.
bool l_shape(int x, int y, int salt) {
  return (x >= 1 + salt && x < 4 + salt && y >= 1 && y < 9) ||
         (x >= 1 + salt && x < 9 && y >= 6 && y < 9);
}

// text without what stands between each start and the end after it (std::regex, in GCC 12's
// sanitizer build, does not compile warning-free).
std::string without_between(std::string text, const std::string& start, const std::string& end) {
  for (std::size_t at = text.find(start); at != std::string::npos; at = text.find(start, at)) {
    at += start.size();
    const std::size_t stop = text.find(end, at);
    if (stop == std::string::npos) break;
    text.erase(at, stop - at);
  }
  return text;
}

// The bytes of the PNG an SVG embeds as a data: URI; empty if none.
std::string sprite_bytes(const std::string& svg) {
  const std::string prefix = "href=\"data:image/png;base64,";
  const std::size_t start = svg.find(prefix);
  if (start == std::string::npos) return {};
  std::string bytes;
  std::uint32_t bits = 0;
  int count = 0;
  for (std::size_t i = start + prefix.size(); i < svg.size() && svg[i] != '"' && svg[i] != '=';
       ++i) {
    static const std::string kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    bits = bits << 6 | static_cast<std::uint32_t>(kAlphabet.find(svg[i]));
    count += 6;
    if (count >= 8) {
      count -= 8;
      bytes.push_back(static_cast<char>((bits >> count) & 0xFF));
    }
  }
  return bytes;
}

// The SVG in the card of the asset named (escaped as in the page), its <title> (the name) left
// out; empty if there is no such card.
std::string card_svg(const std::string& page, const std::string& escaped_name) {
  const std::size_t card = page.find("data-name=\"" + escaped_name + "\"");
  if (card == std::string::npos) return {};
  const std::size_t start = page.find("<svg", card), end = page.find("</svg>", card);
  if (start == std::string::npos || end == std::string::npos) return {};
  const std::string svg = page.substr(start, end - start);
  return without_between(svg, "<title>", "</title>");
}

// The one card's SVG of a page of one asset.
std::string only_svg(const std::string& page) {
  const std::size_t name = page.find("data-name=\"");
  if (name == std::string::npos) return {};
  const std::size_t start = name + 11;
  return card_svg(page, page.substr(start, page.find('"', start) - start));
}

class HtmlCli : public test::TestDirectory {
 protected:
  HtmlCli() : TestDirectory("hullcook_html_cli_") {}

  void write(const std::string& name, const std::string& bytes) {
    std::ofstream(directory / name, std::ios::binary) << bytes;
  }

  // The page of cooking arguments (with -o and --html into the test's directory).
  std::string cook_html(const std::string& arguments) {
    const fs::path page = directory / "report.html";
    fs::remove(page);
    const auto result = run_hullcook("cook " + arguments + " -q -o " +
                                     (directory / "out.hcb").string() + " --html " + page.string());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_bytes(page);
  }

  // The sprite an SVG of the page embeds, decoded.
  RgbaImage sprite_of(const std::string& svg) {
    write("sprite.png", sprite_bytes(svg));
    return load_rgba(directory / "sprite.png", 1 << 20);
  }

  // Two drawings of one asset: the same SVG but for the sprite's bytes, and the same sprite
  // pixels (one may be a PNG file's own bytes, the other re-encoded).
  void expect_same_drawing(const std::string& svg, const std::string& expected) {
    ASSERT_FALSE(sprite_bytes(expected).empty());
    ASSERT_FALSE(sprite_bytes(svg).empty());
    EXPECT_EQ(without_between(svg, "href=\"", "\""), without_between(expected, "href=\"", "\""));
    const RgbaImage sprite = sprite_of(svg), wanted = sprite_of(expected);
    EXPECT_EQ(sprite.width, wanted.width);
    EXPECT_EQ(sprite.height, wanted.height);
    EXPECT_TRUE(sprite.rgba == wanted.rgba) << "the sprites' pixels differ";
  }
};

TEST_F(HtmlCli, GridCellsDrawTheirOwnPixels) {
  // A 2 x 2 grid of 10 px cells; cell 1 is empty (no asset, no card).
  constexpr int kCell = 10;
  write("tiles.png", sprite_png(2 * kCell, 2 * kCell, 0, [](int x, int y) {
          const int index = (y / kCell) * 2 + x / kCell;
          return index != 1 && l_shape(x % kCell, y % kCell, index);
        }));
  // The colours of the tiles are those of their positions in the sheet; each cell alone keeps
  // them, shifted to its own corner.
  const std::string page = cook_html((directory / "tiles.png").string() + " --grid 10x10");
  for (int index : {0, 2, 3}) {
    SCOPED_TRACE(index);
    const int left = (index % 2) * kCell, top = (index / 2) * kCell;
    std::vector<std::uint8_t> pixels(kCell * kCell * 4, 0);
    for (int y = 0; y < kCell; ++y) {
      for (int x = 0; x < kCell; ++x) {
        if (!l_shape(x, y, index)) continue;
        const auto c = colour(left + x, top + y, 0);
        std::copy(c.begin(), c.end(), pixels.begin() + (y * kCell + x) * 4);
      }
    }
    write("cell.png", test::make_png(kCell, kCell, 6, pixels));
    const std::string alone = only_svg(cook_html((directory / "cell.png").string()));
    expect_same_drawing(card_svg(page, "tiles.png/" + std::to_string(index)), alone);
  }
  EXPECT_EQ(page.find("data-name=\"tiles.png/1\""), std::string::npos);
  EXPECT_NE(card_svg(page, "tiles.png/0"), card_svg(page, "tiles.png/3"));
}

TEST_F(HtmlCli, ASheetFrameIsDrawnUprightInItsUntrimmedFrame) {
  // A 6 x 9 frame whose sprite, trimmed to 3 x 5 at (1, 2), is stored turned 90° clockwise at
  // (2, 1) of the atlas: 5 wide, 3 tall. The sprite: a 3 x 5 block missing its top right pixel.
  constexpr int kWidth = 6, kHeight = 9, kTrimX = 1, kTrimY = 2, kTrimW = 3, kTrimH = 5;
  auto in_sprite = [](int x, int y) { return !(x == kTrimW - 1 && y == 0); };
  write("frame.png", sprite_png(kWidth, kHeight, 1, [&](int x, int y) {
          const int sx = x - kTrimX, sy = y - kTrimY;
          return sx >= 0 && sx < kTrimW && sy >= 0 && sy < kTrimH && in_sprite(sx, sy);
        }));
  std::vector<std::uint8_t> atlas(8 * 5 * 4, 0);
  for (int sy = 0; sy < kTrimH; ++sy) {
    for (int sx = 0; sx < kTrimW; ++sx) {
      if (!in_sprite(sx, sy)) continue;
      const auto c = colour(kTrimX + sx, kTrimY + sy, 1);
      const int ax = 2 + kTrimH - 1 - sy, ay = 1 + sx;
      std::copy(c.begin(), c.end(), atlas.begin() + (ay * 8 + ax) * 4);
    }
  }
  write("atlas.png", test::make_png(8, 5, 6, atlas));
  const nlohmann::json sheet = {
      {"frames",
       {{"hero.png",
         {{"frame", {{"x", 2}, {"y", 1}, {"w", kTrimW}, {"h", kTrimH}}},
          {"rotated", true},
          {"trimmed", true},
          {"spriteSourceSize", {{"x", kTrimX}, {"y", kTrimY}, {"w", kTrimW}, {"h", kTrimH}}},
          {"sourceSize", {{"w", kWidth}, {"h", kHeight}}}}}}},
      {"meta", {{"app", "https://www.codeandweb.com/texturepacker"}, {"image", "atlas.png"}}}};
  write("sheet.json", sheet.dump());
  const std::string frame = card_svg(cook_html((directory / "sheet.json").string()), "sheet/hero");
  const std::string alone = only_svg(cook_html((directory / "frame.png").string()));
  expect_same_drawing(frame, alone);
}

TEST_F(HtmlCli, AColourKeyIsDrawnTransparent) {
  // The same L on magenta: in an RGB image keyed with --color-key, and in an RGBA image whose
  // magenta is transparent. The cook traces both alike, and the page draws both alike.
  std::vector<std::uint8_t> rgb, rgba;
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      const bool opaque = l_shape(x, y, 0);
      const auto c = opaque ? colour(x, y, 0) : std::array<std::uint8_t, 4>{255, 0, 255, 0};
      rgb.insert(rgb.end(), c.begin(), c.begin() + 3);
      rgba.insert(rgba.end(), c.begin(), c.end());
    }
  }
  write("keyed.png", test::make_png(10, 10, 2, rgb));
  write("alpha.png", test::make_png(10, 10, 6, rgba));
  const std::string keyed =
      only_svg(cook_html((directory / "keyed.png").string() + " --color-key '#ff00ff'"));
  const std::string alpha = only_svg(cook_html((directory / "alpha.png").string()));
  expect_same_drawing(keyed, alpha);
}

TEST_F(HtmlCli, AWholePngIsEmbeddedAsItsOwnBytes) {
  const fs::path sprite =
      fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites/pingus__traps__spike.png";
  const std::string svg = only_svg(cook_html(sprite.string()));
  EXPECT_TRUE(sprite_bytes(svg) == read_bytes(sprite)) << "not the file's bytes";
}

TEST_F(HtmlCli, NamesAreEscaped) {
  fs::create_directories(directory / "in");
  write("in/a<b>&\"c'.png", sprite_png(10, 10, 0, [](int x, int y) { return l_shape(x, y, 0); }));
  const std::string page = cook_html((directory / "in").string());
  EXPECT_NE(page.find("data-name=\"a&lt;b&gt;&amp;&quot;c&#39;.png\""), std::string::npos);
  EXPECT_NE(page.find("<h2>a&lt;b&gt;&amp;&quot;c&#39;.png</h2>"), std::string::npos);
  EXPECT_NE(page.find("<title>a&lt;b&gt;&amp;&quot;c&#39;.png</title>"), std::string::npos);
  EXPECT_EQ(page.find("a<b>"), std::string::npos);
}

TEST_F(HtmlCli, OnlyTheTimesDifferFromRunToRun) {
  const fs::path sprites = fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites";
  const std::string inputs = (sprites / "pingus__traps__spike.png").string() + " " +
                             (sprites / "frozen-bubble__balls__bubble-1-mini.png").string();
  auto timeless = [](const std::string& page) {
    const std::string text = without_between(page, "data-time=\"", "\"");
    return without_between(without_between(text, "class=\"time\">", " ms"), "hulls, ", " ms.");
  };
  const std::string one = cook_html(inputs + " --threads 1");
  const std::string two = cook_html(inputs + " --threads 2");
  ASSERT_NE(one.find("data-time=\""), std::string::npos);
  EXPECT_EQ(timeless(one), timeless(two));
}

TEST_F(HtmlCli, RefusedBeforeCooking) {
  write("a.png", sprite_png(10, 10, 0, [](int x, int y) { return l_shape(x, y, 0); }));
  const std::string input = (directory / "a.png").string();
  const std::string out = " -q -o " + (directory / "out.hcb").string();
  auto result = run_hullcook("cook " + input + out + " --html " + (directory / "r.txt").string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("written as .html"), std::string::npos) << result.output;
  result = run_hullcook("cook " + input + out + " --html " + (directory / "no/r.html").string());
  EXPECT_EQ(result.exit_code, 3) << result.output;
  result = run_hullcook("cook " + input + out + " --depfile " + (directory / "r.html").string() +
                        " --html " + (directory / "r.html").string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("names another output"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(directory / "out.hcb"));
  EXPECT_FALSE(fs::exists(directory / "r.html"));
}

}  // namespace
}  // namespace hullcook
