// libFuzzer target: the sprite sheet importers (TexturePacker hash and array, Aseprite with
// slices) on any JSON text. Refusing it (InputError naming the file) is fine; a sheet it accepts
// must keep what the cooker then relies on: named, distinct frames whose trimmed sprite lies
// inside the untrimmed frame, atlas rectangles of the sprite's size (turned when rotated), no
// frame above the pixel limit, finite pivots; and each frame inside an atlas that holds them all
// is cut out of it (under ASan, every pixel read is checked) at its untrimmed size.
#include "fuzz_check.h"
#include "sheet.h"  // tool/cook/src

#include "hullcook/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>

namespace {

using namespace hullcook;

// Small enough that cutting out every frame stays fast.
constexpr std::uint64_t kMaxPixels = 1 << 14;
constexpr std::uint64_t kLargestAtlas = 1 << 18;

void check_accepted(const Sheet& sheet) {
  FUZZ_CHECK(!sheet.frames.empty(), "a sheet has frames");
  FUZZ_CHECK(!sheet.image.empty(), "a sheet names its atlas");
  std::set<std::string> names;
  for (const SheetFrame& frame : sheet.frames) {
    FUZZ_CHECK(!frame.name.empty(), "a frame has a name");
    FUZZ_CHECK(names.insert(frame.name).second, "frame names are distinct");
    FUZZ_CHECK(frame.trimmed_width >= 1 && frame.trimmed_height >= 1, "a sprite has pixels");
    FUZZ_CHECK(frame.offset_x >= 0 && frame.offset_y >= 0, "offsets are not negative");
    FUZZ_CHECK(frame.offset_x + frame.trimmed_width <= frame.width &&
                   frame.offset_y + frame.trimmed_height <= frame.height,
               "the trimmed sprite lies inside its frame");
    FUZZ_CHECK(static_cast<std::uint64_t>(frame.width) * frame.height <= kMaxPixels,
               "no frame above the pixel limit");
    const int turned_width = frame.rotated ? frame.trimmed_height : frame.trimmed_width;
    const int turned_height = frame.rotated ? frame.trimmed_width : frame.trimmed_height;
    FUZZ_CHECK(frame.atlas.width == turned_width && frame.atlas.height == turned_height,
               "the atlas rectangle is the sprite's, turned when rotated");
    FUZZ_CHECK(frame.atlas.x >= 0 && frame.atlas.y >= 0, "atlas rectangles start inside");
    if (frame.pivot) {
      FUZZ_CHECK(std::isfinite(frame.pivot->x) && std::isfinite(frame.pivot->y),
                 "pivots are finite");
    }
  }
}

// An atlas just large enough for every frame (when that is small), its alpha a pattern.
void cut_out_frames(const Sheet& sheet, const std::string& path) {
  long long width = 1, height = 1;
  for (const SheetFrame& frame : sheet.frames) {
    width = std::max<long long>(width, 0LL + frame.atlas.x + frame.atlas.width);
    height = std::max<long long>(height, 0LL + frame.atlas.y + frame.atlas.height);
  }
  if (static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) > kLargestAtlas) {
    // Too large to make here: a 64 x 64 atlas, which such a sheet cannot fit.
    try {
      check_frames_inside(sheet, path, 64, 64);
    } catch (const InputError& e) {
      FUZZ_CHECK(std::string_view(e.what()).find(path) != std::string_view::npos,
                 "a frame outside the atlas is named with the file");
      return;
    }
    FUZZ_CHECK(false, "frames beyond a 64 x 64 atlas are refused");
  }
  AlphaImage atlas;
  atlas.width = static_cast<int>(width);
  atlas.height = static_cast<int>(height);
  atlas.alpha.resize(static_cast<std::size_t>(width * height));
  for (std::size_t i = 0; i < atlas.alpha.size(); ++i) atlas.alpha[i] = (i * 37) % 256;
  check_frames_inside(sheet, path, atlas.width, atlas.height);
  for (const SheetFrame& frame : sheet.frames) {
    const AlphaImage image = frame_image(atlas, frame);
    FUZZ_CHECK(image.width == frame.width && image.height == frame.height,
               "a frame is cut out at its untrimmed size");
    FUZZ_CHECK(image.alpha.size() == static_cast<std::size_t>(image.width) * image.height,
               "a frame's image holds its pixels");
  }
  // One pixel narrower, the widest frame no longer fits.
  if (width > 1) {
    bool refused = false;
    try {
      check_frames_inside(sheet, path, atlas.width - 1, atlas.height);
    } catch (const InputError&) {
      refused = true;
    }
    FUZZ_CHECK(refused, "a frame past the atlas's right edge is refused");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string path = "fuzz/sheet.json";
  Sheet sheet;
  try {
    sheet = parse_sheet(text, path, kMaxPixels);
  } catch (const InputError& e) {
    FUZZ_CHECK(std::string_view(e.what()).starts_with(path + ": "),
               "a refusal names the file first");
    return 0;
  }
  check_accepted(sheet);
  cut_out_frames(sheet, path);
  return 0;
}
