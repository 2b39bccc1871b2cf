// Image reading: header checks before decoding, then OpenCV (PNG, BMP, WebP) or our own TGA and
// 32-bit BMP readers, reduced to an 8-bit alpha channel.
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"

#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>

namespace hullcook {
namespace {

enum class Format { png, bmp, webp, tga };

const char* format_name(Format format) {
  switch (format) {
    case Format::png:
      return "PNG";
    case Format::bmp:
      return "BMP";
    case Format::webp:
      return "WebP";
    case Format::tga:
      return "TGA";
  }
  return "image";
}

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
  throw InputError(name + ": " + problem);
}

std::uint32_t read_u32_be(const std::string& bytes, std::size_t at) {
  auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(std::uint8_t(bytes[at + i]));
  };
  return byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
}
std::uint32_t read_u32_le(const std::string& bytes, std::size_t at) {
  auto byte = [&](std::size_t i) {
    return static_cast<std::uint32_t>(std::uint8_t(bytes[at + i]));
  };
  return byte(3) << 24 | byte(2) << 16 | byte(1) << 8 | byte(0);
}
std::uint32_t read_u24_le(const std::string& bytes, std::size_t at) {
  return read_u32_le(bytes, at) & 0xFFFFFF;
}
std::uint32_t read_u16_le(const std::string& bytes, std::size_t at) {
  return static_cast<std::uint32_t>(std::uint8_t(bytes[at])) |
         static_cast<std::uint32_t>(std::uint8_t(bytes[at + 1])) << 8;
}

std::string lower_extension(const std::string& name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

std::uint32_t crc32(const char* data, std::size_t size, std::uint32_t crc = 0) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i)
    crc = table[(crc ^ std::uint8_t(data[i])) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

struct Header {
  Format format;
  std::uint64_t width = 0;
  std::uint64_t height = 0;
};

// Reads the dimensions without decoding; throws on anything that is not a plausible image.
Header read_header(const std::string& bytes, const std::string& name) {
  static const char png_signature[] = "\x89PNG\r\n\x1a\n";
  if (bytes.size() >= 8 && bytes.compare(0, 8, png_signature, 8) == 0) {
    if (bytes.size() < 33) fail(name, "truncated PNG (the file ends inside the IHDR header)");
    if (read_u32_be(bytes, 8) != 13 || bytes.compare(12, 4, "IHDR") != 0) {
      fail(name, "corrupt PNG (the first chunk is not a 13-byte IHDR)");
    }
    return {Format::png, read_u32_be(bytes, 16), read_u32_be(bytes, 20)};
  }
  if (bytes.size() >= 2 && bytes.compare(0, 2, "BM") == 0) {
    if (bytes.size() < 26) fail(name, "truncated BMP (the file ends inside the header)");
    std::uint32_t info_size = read_u32_le(bytes, 14);
    if (info_size == 12) return {Format::bmp, read_u16_le(bytes, 18), read_u16_le(bytes, 20)};
    if (info_size < 40)
      fail(name, "corrupt BMP (unknown header size " + std::to_string(info_size) + ")");
    // OpenCV prints to stderr on a short BMP, so the sizes are checked here.
    if (bytes.size() < 14 + std::uint64_t{info_size}) {
      fail(name, "truncated BMP (the file ends inside the header)");
    }
    auto magnitude = [](std::uint32_t v) {
      auto value = static_cast<std::int64_t>(static_cast<std::int32_t>(v));
      return static_cast<std::uint64_t>(value < 0 ? -value : value);
    };
    const std::uint64_t width = magnitude(read_u32_le(bytes, 18));
    const std::uint64_t height = magnitude(read_u32_le(bytes, 22));
    const std::uint32_t bits = read_u16_le(bytes, 28), compression = read_u32_le(bytes, 30);
    const std::uint64_t stride = (width * bits + 31) / 32 * 4;
    const bool plausible = width <= 0xFFFFFF && height <= 0xFFFFFF && bits <= 64;  // no overflow
    if ((compression == 0 || compression == 3) && plausible &&
        read_u32_le(bytes, 10) + stride * height > bytes.size()) {
      fail(name, "truncated BMP (the pixel data ends before the last row)");
    }
    return {Format::bmp, width, height};
  }
  if (bytes.size() >= 12 && bytes.compare(0, 4, "RIFF") == 0 && bytes.compare(8, 4, "WEBP") == 0) {
    if (bytes.size() < 30) fail(name, "truncated WebP (the file ends inside the header)");
    if (bytes.compare(12, 4, "VP8X") == 0) {
      return {Format::webp, read_u24_le(bytes, 24) + 1ull, read_u24_le(bytes, 27) + 1ull};
    }
    if (bytes.compare(12, 4, "VP8L") == 0 && std::uint8_t(bytes[20]) == 0x2f) {
      std::uint32_t bits = read_u32_le(bytes, 21);
      return {Format::webp, (bits & 0x3FFF) + 1ull, ((bits >> 14) & 0x3FFF) + 1ull};
    }
    if (bytes.compare(12, 4, "VP8 ") == 0 && bytes.compare(23, 3, "\x9d\x01\x2a", 3) == 0) {
      return {Format::webp, read_u16_le(bytes, 26) & 0x3FFFu, read_u16_le(bytes, 28) & 0x3FFFu};
    }
    fail(name, "corrupt WebP (unknown bitstream chunk)");
  }
  std::string extension = lower_extension(name);
  if (extension == ".tga") {
    if (bytes.size() < 18) fail(name, "truncated TGA (the file ends inside the 18-byte header)");
    return {Format::tga, read_u16_le(bytes, 12), read_u16_le(bytes, 14)};
  }
  if (bytes.empty()) fail(name, "empty file, not an image");
  if (extension == ".png") fail(name, "not a PNG file (the PNG signature is missing)");
  if (extension == ".bmp") fail(name, "not a BMP file (the 'BM' signature is missing)");
  if (extension == ".webp") fail(name, "not a WebP file (the RIFF/WEBP signature is missing)");
  fail(name, "not a PNG, BMP, WebP or TGA image (unrecognised signature)");
}

// libpng prints its own errors to stderr and OpenCV reports them only as an empty image, so the
// chunk structure and checksums are verified here first, for a clear message.
void check_png_chunks(const std::string& bytes, const std::string& name) {
  std::size_t at = 8;
  while (true) {
    if (at + 12 > bytes.size()) {
      fail(name, "truncated PNG (the file ends at byte " + std::to_string(bytes.size()) +
                     " before the IEND chunk)");
    }
    std::uint64_t length = read_u32_be(bytes, at);
    std::string type = bytes.substr(at + 4, 4);
    if (at + 12 + length > bytes.size()) {
      fail(name, "truncated PNG (the " + type + " chunk at byte " + std::to_string(at) +
                     " runs past the end of the file)");
    }
    std::uint32_t stored = read_u32_be(bytes, at + 8 + length);
    if (crc32(bytes.data() + at + 4, length + 4) != stored) {
      fail(name, "corrupt PNG (bad checksum in the " + type + " chunk at byte " +
                     std::to_string(at) + ")");
    }
    if (type == "IEND") return;
    at += 12 + length;
  }
}

// Decoded pixels before alpha extraction: 8-bit, 1 to 4 channels in OpenCV's B, G, R, A order.
struct Pixels {
  cv::Mat mat;
  bool has_alpha = false;
};

// TGA: no OpenCV codec. Types 1/9 (colour-mapped), 2/10 (true colour), 3/11 (grey), RLE or not.
Pixels decode_tga(const std::string& bytes, const std::string& name, int width, int height) {
  auto u8 = [&](std::size_t at) { return std::uint8_t(bytes[at]); };
  int id_length = u8(0), map_type = u8(1), image_type = u8(2);
  int map_first = static_cast<int>(read_u16_le(bytes, 3));
  int map_length = static_cast<int>(read_u16_le(bytes, 5));
  int map_entry_bits = u8(7), pixel_bits = u8(16), descriptor = u8(17);
  bool rle = image_type >= 9;
  int base_type = rle ? image_type - 8 : image_type;
  bool supported = (base_type == 1 && map_type == 1 && pixel_bits == 8 &&
                    (map_entry_bits == 24 || map_entry_bits == 32)) ||
                   (base_type == 2 && (pixel_bits == 16 || pixel_bits == 24 || pixel_bits == 32)) ||
                   (base_type == 3 && (pixel_bits == 8 || pixel_bits == 16));
  if (!supported) {
    fail(name, "unsupported TGA (image type " + std::to_string(image_type) + ", " +
                   std::to_string(pixel_bits) + " bits per pixel)");
  }
  std::size_t at = 18 + static_cast<std::size_t>(id_length);
  std::vector<cv::Vec4b> palette;
  if (map_type == 1) {
    std::size_t entry_bytes = (map_entry_bits + 7) / 8;
    if (at + entry_bytes * map_length > bytes.size()) fail(name, "truncated TGA (colour map)");
    if (base_type == 1) {
      for (int i = 0; i < map_length; ++i, at += entry_bytes) {
        palette.emplace_back(u8(at), u8(at + 1), u8(at + 2), entry_bytes == 4 ? u8(at + 3) : 255);
      }
    } else {
      at += entry_bytes * map_length;
    }
  }
  const std::size_t pixel_bytes = pixel_bits / 8;
  auto to_bgra = [&](std::size_t p) -> cv::Vec4b {
    switch (base_type) {
      case 1: {
        int index = u8(p) - map_first;
        if (index < 0 || index >= static_cast<int>(palette.size())) {
          fail(name, "corrupt TGA (colour index " + std::to_string(u8(p)) + " outside the map)");
        }
        return palette[index];
      }
      case 3:
        return {u8(p), u8(p), u8(p), pixel_bits == 16 ? u8(p + 1) : std::uint8_t(255)};
      default:
        if (pixel_bits == 16) {
          std::uint32_t v = read_u16_le(bytes, p);
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
  std::vector<cv::Vec4b> pixels;
  pixels.reserve(count);
  while (pixels.size() < count) {
    std::size_t run = 1;
    bool repeat = false;
    if (rle) {
      if (at >= bytes.size()) break;
      std::uint8_t packet = u8(at++);
      run = (packet & 0x7F) + 1u;
      repeat = (packet & 0x80) != 0;
    }
    std::size_t need = repeat ? pixel_bytes : pixel_bytes * run;
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
  Pixels result;
  result.mat = cv::Mat(height, width, CV_8UC4);
  bool bottom_up = (descriptor & 0x20) == 0, right_to_left = (descriptor & 0x10) != 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      int row = bottom_up ? height - 1 - y : y, column = right_to_left ? width - 1 - x : x;
      result.mat.at<cv::Vec4b>(row, column) = pixels[static_cast<std::size_t>(y) * width + x];
    }
  }
  // 16-bit true colour has its attribute bit, 32-bit its fourth byte, grey 16-bit its second.
  result.has_alpha = (base_type == 2 && pixel_bits != 24) || (base_type == 3 && pixel_bits == 16) ||
                     (base_type == 1 && map_entry_bits == 32);
  return result;
}

// OpenCV ignores the fourth byte of 32-bit BMPs, where many tools store alpha. Uncompressed
// (BI_RGB) or BI_BITFIELDS with the standard BGRA masks is read here; an all-zero fourth byte
// means "unused" by the BMP convention, so such an image has no alpha.
std::optional<Pixels> decode_bmp32(const std::string& bytes, const std::string& name) {
  if (bytes.size() < 54) return std::nullopt;
  std::uint32_t info_size = read_u32_le(bytes, 14);
  if (info_size < 40 || read_u16_le(bytes, 28) != 32) return std::nullopt;
  std::uint32_t compression = read_u32_le(bytes, 30);
  if (compression == 3) {
    bool standard = info_size >= 56 && bytes.size() >= 14 + 56 &&
                    read_u32_le(bytes, 54) == 0x00FF0000 && read_u32_le(bytes, 58) == 0x0000FF00 &&
                    read_u32_le(bytes, 62) == 0x000000FF && read_u32_le(bytes, 66) == 0xFF000000;
    if (!standard) return std::nullopt;
  } else if (compression != 0) {
    return std::nullopt;
  }
  auto width = static_cast<std::int32_t>(read_u32_le(bytes, 18));
  auto height = static_cast<std::int32_t>(read_u32_le(bytes, 22));
  bool top_down = height < 0;
  int rows = top_down ? -height : height;
  std::size_t offset = read_u32_le(bytes, 10);
  std::size_t size = static_cast<std::size_t>(width) * 4 * static_cast<std::size_t>(rows);
  if (offset > bytes.size() || bytes.size() - offset < size) {
    fail(name, "truncated BMP (pixel data ends early)");
  }
  Pixels result;
  result.mat = cv::Mat(rows, width, CV_8UC4);
  for (int y = 0; y < rows; ++y) {
    const char* source = bytes.data() + offset + static_cast<std::size_t>(y) * width * 4;
    std::memcpy(result.mat.ptr(top_down ? y : rows - 1 - y), source,
                static_cast<std::size_t>(width) * 4);
  }
  std::vector<cv::Mat> channels;
  cv::split(result.mat, channels);
  result.has_alpha = cv::countNonZero(channels[3]) > 0;
  return result;
}

void silence_opencv_logging() {
  static std::once_flag once;
  std::call_once(once,
                 [] { cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT); });
}

Pixels decode_with_opencv(const std::string& bytes, const std::string& name, Format format) {
  silence_opencv_logging();
  cv::Mat raw;
  try {
    cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8U,
                   const_cast<char*>(bytes.data()));  // imdecode only reads it
    raw = cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    fail(name, std::string("corrupt ") + format_name(format) + " (" + e.err + ")");
  }
  if (raw.empty())
    fail(name, std::string("corrupt or unsupported ") + format_name(format) + " data");
  if (raw.depth() == CV_16U) {
    cv::Mat eight;
    raw.convertTo(eight, CV_8U, 1.0 / 257.0);
    raw = eight;
  } else if (raw.depth() != CV_8U) {
    fail(name, std::string("unsupported ") + format_name(format) + " sample type");
  }
  Pixels result;
  result.mat = raw;
  result.has_alpha = raw.channels() == 4 || raw.channels() == 2;
  return result;
}

AlphaImage to_alpha(const Pixels& pixels, const std::string& name, const TraceSettings& settings) {
  const cv::Mat& mat = pixels.mat;
  const int channels = mat.channels();
  if (!pixels.has_alpha && !settings.color_key) {
    fail(name,
         "the image has no alpha channel; give a colour key (--color-key #RRGGBB) to trace "
         "it");
  }
  AlphaImage image;
  image.width = mat.cols;
  image.height = mat.rows;
  image.alpha.resize(static_cast<std::size_t>(mat.cols) * static_cast<std::size_t>(mat.rows));
  const int alpha_channel = channels == 2 ? 1 : 3;
  for (int y = 0; y < mat.rows; ++y) {
    const std::uint8_t* row = mat.ptr<std::uint8_t>(y);
    std::uint8_t* out = image.alpha.data() + static_cast<std::size_t>(y) * mat.cols;
    for (int x = 0; x < mat.cols; ++x) {
      const std::uint8_t* p = row + static_cast<std::size_t>(x) * channels;
      std::uint8_t alpha = pixels.has_alpha ? p[alpha_channel] : 255;
      if (settings.color_key) {
        const auto& key = *settings.color_key;  // R, G, B
        bool keyed = channels <= 2 ? (p[0] == key[0] && p[0] == key[1] && p[0] == key[2])
                                   : (p[2] == key[0] && p[1] == key[1] && p[0] == key[2]);
        if (keyed) alpha = 0;
      }
      out[x] = alpha;
    }
  }
  return image;
}

}  // namespace

AlphaImage decode_alpha(const std::string& bytes, const std::string& name,
                        const TraceSettings& settings) {
  Header header = read_header(bytes, name);
  if (header.width == 0 || header.height == 0) {
    fail(name, "empty image (" + std::to_string(header.width) + "x" +
                   std::to_string(header.height) + " pixels)");
  }
  const std::uint64_t pixel_count = header.width * header.height;
  if (pixel_count > settings.max_pixels) {
    fail(name, std::to_string(header.width) + "x" + std::to_string(header.height) + " = " +
                   std::to_string(pixel_count) + " pixels is more than --max-pixels " +
                   std::to_string(settings.max_pixels));
  }
  if (header.width > 0x7FFFFFF || header.height > 0x7FFFFFF) {
    fail(name, "image dimensions out of range");
  }
  const int width = static_cast<int>(header.width), height = static_cast<int>(header.height);
  Pixels pixels;
  switch (header.format) {
    case Format::tga:
      pixels = decode_tga(bytes, name, width, height);
      break;
    case Format::bmp:
      if (auto bmp32 = decode_bmp32(bytes, name)) {
        pixels = std::move(*bmp32);
        break;
      }
      pixels = decode_with_opencv(bytes, name, header.format);
      break;
    case Format::png:
      check_png_chunks(bytes, name);
      pixels = decode_with_opencv(bytes, name, header.format);
      break;
    case Format::webp:
      pixels = decode_with_opencv(bytes, name, header.format);
      break;
  }
  if (pixels.mat.cols != width || pixels.mat.rows != height) {
    fail(name, std::string("corrupt ") + format_name(header.format) + " (the header says " +
                   std::to_string(width) + "x" + std::to_string(height) + ", the data " +
                   std::to_string(pixels.mat.cols) + "x" + std::to_string(pixels.mat.rows) + ")");
  }
  return to_alpha(pixels, name, settings);
}

AlphaImage load_alpha(const std::filesystem::path& path, const TraceSettings& settings) {
  const std::string name = path.string();
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) fail(name, "is a directory, not an image");
  std::ifstream file(path, std::ios::binary);
  if (!file) fail(name, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad()) fail(name, "cannot read the file");
  return decode_alpha(contents.str(), name, settings);
}

bool is_image_file(const std::filesystem::path& path) {
  std::string extension = lower_extension(path.string());
  return extension == ".png" || extension == ".tga" || extension == ".bmp" || extension == ".webp";
}

}  // namespace hullcook
