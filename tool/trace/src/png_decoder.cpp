// PNG through libpng, giving what OpenCV 4.6's imdecode(IMREAD_UNCHANGED) gave (the same libpng
// transforms, then 16-bit samples to 8 as convertTo(CV_8U, 1/257) rounds) but for grey with tRNS,
// whose transparent value is read as alpha; and reading straight into the alpha plane when that
// is all the tracer needs.
#include "pixel_sink.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace hullcook::image_detail {
namespace {

// A chunk's type as a message may show it: a byte that is not printable ASCII as \xNN (a corrupt
// type's control characters and escape sequences reached the terminal).
std::string printable_type(const std::string& type) {
  std::string shown;
  for (const unsigned char c : type) {
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      shown += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789abcdef";
      shown += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
    }
  }
  return shown;
}

// What check_png_chunks finds out on its way.
struct ChunkSummary {
  bool transparency = false;           // a tRNS chunk
  std::uint64_t image_data_bytes = 0;  // the IDAT chunks' data, summed
};

// libpng prints its own errors to stderr, so the chunk structure and checksums are verified here
// first, for a clear message; libpng then skips its own checksums.
ChunkSummary check_png_chunks(const std::string& bytes, const std::string& name) {
  ChunkSummary summary;
  std::size_t at = 8;
  while (true) {
    if (at + 12 > bytes.size()) {
      // Where the file ends inside a chunk's 12 bytes of framing, the chunk is named when its
      // type is there (a file cut in IEND's checksum lacks only the last bytes of the end).
      const std::string type =
          at + 8 <= bytes.size() ? printable_type(bytes.substr(at + 4, 4)) : "";
      fail(name, "truncated PNG (the file ends at byte " + std::to_string(bytes.size()) +
                     (type.empty() || at == bytes.size()
                          ? " before the IEND chunk)"
                          : ", inside the " + type + " chunk at byte " + std::to_string(at) +
                                (type == "IEND" ? ", the end of the image)" : ")")));
    }
    const std::uint64_t length = u32_be(bytes, at);
    const std::string type = printable_type(bytes.substr(at + 4, 4));
    if (at + 12 + length > bytes.size()) {
      fail(name, "truncated PNG (the " + type + " chunk at byte " + std::to_string(at) +
                     " runs past the end of the file)");
    }
    const std::uint32_t stored = u32_be(bytes, at + 8 + length);
    const auto* data = reinterpret_cast<const Bytef*>(bytes.data() + at + 4);
    if (::crc32(0, data, static_cast<uInt>(length + 4)) != stored) {
      fail(name, "corrupt PNG (bad checksum in the " + type + " chunk at byte " +
                     std::to_string(at) + ")");
    }
    summary.transparency = summary.transparency || type == "tRNS";
    if (type == "IDAT") summary.image_data_bytes += length;
    if (type == "IEND") return summary;
    at += 12 + length;
  }
}

// 16-bit to 8-bit as OpenCV's convertTo(CV_8U, 1.0 / 257) does: round(v / 257), never a tie.
inline std::uint8_t eight(const png_byte* big_endian) {
  const unsigned v = static_cast<unsigned>(big_endian[0]) << 8 | big_endian[1];
  return static_cast<std::uint8_t>((v + 128) / 257);
}

struct Input {
  const png_byte* data;
  std::size_t size;
  std::size_t at;
};

void read_input(png_structp png, png_bytep out, png_size_t size) {
  auto* input = static_cast<Input*>(png_get_io_ptr(png));
  if (size > input->size - input->at) png_error(png, "the file ends inside the image data");
  std::memcpy(out, input->data + input->at, size);
  input->at += size;
}

struct Failure {
  char message[200] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* failure = static_cast<Failure*>(png_get_error_ptr(png));
  std::strncpy(failure->message, message, sizeof failure->message - 1);
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

// Owns libpng's structures; every libpng call that may fail runs inside guarded().
class Reader {
 public:
  Reader(const std::string& bytes, const std::string& name)
      : input_{reinterpret_cast<const png_byte*>(bytes.data()), bytes.size(), 0}, name_(name) {
    png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure_, on_error, on_warning);
    if (png_) info_ = png_create_info_struct(png_);
    if (!png_ || !info_) fail(name_, "cannot start the PNG decoder (out of memory)");
    png_set_read_fn(png_, &input_, read_input);
    // check_png_chunks() verified every checksum.
    png_set_crc_action(png_, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
#ifdef PNG_SET_USER_LIMITS_SUPPORTED
    // libpng's own limit of a million pixels a side refused a valid 1,000,001 x 1 image as
    // corrupt; --max-pixels bounds the image instead (checked on the header, before decoding).
    png_set_user_limits(png_, 0x7fffffff, 0x7fffffff);
#endif
#ifdef PNG_IGNORE_ADLER32
    // The image data's Adler-32 guards bytes the chunks' CRC-32 has just verified: computing it
    // was a quarter of decoding (82 of 318 M instructions on samples/sprites).
    png_set_option(png_, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
#endif
  }
  ~Reader() { png_destroy_read_struct(&png_, &info_, nullptr); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

  // Runs body (libpng calls and plain arithmetic only: a libpng error long-jumps out of it) and
  // turns a libpng error into an InputError.
  template <typename Body>
  void guarded(Body&& body) {
    if (!run(body)) {
      fail(name_, std::string("corrupt or unsupported PNG data (") + failure_.message + ")");
    }
  }

 private:
  template <typename Body>
  bool run(Body& body) {
    if (setjmp(png_jmpbuf(png_))) return false;
    body();
    return true;
  }

  Input input_;
  Failure failure_;
  const std::string& name_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

// The alpha of one raw (untransformed) row, for the forms with an alpha sample or a palette.
void alpha_of_raw_row(const png_byte* row, int width, int colour_type, int bit_depth,
                      const std::uint8_t* palette_alpha, std::uint8_t* out) {
  if (colour_type == PNG_COLOR_TYPE_PALETTE) {  // unpacked to a byte per index
    for (int x = 0; x < width; ++x) out[x] = palette_alpha[row[x]];
    return;
  }
  const int channels = colour_type == PNG_COLOR_TYPE_RGB_ALPHA ? 4 : 2;
  if (bit_depth == 8) {
    const png_byte* a = row + channels - 1;
    for (int x = 0; x < width; ++x) out[x] = a[static_cast<std::size_t>(x) * channels];
  } else {
    const png_byte* a = row + 2 * (channels - 1);
    for (int x = 0; x < width; ++x) out[x] = eight(a + static_cast<std::size_t>(x) * 2 * channels);
  }
}

}  // namespace

void decode_png(const std::string& bytes, PixelSink& sink) {
  const ChunkSummary chunks = check_png_chunks(bytes, sink.name());
  const bool has_transparency_chunk = chunks.transparency;
  Reader reader(bytes, sink.name());
  png_structp png = reader.png();
  png_infop info = reader.info();

  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0, interlace = 0, transparent_count = 0;
  png_bytep transparent_alpha = nullptr;
  png_color_16p transparent_colour = nullptr;
  reader.guarded([&] {
    png_read_info(png, info);
    png_get_IHDR(png, info, &width, &height, &bit_depth, &colour_type, &interlace, nullptr,
                 nullptr);
    png_get_tRNS(png, info, &transparent_alpha, &transparent_count, &transparent_colour);
  });
  // A tRNS chunk that libpng set aside (a palette's with more entries than colours, one before
  // PLTE): the image would be refused as having no alpha channel, which its author would not
  // recognise.
  if (has_transparency_chunk && transparent_count == 0 && sink.alpha_only() &&
      (colour_type & PNG_COLOR_MASK_ALPHA) == 0) {
    fail(sink.name(),
         "its tRNS chunk (the transparency of a palette, grey or RGB image) is invalid and was "
         "ignored: for a palette, more entries than it has colours, or a tRNS before PLTE; "
         "without it the image has no alpha channel");
  }
  // OpenCV's channels: RGB and palette 3, or 4 with tRNS; with an alpha sample 4; grey 1. Grey
  // with tRNS is 4 here (OpenCV reads it as 1 channel, as if opaque, which refused such sprites
  // as having no alpha channel), expanded as RGB with tRNS is.
  Layout layout;
  switch (colour_type) {
    case PNG_COLOR_TYPE_RGB:
    case PNG_COLOR_TYPE_PALETTE:
      layout = transparent_count > 0 ? Layout{4, true} : Layout{3, false};
      break;
    case PNG_COLOR_TYPE_GRAY:
      layout = transparent_count > 0 ? Layout{4, true} : Layout{1, false};
      break;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
    case PNG_COLOR_TYPE_RGB_ALPHA:
      layout = Layout{4, true};
      break;
    default:
      layout = Layout{1, false};
  }
  // Deflate packs at most 1032 bytes into one (a 258-byte match in two bits): image data too
  // short for the header's pixels, at their fewest bytes, is refused before the image is
  // allocated (a 69-byte file claiming 100000 x 100000 pixels, with --max-pixels raised, filled
  // 9.8 GB before libpng found its data short).
  const int samples = colour_type == PNG_COLOR_TYPE_RGB_ALPHA    ? 4
                      : colour_type == PNG_COLOR_TYPE_RGB        ? 3
                      : colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                 : 1;
  const double fewest_bytes =
      static_cast<double>(width) * static_cast<double>(height) * samples * bit_depth / 8.0;
  if (fewest_bytes > 1032.0 * (static_cast<double>(chunks.image_data_bytes) + 1.0)) {
    fail(sink.name(), "truncated PNG (its image data, " + std::to_string(chunks.image_data_bytes) +
                          " bytes, is too short for " + std::to_string(width) + "x" +
                          std::to_string(height) + " pixels)");
  }
  sink.start(static_cast<int>(width), static_cast<int>(height), layout);
  const int rows = static_cast<int>(height);

  const bool raw_alpha = sink.alpha_only() && (colour_type == PNG_COLOR_TYPE_RGB_ALPHA ||
                                               colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ||
                                               colour_type == PNG_COLOR_TYPE_PALETTE);
  std::uint8_t palette_alpha[256];
  std::memset(palette_alpha, 255, sizeof palette_alpha);
  if (raw_alpha && colour_type == PNG_COLOR_TYPE_PALETTE) {
    std::memcpy(palette_alpha, transparent_alpha, static_cast<std::size_t>(transparent_count));
  }

  std::vector<png_byte> buffer;
  std::vector<png_bytep> row_pointers;
  std::vector<std::uint8_t> eight_bit;
  std::size_t row_bytes = 0;
  int passes = 1;
  reader.guarded([&] {
    if (raw_alpha) {
      if (bit_depth < 8) png_set_packing(png);
    } else {
      // OpenCV 4.6's transforms for IMREAD_UNCHANGED (grfmt_png.cpp), but for the byte swap of
      // 16-bit samples, which are read big-endian here.
      if (layout.channels < 4) {
        png_set_strip_alpha(png);
      } else {
        png_set_tRNS_to_alpha(png);
      }
      if (colour_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
      if ((colour_type & PNG_COLOR_MASK_COLOR) == 0 && bit_depth < 8) {
        png_set_expand_gray_1_2_4_to_8(png);
      }
      if ((colour_type & PNG_COLOR_MASK_COLOR) != 0 && layout.channels > 1) {
        png_set_bgr(png);
      } else if (layout.channels > 1) {
        png_set_gray_to_rgb(png);
      }
    }
    passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    row_bytes = png_get_rowbytes(png, info);
  });

  // An interlaced image needs every row at once; otherwise one row is reused.
  const bool whole = passes > 1;
  buffer.resize(row_bytes * (whole ? static_cast<std::size_t>(rows) : 1u));
  if (whole) {
    row_pointers.resize(static_cast<std::size_t>(rows));
    for (int y = 0; y < rows; ++y) row_pointers[y] = buffer.data() + row_bytes * y;
  }
  const bool sixteen = bit_depth == 16;
  if (!raw_alpha && sixteen) eight_bit.resize(row_bytes / 2);
  const int row_width = static_cast<int>(width);
  auto deliver = [&](int y, const png_byte* row) {
    if (raw_alpha) {
      alpha_of_raw_row(row, row_width, colour_type, bit_depth, palette_alpha, sink.alpha_row(y));
      return;
    }
    if (sixteen) {
      for (std::size_t i = 0; i < eight_bit.size(); ++i) eight_bit[i] = eight(row + 2 * i);
      row = eight_bit.data();
    }
    sink.put_row(y, row);
  };
  reader.guarded([&] {
    if (whole) {
      png_read_image(png, row_pointers.data());
    } else {
      for (int y = 0; y < rows; ++y) {
        png_read_row(png, buffer.data(), nullptr);
        deliver(y, buffer.data());
      }
    }
    png_read_end(png, nullptr);
  });
  if (whole) {
    for (int y = 0; y < rows; ++y) deliver(y, row_pointers[y]);
  }
}

}  // namespace hullcook::image_detail
