// TGA: types 1/9 (colour-mapped), 2/10 (true colour), 3/11 (grey), run-length encoded or not.
#include "pixel_sink.h"

#include <array>
#include <string>
#include <vector>

namespace hullcook::image_detail {

void decode_tga(const std::string& bytes, int width, int height, PixelSink& sink) {
  const std::string& name = sink.name();
  auto u8 = [&](std::size_t at) { return std::uint8_t(bytes[at]); };
  const int id_length = u8(0), map_type = u8(1), image_type = u8(2);
  const int map_first = static_cast<int>(u16_le(bytes, 3));
  const int map_length = static_cast<int>(u16_le(bytes, 5));
  const int map_entry_bits = u8(7), pixel_bits = u8(16), descriptor = u8(17);
  const bool rle = image_type >= 9;
  const int base_type = rle ? image_type - 8 : image_type;
  const bool supported =
      (base_type == 1 && map_type == 1 && pixel_bits == 8 &&
       (map_entry_bits == 24 || map_entry_bits == 32)) ||
      (base_type == 2 && (pixel_bits == 16 || pixel_bits == 24 || pixel_bits == 32)) ||
      (base_type == 3 && (pixel_bits == 8 || pixel_bits == 16));
  if (!supported) {
    fail(name, "unsupported TGA (image type " + std::to_string(image_type) + ", " +
                   std::to_string(pixel_bits) + " bits per pixel)");
  }
  using Bgra = std::array<std::uint8_t, 4>;
  std::size_t at = 18 + static_cast<std::size_t>(id_length);
  std::vector<Bgra> palette;
  if (map_type == 1) {
    const std::size_t entry_bytes = (map_entry_bits + 7) / 8;
    if (at + entry_bytes * map_length > bytes.size()) fail(name, "truncated TGA (colour map)");
    if (base_type == 1) {
      for (int i = 0; i < map_length; ++i, at += entry_bytes) {
        palette.push_back(
            {u8(at), u8(at + 1), u8(at + 2), entry_bytes == 4 ? u8(at + 3) : std::uint8_t(255)});
      }
    } else {
      at += entry_bytes * map_length;
    }
  }
  const std::size_t pixel_bytes = pixel_bits / 8;
  auto to_bgra = [&](std::size_t p) -> Bgra {
    switch (base_type) {
      case 1: {
        const int index = u8(p) - map_first;
        if (index < 0 || index >= static_cast<int>(palette.size())) {
          fail(name, "corrupt TGA (colour index " + std::to_string(u8(p)) + " outside the map)");
        }
        return palette[index];
      }
      case 3:
        return {u8(p), u8(p), u8(p), pixel_bits == 16 ? u8(p + 1) : std::uint8_t(255)};
      default:
        if (pixel_bits == 16) {
          const std::uint32_t v = u16_le(bytes, p);
          auto five = [](std::uint32_t c) {
            return static_cast<std::uint8_t>((c & 31) * 255 / 31);
          };
          return {five(v), five(v >> 5), five(v >> 10),
                  (v & 0x8000) ? std::uint8_t(255) : std::uint8_t(0)};
        }
        return {u8(p), u8(p + 1), u8(p + 2), pixel_bits == 32 ? u8(p + 3) : std::uint8_t(255)};
    }
  };
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<Bgra> pixels;
  pixels.reserve(count);
  while (pixels.size() < count) {
    std::size_t run = 1;
    bool repeat = false;
    if (rle) {
      if (at >= bytes.size()) break;
      const std::uint8_t packet = u8(at++);
      run = (packet & 0x7F) + 1u;
      repeat = (packet & 0x80) != 0;
    }
    const std::size_t need = repeat ? pixel_bytes : pixel_bytes * run;
    if (at + need > bytes.size()) break;
    for (std::size_t k = 0; k < run && pixels.size() < count; ++k) {
      pixels.push_back(to_bgra(repeat ? at : at + k * pixel_bytes));
    }
    at += need;
  }
  if (pixels.size() < count) {
    fail(name, "truncated TGA (pixel data ends after " + std::to_string(pixels.size()) + " of " +
                   std::to_string(count) + " pixels)");
  }
  // 16-bit true colour has its attribute bit, 32-bit its fourth byte, grey 16-bit its second.
  const bool has_alpha = (base_type == 2 && pixel_bits != 24) ||
                         (base_type == 3 && pixel_bits == 16) ||
                         (base_type == 1 && map_entry_bits == 32);
  sink.start(width, height, Layout{4, has_alpha});
  const bool bottom_up = (descriptor & 0x20) == 0, right_to_left = (descriptor & 0x10) != 0;
  std::vector<Bgra> row(static_cast<std::size_t>(width));
  for (int y = 0; y < height; ++y) {
    const int stored = bottom_up ? height - 1 - y : y;
    const Bgra* source = pixels.data() + static_cast<std::size_t>(stored) * width;
    for (int x = 0; x < width; ++x) row[x] = source[right_to_left ? width - 1 - x : x];
    sink.put_row(y, row.front().data());
  }
}

}  // namespace hullcook::image_detail
