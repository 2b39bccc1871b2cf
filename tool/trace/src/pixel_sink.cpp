// The decoders' common end: rows in OpenCV's layout to an alpha plane or RGBA.
#include "pixel_sink.h"

#include "hullcook/core/error.h"

#include <cstring>

namespace hullcook::image_detail {

void fail(const std::string& name, const std::string& problem) {
  throw InputError(name + ": " + problem);
}

void PixelSink::start(int width, int height, Layout layout) {
  if (keep_ == Keep::alpha && !layout.has_alpha && !colour_key_) {
    fail(name_,
         "the image has no alpha channel; give a colour key to trace it (--color-key #RRGGBB, "
         "or \"color_key\" in a hullcook.json rule or sidecar for it)");
  }
  width_ = width;
  height_ = height;
  layout_ = layout;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  pixels_.resize(keep_ == Keep::alpha ? count : count * 4);
}

void PixelSink::put_row(int y, const std::uint8_t* samples) {
  const int channels = layout_.channels;
  const bool has_alpha = layout_.has_alpha;
  if (keep_ == Keep::rgba) {
    std::uint8_t* out = pixels_.data() + static_cast<std::size_t>(y) * width_ * 4;
    for (int x = 0; x < width_; ++x, samples += channels, out += 4) {
      if (channels == 1) {
        out[0] = out[1] = out[2] = samples[0];
      } else {
        out[0] = samples[2], out[1] = samples[1], out[2] = samples[0];
      }
      out[3] = has_alpha ? samples[3] : 255;
    }
    return;
  }
  std::uint8_t* out = alpha_row(y);
  if (!colour_key_) {
    for (int x = 0; x < width_; ++x) out[x] = samples[static_cast<std::size_t>(x) * 4 + 3];
    return;
  }
  const auto& key = *colour_key_;  // R, G, B
  for (int x = 0; x < width_; ++x, samples += channels) {
    const bool keyed = channels == 1
                           ? samples[0] == key[0] && samples[0] == key[1] && samples[0] == key[2]
                           : samples[2] == key[0] && samples[1] == key[1] && samples[0] == key[2];
    out[x] = keyed ? 0 : (has_alpha ? samples[3] : 255);
  }
}

AlphaImage PixelSink::take_alpha() {
  AlphaImage image;
  image.width = width_;
  image.height = height_;
  image.alpha = std::move(pixels_);
  return image;
}

RgbaImage PixelSink::take_rgba() {
  RgbaImage image;
  image.width = width_;
  image.height = height_;
  image.has_alpha = layout_.has_alpha;
  image.rgba = std::move(pixels_);
  return image;
}

}  // namespace hullcook::image_detail
