#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/debug_json.h"
#include "hullcook/cook/gltf_writer.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"

namespace hullcook {

void write_output(const CookResult& result, const std::filesystem::path& path,
                  const Settings& settings) {
  std::string extension = path.extension().string();
  std::string bytes;
  if (extension == ".json") {
    bytes = debug_json(result.assets);
  } else if (extension == ".hcb") {
    bytes = write_bundle(result.assets);
  } else if (extension == ".gltf" || extension == ".glb") {
    bytes = write_gltf(result.assets, GltfOptions{extension == ".glb", settings.draco});
  } else {
    throw UsageError(path.string() + ": unknown output format '" + extension +
                     "'; use .hcb, .gltf, .glb or .json");
  }
  write_file_atomically(path, bytes);
}

}  // namespace hullcook
