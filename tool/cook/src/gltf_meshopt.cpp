#include "gltf_meshopt.h"

#include "hullcook/cook/meshopt_library.h"
#include "hullcook/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace hullcook {

Quantization Quantization::of(const CookedAsset& asset) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const CookedLevel& level : asset.levels) {
    for (const Ring& hull : level.hulls) {
      for (const Vec2& v : hull) {
        min_x = std::min(min_x, v.x), max_x = std::max(max_x, v.x);
        min_y = std::min(min_y, v.y), max_y = std::max(max_y, v.y);
      }
    }
  }
  Quantization grid;
  if (!(min_x <= max_x)) return grid;  // no vertex
  const double tau = asset.levels.empty() ? asset.tau : asset.levels.front().tau;
  const double extent = std::max(max_x - min_x, max_y - min_y);
  grid.step = std::max({std::sqrt(2.0) * 0.01 * tau,
                        std::sqrt(2.0) / (64.0 * asset.pixels_per_unit), extent / 65000.0});
  grid.origin = {0.5 * (min_x + max_x), 0.5 * (min_y + max_y)};
  // About the origin, the int16 range holds 65 534 quanta less the rounding of both ends. (The
  // step's own 65 000 may come back a few ulps over 65 000 when the extent sets it: the test
  // against 65 000 refused hulls 1e6 wide.)
  constexpr double kQuantaAboutTheOrigin = 65532.0;
  if (!(grid.step > 0.0) || !std::isfinite(grid.step) ||
      extent / grid.step > kQuantaAboutTheOrigin) {
    throw OutputError("asset " + asset.name + ": its hulls do not fit a 16-bit grid");
  }
  return grid;
}

std::int16_t Quantization::x(double value) const {
  return static_cast<std::int16_t>(std::lround((value - origin.x) / step));
}
std::int16_t Quantization::y(double value) const {
  return static_cast<std::int16_t>(std::lround((value - origin.y) / step));
}

std::string meshopt_compress(std::string_view data, std::size_t stride, MeshoptMode mode) {
  std::string problem;
  const MeshoptLibrary* meshopt = meshopt_library(&problem);
  if (meshopt == nullptr) throw OutputError("cannot compress with meshoptimizer: " + problem);
  const std::size_t count = data.size() / stride;
  std::vector<unsigned char> out;
  std::size_t size = 0;
  if (mode == MeshoptMode::attributes) {
    out.resize(meshopt->encodeVertexBufferBound(count, stride));
    size = meshopt->encodeVertexBuffer(out.data(), out.size(), data.data(), count, stride);
  } else {
    std::vector<unsigned int> indices(count);
    for (std::size_t i = 0; i < count; ++i) {
      if (stride == 2) {
        std::uint16_t value;
        std::memcpy(&value, data.data() + 2 * i, 2);
        indices[i] = value;
      } else {
        std::memcpy(&indices[i], data.data() + 4 * i, 4);
      }
    }
    const unsigned int vertices =
        indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end()) + 1;
    // Version 1 of the index codec, the one EXT_meshopt_compression's decoders read.
    meshopt->encodeIndexVersion(1);
    out.resize(meshopt->encodeIndexBufferBound(count, vertices));
    size = meshopt->encodeIndexBuffer(out.data(), out.size(), indices.data(), count);
  }
  if (size == 0) throw OutputError("meshoptimizer could not compress a bufferView");
  return std::string(reinterpret_cast<const char*>(out.data()), size);
}

}  // namespace hullcook
