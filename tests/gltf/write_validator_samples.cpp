// Writes the hand-made sample assets as .gltf, .glb and Draco .glb/.gltf files into a directory,
// for the Khronos glTF validator run (run_validator.sh).
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
    };
    for (const Set& set : sets) {
      for (bool draco : {false, true}) {
        for (bool binary : {false, true}) {
          std::string name =
              std::string(set.name) + (draco ? "_draco" : "") + (binary ? ".glb" : ".gltf");
          write_file_atomically(directory / name,
                                write_gltf(set.assets, {.binary = binary, .draco = draco}));
        }
      }
    }
  } catch (const std::exception& error) {
    std::cerr << "write_validator_samples: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
