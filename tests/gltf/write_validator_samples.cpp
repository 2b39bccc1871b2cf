// Writes the hand-made sample assets and the cooked sample sprites as .gltf and .glb files, plain,
// Draco and meshopt, into a directory, for the Khronos glTF validator run (run_validator.sh).
#include "sample_assets.h"

#include "hullcook/cook/gltf_writer.h"
#include "hullcook/cook/output_file.h"

#include <exception>
#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_validator_samples OUTPUT_DIRECTORY\n";
    return 1;
  }
  using namespace hullcook;
  try {
    const std::filesystem::path directory = argv[1];
    std::filesystem::create_directories(directory);
    struct Set {
      const char* name;
      std::vector<CookedAsset> assets;
    };
    const Set sets[] = {
        {"all", test::all_sample_assets()},
        {"many", {test::many_hulls_asset(400)}},
        {"physics", {test::physics_asset(), test::sensor_asset()}},
        {"empty", {test::empty_asset()}},
        {"nothing", {}},
        // Every sample sprite, cooked as scripts/cook-samples does: real outlines, three levels.
        {"sprites", test::sample_sprites({Tolerance{8.0, false}, Tolerance{0.5, false}})},
    };
    for (const Set& set : sets) {
      for (const char* compression : {"", "_draco", "_meshopt"}) {
        for (bool binary : {false, true}) {
          const GltfOptions options{.binary = binary,
                                    .draco = compression == std::string("_draco"),
                                    .meshopt = compression == std::string("_meshopt")};
          std::string name = std::string(set.name) + compression + (binary ? ".glb" : ".gltf");
          write_file_atomically(directory / name, write_gltf(set.assets, options));
        }
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "write_validator_samples: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
