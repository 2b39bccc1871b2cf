// Image reading: the header is checked and the size bounded before anything is decoded; then
// libpng, libwebp or our own BMP and TGA readers (png_decoder.cpp, ...) give the alpha channel.
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"
#include "pixel_sink.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace hullcook {
namespace {

using image_detail::fail;
using image_detail::PixelSink;

enum class Format { png, bmp, webp, tga };

std::uint32_t read_u32_be(const std::string& bytes, std::size_t at) {
  return image_detail::u32_be(bytes, at);
}
std::uint32_t read_u32_le(const std::string& bytes, std::size_t at) {
  return image_detail::u32_le(bytes, at);
}
std::uint32_t read_u24_le(const std::string& bytes, std::size_t at) {
  return read_u32_le(bytes, at) & 0xFFFFFF;
}
std::uint32_t read_u16_le(const std::string& bytes, std::size_t at) {
  return image_detail::u16_le(bytes, at);
}

std::string lower_extension(const std::string& name) {
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
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
    if (bytes.size() < 33) {
      fail(name, bytes.size() == 8 ? "truncated PNG (the file ends after the signature, before "
                                     "the IHDR header)"
                                   : "truncated PNG (the file ends inside the IHDR header)");
    }
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
    // Checked here for a clear message before the decoder reads.
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
    // Each bitstream's header ends at its own offset: a lossless (VP8L) file of a small image
    // can be 26 bytes in all, the others hold their size up to byte 30.
    auto header_ends_at = [&](std::size_t end) {
      if (bytes.size() < end) fail(name, "truncated WebP (the file ends inside the header)");
    };
    header_ends_at(16);
    // libwebp refuses a file shorter than its RIFF size as corrupt: this names the problem.
    const std::uint64_t declared = read_u32_le(bytes, 4) + 8ull;
    if (bytes.size() < declared) {
      fail(name, "truncated WebP (the file ends after " + std::to_string(bytes.size()) +
                     " of the " + std::to_string(declared) + " bytes its RIFF header declares)");
    }
    if (bytes.compare(12, 4, "VP8X") == 0) {
      header_ends_at(30);
      return {Format::webp, read_u24_le(bytes, 24) + 1ull, read_u24_le(bytes, 27) + 1ull};
    }
    if (bytes.compare(12, 4, "VP8L") == 0) header_ends_at(25);
    if (bytes.compare(12, 4, "VP8L") == 0 && std::uint8_t(bytes[20]) == 0x2f) {
      std::uint32_t bits = read_u32_le(bytes, 21);
      return {Format::webp, (bits & 0x3FFF) + 1ull, ((bits >> 14) & 0x3FFF) + 1ull};
    }
    if (bytes.compare(12, 4, "VP8 ") == 0) header_ends_at(30);
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

// Checks the header and the size, then decodes into sink.
void decode(const std::string& bytes, const std::string& name, std::uint64_t max_pixels,
            PixelSink& sink) {
  Header header = read_header(bytes, name);
  if (header.width == 0 || header.height == 0) {
    fail(name, "empty image (" + std::to_string(header.width) + "x" +
                   std::to_string(header.height) + " pixels)");
  }
  const std::uint64_t pixel_count = header.width * header.height;
  if (pixel_count > max_pixels) {
    fail(name, std::to_string(header.width) + "x" + std::to_string(header.height) + " = " +
                   std::to_string(pixel_count) + " pixels is more than --max-pixels " +
                   std::to_string(max_pixels));
  }
  if (header.width > 0x7FFFFFF || header.height > 0x7FFFFFF) {
    fail(name, "image dimensions out of range");
  }
  const int width = static_cast<int>(header.width), height = static_cast<int>(header.height);
  switch (header.format) {
    case Format::tga:
      image_detail::decode_tga(bytes, width, height, sink);
      break;
    case Format::bmp:
      image_detail::decode_bmp(bytes, sink);
      break;
    case Format::png:
      image_detail::decode_png(bytes, sink);
      break;
    case Format::webp:
      image_detail::decode_webp(bytes, width, height, sink);
      break;
  }
  if (sink.width() != width || sink.height() != height) {
    fail(name, "corrupt image (the header says " + std::to_string(width) + "x" +
                   std::to_string(height) + ", the data " + std::to_string(sink.width()) + "x" +
                   std::to_string(sink.height()) + ")");
  }
}

// The whole file in one read (no stream buffers, no copies).
std::string read_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  // Not blocking on a pipe without a writer (refused below); no effect on a regular file.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno == EISDIR) fail(name, "is a directory, not an image");
    fail(name, std::string("cannot open: ") + std::strerror(errno));
  }
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  // Its size and kind in one call (a cook of 10,000 sprites made three per image).
  struct stat status {};
  if (::fstat(fd, &status) != 0) fail(name, "cannot read the file");
  if (S_ISDIR(status.st_mode)) fail(name, "is a directory, not an image");
  // A pipe or a device may never end: images are read whole.
  if (!S_ISREG(status.st_mode)) fail(name, "not a regular file");
  auto read_some = [&](char* into, std::size_t count) {
    while (true) {
      const ssize_t got = ::read(fd, into, count);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) fail(name, "cannot read the file");
      return static_cast<std::size_t>(got);
    }
  };
  std::string bytes(static_cast<std::size_t>(std::max<off_t>(status.st_size, 0)), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const std::size_t got = read_some(bytes.data() + done, bytes.size() - done);
    if (got == 0) break;
    done += got;
  }
  bytes.resize(done);
  // A file that grew since: read on to its end.
  std::array<char, 65536> more;
  while (const std::size_t got = read_some(more.data(), more.size()))
    bytes.append(more.data(), got);
  return bytes;
}

}  // namespace

AlphaImage decode_alpha(const std::string& bytes, const std::string& name,
                        const TraceSettings& settings) {
  PixelSink sink(PixelSink::Keep::alpha, settings.color_key, name);
  decode(bytes, name, settings.max_pixels, sink);
  return sink.take_alpha();
}

AlphaImage load_alpha(const std::filesystem::path& path, const TraceSettings& settings) {
  return decode_alpha(read_file(path), path.string(), settings);
}

RgbaImage load_rgba(const std::filesystem::path& path, std::uint64_t max_pixels) {
  const std::string name = path.string();
  PixelSink sink(PixelSink::Keep::rgba, std::nullopt, name);
  decode(read_file(path), name, max_pixels, sink);
  return sink.take_rgba();
}

bool is_image_file(const std::filesystem::path& path) {
  std::string extension = lower_extension(path.string());
  return extension == ".png" || extension == ".tga" || extension == ".bmp" || extension == ".webp";
}

}  // namespace hullcook
