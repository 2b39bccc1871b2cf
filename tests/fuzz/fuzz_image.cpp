// libFuzzer target: any bytes through the image loader (PNG, BMP and WebP told by their magic
// bytes, TGA by the ".tga" name the input is given) and, when they decode, through the tracer,
// whose output must keep the promises of trace.h and pass the clean-up the cook puts it through.
// Refusing the bytes (InputError) is fine; a crash or a broken promise is a finding.
#include "fuzz_check.h"
#include "fuzz_limits.h"

#include "hullcook/core/clean.h"
#include "hullcook/core/error.h"
#include "hullcook/core/geometry.h"
#include "hullcook/trace/trace.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace hullcook;

void check_ring(const Ring& ring, const AlphaImage& image, bool outer) {
  FUZZ_CHECK(ring.size() >= 3, "a traced ring has at least 3 vertices");
  for (const Vec2& p : ring) {
    // Pixel centres of the transparent border lie half a pixel outside the image.
    FUZZ_CHECK(p.x >= -0.5 && p.y >= -0.5 && p.x <= image.width + 0.5 && p.y <= image.height + 0.5,
               "traced points lie on the padded image");
  }
  FUZZ_CHECK(outer ? signed_area(ring) > 0 : signed_area(ring) < 0,
             "outer rings have a positive shoelace area in pixel space, holes a negative one");
}

void trace_and_check(const AlphaImage& image, const TraceSettings& settings) {
  const TraceResult traced = trace_alpha(image, settings);
  FUZZ_CHECK(traced.width == image.width && traced.height == image.height, "the traced size");
  std::vector<Region> flipped;
  for (const Region& region : traced.regions) {
    check_ring(region.outer, image, true);
    for (const Ring& hole : region.holes) check_ring(hole, image, false);
    // As the cook maps pixels to y-up output units.
    Region mapped = region;
    for (Vec2& p : mapped.outer) p.y = -p.y;
    for (Ring& hole : mapped.holes) {
      for (Vec2& p : hole) p.y = -p.y;
    }
    flipped.push_back(std::move(mapped));
  }
  if (flipped.empty()) return;
  try {
    (void)clean_and_validate(std::move(flipped), "fuzz.tga");
  } catch (const InputError& e) {
    std::fprintf(stderr, "the traced outline is refused by the clean-up: %s\n", e.what());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  TraceSettings settings;
  settings.max_pixels = fuzz::kMaxImagePixels;
  // Images without an alpha channel decode only with a colour key: half of the inputs (by their
  // size's parity, which the fuzzer flips by adding a byte) have one.
  if (size % 2 == 1) settings.color_key = std::array<std::uint8_t, 3>{0, 0, 0};
  AlphaImage image;
  try {
    image = decode_alpha(bytes, "fuzz.tga", settings);
  } catch (const InputError&) {
    return 0;
  }
  FUZZ_CHECK(image.width > 0 && image.height > 0, "a decoded image is not empty");
  FUZZ_CHECK(std::uint64_t(image.width) * std::uint64_t(image.height) <= fuzz::kMaxImagePixels,
             "max_pixels is kept");
  FUZZ_CHECK(image.alpha.size() == std::size_t(image.width) * std::size_t(image.height),
             "one alpha value per pixel");
  trace_and_check(image, settings);  // the cook's defaults
  // And the exact outline of every blob at a threshold the input picks (its last byte).
  TraceSettings exact = settings;
  exact.alpha = 1 + data[size - 1] % 255;
  exact.simplify = 0.0;
  exact.min_blob_area = 0.0;
  exact.min_hole_area = 0.0;
  trace_and_check(image, exact);
  return 0;
}
