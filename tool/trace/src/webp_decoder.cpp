// WebP through libwebp, as OpenCV 4.6 read it: B, G, R with A when the bitstream has alpha.
#include "pixel_sink.h"

#include <webp/decode.h>

#include <string>
#include <vector>

namespace hullcook::image_detail {

void decode_webp(const std::string& bytes, int width, int height, PixelSink& sink) {
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(data, bytes.size(), &features) != VP8_STATUS_OK) {
    fail(sink.name(), "corrupt or unsupported WebP data");
  }
  if (features.width != width || features.height != height) {
    fail(sink.name(), "corrupt WebP (the header says " + std::to_string(width) + "x" +
                          std::to_string(height) + ", the data " + std::to_string(features.width) +
                          "x" + std::to_string(features.height) + ")");
  }
  const Layout layout = features.has_alpha ? Layout{4, true} : Layout{3, false};
  sink.start(width, height, layout);
  const std::size_t stride = static_cast<std::size_t>(width) * layout.channels;
  std::vector<std::uint8_t> pixels(stride * static_cast<std::size_t>(height));
  const std::uint8_t* decoded = layout.channels == 4
                                    ? WebPDecodeBGRAInto(data, bytes.size(), pixels.data(),
                                                         pixels.size(), static_cast<int>(stride))
                                    : WebPDecodeBGRInto(data, bytes.size(), pixels.data(),
                                                        pixels.size(), static_cast<int>(stride));
  if (!decoded) fail(sink.name(), "corrupt or unsupported WebP data");
  for (int y = 0; y < height; ++y) sink.put_row(y, pixels.data() + stride * y);
}

}  // namespace hullcook::image_detail
