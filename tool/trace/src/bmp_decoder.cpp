// BMP: what OpenCV 4.6's decoder (grfmt_bmp.cpp) gave, so that cooked outputs do not change, and
// the fourth byte of 32-bit images as alpha, which OpenCV ignored.
//
// Forms: 1, 4 and 8 bits with a palette (uncompressed, RLE4, RLE8), 16 bits (5-5-5 or 5-6-5, or
// other masks with an alpha mask), 24 and 32 bits. Where OpenCV was wrong, the file's colours are
// read: OS/2 headers (12 bytes) in colour, which OpenCV read as grey (a --color-key then keyed
// nothing), and 16-bit masks inside a V4 or V5 header, which OpenCV looked for after it (a real
// 5-6-5 sprite was refused). A 16-bit image's alpha mask (GIMP's A1R5G5B5 and A4R4G4B4), which
// OpenCV ignored or refused, is its alpha.
#include "pixel_sink.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

namespace hullcook::image_detail {
namespace {

constexpr std::uint32_t kRgb = 0, kRle8 = 1, kRle4 = 2, kBitfields = 3;

using Bgr = std::array<std::uint8_t, 3>;

// One channel of a 16-bit BI_BITFIELDS pixel: a run of set bits, scaled to 0..255.
class ChannelMask {
 public:
  ChannelMask() = default;
  explicit ChannelMask(std::uint32_t mask) : mask_(mask) {
    if (mask == 0) return;
    while (!(mask >> shift_ & 1)) ++shift_;
    top_ = mask >> shift_;
  }
  // A run of set bits within 16 (else the mask means nothing this decoder knows).
  bool valid() const { return top_ != 0 && mask_ <= 0xffff && (top_ & (top_ + 1)) == 0; }
  std::uint32_t mask() const { return mask_; }
  std::uint8_t operator()(unsigned pixel) const {
    return static_cast<std::uint8_t>((((pixel & mask_) >> shift_) * 255 + top_ / 2) / top_);
  }

 private:
  std::uint32_t mask_ = 0;
  unsigned shift_ = 0;
  std::uint32_t top_ = 0;  // the mask's largest value, shifted down
};

// The 32-bit forms with an alpha byte in the standard place: uncompressed (BI_RGB), or
// BI_BITFIELDS with the standard BGRA masks. An all-zero fourth byte means "unused" by the BMP
// convention, so such an image has no alpha.
bool decode_bmp32(const std::string& bytes, PixelSink& sink) {
  if (bytes.size() < 54) return false;
  const std::uint32_t info_size = u32_le(bytes, 14);
  if (info_size < 40 || u16_le(bytes, 28) != 32) return false;
  const std::uint32_t compression = u32_le(bytes, 30);
  if (compression == kBitfields) {
    const bool standard = info_size >= 56 && bytes.size() >= 14 + 56 &&
                          u32_le(bytes, 54) == 0x00FF0000 && u32_le(bytes, 58) == 0x0000FF00 &&
                          u32_le(bytes, 62) == 0x000000FF && u32_le(bytes, 66) == 0xFF000000;
    if (!standard) return false;
  } else if (compression != kRgb) {
    return false;
  }
  const auto width = static_cast<std::int32_t>(u32_le(bytes, 18));
  const auto height = static_cast<std::int32_t>(u32_le(bytes, 22));
  const bool top_down = height < 0;
  const int rows = top_down ? -height : height;
  const std::size_t offset = u32_le(bytes, 10);
  const std::size_t row_bytes = static_cast<std::size_t>(width) * 4;
  if (offset > bytes.size() || bytes.size() - offset < row_bytes * static_cast<std::size_t>(rows)) {
    fail(sink.name(), "truncated BMP (pixel data ends early)");
  }
  const auto* pixels = reinterpret_cast<const std::uint8_t*>(bytes.data()) + offset;
  bool has_alpha = false;
  for (std::size_t i = 3; i < row_bytes * rows && !has_alpha; i += 4) has_alpha = pixels[i] != 0;
  sink.start(width, rows, Layout{4, has_alpha});
  for (int y = 0; y < rows; ++y)
    sink.put_row(y, pixels + row_bytes * (top_down ? y : rows - 1 - y));
  return true;
}

// Reads the file's bytes in order; running past the end is a truncated file.
class Cursor {
 public:
  Cursor(const std::string& bytes, std::size_t at, const std::string& name)
      : bytes_(bytes), at_(at), name_(name) {}
  const std::uint8_t* take(std::size_t count) {
    if (at_ > bytes_.size() || bytes_.size() - at_ < count) {
      fail(name_, "truncated BMP (pixel data ends early)");
    }
    const auto* p = reinterpret_cast<const std::uint8_t*>(bytes_.data()) + at_;
    at_ += count;
    return p;
  }
  std::uint8_t byte() { return *take(1); }

 private:
  const std::string& bytes_;
  std::size_t at_;
  const std::string& name_;
};

// The decoded image in decoding order (the file's first row first), B, G, R.
class Canvas {
 public:
  Canvas(int width, int height)
      : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height) {}
  Bgr& at(int y, int x) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  const Bgr* row(int y) const { return pixels_.data() + static_cast<std::size_t>(y) * width_; }

  // OpenCV's FillUniColor: count pixels of one colour from (y, x) on, continuing on the next
  // row at the end of one; stops after the last row.
  void fill(int& y, int& x, long long count, const Bgr& colour) {
    do {
      const long long here = std::min<long long>(count, width_ - x);
      for (long long i = 0; i < here; ++i) at(y, x++) = colour;
      count -= here;
      if (x >= width_) {
        x = 0;
        if (++y >= height_) break;
      }
    } while (count > 0);
  }

 private:
  int width_, height_;
  std::vector<Bgr> pixels_;
};

void decode_rle(Cursor& in, Canvas& canvas, int width, int height, int bits,
                const std::array<Bgr, 256>& palette, const std::string& name) {
  auto bad = [&] { fail(name, "corrupt BMP (a run-length code runs past the end of a row)"); };
  int y = 0, x = 0;
  bool just_wrapped = false;  // RLE8: the last run ended exactly at the end of a row
  while (true) {
    const int count = in.byte(), code = in.byte();
    if (count != 0) {  // a run
      if (x + count > width) bad();
      if (bits == 8) {
        const int before = y;
        canvas.fill(y, x, count, palette[code]);
        just_wrapped = y != before;
        if (y >= height) return;
      } else {
        const Bgr colours[2] = {palette[code >> 4], palette[code & 15]};
        for (int i = 0; i < count; ++i) canvas.at(y, x++) = colours[i & 1];
      }
    } else if (code > 2) {  // absolute: code literal pixels, padded to 16 bits
      if (x + code > width) bad();
      const int size = bits == 8 ? (code + 1) & ~1 : (((code + 1) >> 1) + 1) & ~1;
      const std::uint8_t* literal = in.take(static_cast<std::size_t>(size));
      for (int i = 0; i < code; ++i) {
        const int index = bits == 8 ? literal[i] : (literal[i / 2] >> (i % 2 ? 0 : 4)) & 15;
        canvas.at(y, x++) = palette[index];
      }
      just_wrapped = false;
    } else {  // 0: end of line, 1: end of bitmap, 2: delta; skipped pixels take palette[0]
      long long skip = width - x, rows = height - y;
      if (bits == 8 && code == 0 && just_wrapped && x == 0) {
        just_wrapped = false;
        continue;
      }
      if (code == 2) {
        skip = in.byte();
        rows = in.byte();
      }
      if (bits == 8 && code != 0) skip += rows * width;
      if (bits == 8 && y >= height) return;
      canvas.fill(y, x, skip, palette[0]);
      just_wrapped = false;
      if (y >= height) return;
    }
  }
}

}  // namespace

void decode_bmp(const std::string& bytes, PixelSink& sink) {
  if (decode_bmp32(bytes, sink)) return;
  const std::string& name = sink.name();
  auto unsupported = [&] { fail(name, "corrupt or unsupported BMP data"); };
  const std::uint32_t info_size = u32_le(bytes, 14);
  const bool os2 = info_size == 12;
  const std::size_t offset = u32_le(bytes, 10);
  int width = 0, height = 0, bits = 0;
  std::uint32_t compression = kRgb;
  std::array<Bgr, 256> palette{};
  // 16 bits: masks other than 5-5-5 and 5-6-5 (general, B, G, R's), and an alpha mask.
  bool general = false;
  std::array<ChannelMask, 3> colours;
  ChannelMask alpha;
  if (os2) {
    width = static_cast<int>(u16_le(bytes, 18));
    height = static_cast<int>(u16_le(bytes, 20));
    bits = static_cast<int>(u16_le(bytes, 24));
    if (bits != 1 && bits != 4 && bits != 8 && bits != 24 && bits != 32) unsupported();
    if (bits <= 8) {
      Cursor in(bytes, 26, name);
      for (int i = 0; i < (1 << bits); ++i) {
        const std::uint8_t* entry = in.take(3);
        palette[i] = {entry[0], entry[1], entry[2]};
      }
    }
  } else {
    width = static_cast<std::int32_t>(u32_le(bytes, 18));
    height = static_cast<std::int32_t>(u32_le(bytes, 22));
    bits = static_cast<int>(u16_le(bytes, 28));
    compression = u32_le(bytes, 30);
    const bool known = ((bits == 1 || bits == 4 || bits == 8 || bits == 24 || bits == 32) &&
                        compression == kRgb) ||
                       ((bits == 16 || bits == 32) && compression == kBitfields) ||
                       (bits == 16 && compression == kRgb) || (bits == 4 && compression == kRle4) ||
                       (bits == 8 && compression == kRle8);
    if (!known || width <= 0 || height == 0) unsupported();
    if (bits <= 8) {
      const std::uint32_t used = bytes.size() >= 50 ? u32_le(bytes, 46) : 0;
      if (used > 256) unsupported();
      Cursor in(bytes, 14 + std::size_t{info_size}, name);
      for (std::uint32_t i = 0; i < (used == 0 ? 1u << bits : used); ++i) {
        const std::uint8_t* entry = in.take(4);
        palette[i] = {entry[0], entry[1], entry[2]};
      }
    } else if (bits == 16 && compression == kBitfields) {
      // The masks follow a 40-byte header; V2 to V5 headers (52 bytes and more) hold them there,
      // and V3 to V5 (56 and more) an alpha mask after them.
      Cursor in(bytes, 14 + 40, name);
      const std::uint8_t* masks = in.take(info_size >= 56 ? 16 : 12);
      auto mask = [&](int k) {
        return static_cast<std::uint32_t>(masks[4 * k]) | masks[4 * k + 1] << 8 |
               masks[4 * k + 2] << 16 | static_cast<std::uint32_t>(masks[4 * k + 3]) << 24;
      };
      const std::uint32_t red = mask(0), green = mask(1), blue = mask(2);
      if (info_size >= 56) {
        // An alpha mask that overlaps the colours' is taken for none, as OpenCV took every one.
        const ChannelMask candidate(mask(3));
        if (candidate.valid() && !(candidate.mask() & (red | green | blue))) alpha = candidate;
      }
      if (red == 0x7c00 && green == 0x3e0 && blue == 0x1f) {
        bits = 15;
      } else if (!(red == 0xf800 && green == 0x7e0 && blue == 0x1f)) {
        // Other masks (A4R4G4B4, X4R4G4B4): OpenCV refused them; each channel is scaled.
        colours = {ChannelMask(red), ChannelMask(green), ChannelMask(blue)};
        const bool disjoint = !(red & green) && !(red & blue) && !(green & blue);
        if (!disjoint || !std::all_of(colours.begin(), colours.end(),
                                      [](const ChannelMask& c) { return c.valid(); })) {
          unsupported();
        }
        general = true;
      }
    } else if (bits == 16) {
      bits = 15;
    }
  }
  const bool bottom_up = height > 0;
  height = std::abs(height);
  // 32-bit BI_BITFIELDS with other masks: OpenCV copied the four bytes as B, G, R, A.
  const bool four = !os2 && bits == 32;
  Canvas canvas(width, height);
  std::vector<std::array<std::uint8_t, 4>> bgra;
  std::vector<std::uint8_t> alphas;  // 16 bits with an alpha mask: per pixel, in decoding order
  if (alpha.valid()) alphas.resize(static_cast<std::size_t>(width) * height);
  Cursor in(bytes, offset, name);
  if (compression == kRle4 || compression == kRle8) {
    decode_rle(in, canvas, width, height, bits, palette, name);
  } else {
    const std::size_t pitch =
        ((static_cast<std::size_t>(width) * (bits == 15 ? 16 : bits) + 7) / 8 + 3) &
        ~std::size_t{3};
    if (four) bgra.resize(static_cast<std::size_t>(width) * height);
    for (int y = 0; y < height; ++y) {
      const std::uint8_t* source = in.take(pitch);
      for (int x = 0; x < width; ++x) {
        Bgr& out = canvas.at(y, x);
        switch (bits) {
          case 1:
            out = palette[(source[x / 8] >> (7 - x % 8)) & 1];
            break;
          case 4:
            out = palette[(source[x / 2] >> (x % 2 ? 0 : 4)) & 15];
            break;
          case 8:
            out = palette[source[x]];
            break;
          case 15:
          case 16: {
            const unsigned v = source[2 * x] | source[2 * x + 1] << 8;
            out = general      ? Bgr{colours[2](v), colours[1](v), colours[0](v)}
                  : bits == 15 ? Bgr{std::uint8_t((v << 3) & 0xf8), std::uint8_t((v >> 2) & 0xf8),
                                     std::uint8_t((v >> 7) & 0xf8)}
                               : Bgr{std::uint8_t((v << 3) & 0xf8), std::uint8_t((v >> 3) & 0xfc),
                                     std::uint8_t((v >> 8) & 0xf8)};
            if (!alphas.empty()) alphas[static_cast<std::size_t>(y) * width + x] = alpha(v);
            break;
          }
          case 24:
            out = {source[3 * x], source[3 * x + 1], source[3 * x + 2]};
            break;
          default:  // 32
            out = {source[4 * x], source[4 * x + 1], source[4 * x + 2]};
            if (four) {
              std::memcpy(bgra[static_cast<std::size_t>(y) * width + x].data(), source + 4 * x, 4);
            }
        }
      }
    }
  }
  // An alpha mask whose bits are all 0 is unused, as a 32-bit image's fourth byte is.
  const bool masked_alpha =
      std::any_of(alphas.begin(), alphas.end(), [](std::uint8_t a) { return a != 0; });
  const Layout layout = four || masked_alpha ? Layout{4, true} : Layout{3, false};
  sink.start(width, height, layout);
  std::vector<std::uint8_t> row;
  for (int y = 0; y < height; ++y) {
    const int stored = bottom_up ? height - 1 - y : y;
    if (four) {
      sink.put_row(y, bgra[static_cast<std::size_t>(stored) * width].data());
    } else if (masked_alpha) {
      row.resize(static_cast<std::size_t>(width) * 4);
      const Bgr* colour = canvas.row(stored);
      const std::uint8_t* a = alphas.data() + static_cast<std::size_t>(stored) * width;
      for (int x = 0; x < width; ++x) {
        std::copy(colour[x].begin(), colour[x].end(), row.begin() + 4 * x);
        row[4 * static_cast<std::size_t>(x) + 3] = a[x];
      }
      sink.put_row(y, row.data());
    } else {
      sink.put_row(y, canvas.row(stored)->data());
    }
  }
}

}  // namespace hullcook::image_detail
