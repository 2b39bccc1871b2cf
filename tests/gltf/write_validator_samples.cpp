// Writes the hand-made sample assets and the cooked sample sprites as .gltf, .glb and Draco
// .glb/.gltf files into a directory, for the Khronos glTF validator run (run_validator.sh).
#include "sample_assets.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/gltf_writer.h"
#include "hullcook/cook/output_file.h"

#include <exception>
#include <filesystem>
#include <iostream>

// Every sample sprite, cooked as scripts/cook-samples does: real outlines, three levels.
std::vector<hullcook::CookedAsset> sprites_cooked_like_cook_samples() {
  hullcook::Settings settings;
  settings.tau = hullcook::Tolerance{2.0, false};
  settings.lods = {hullcook::Tolerance{8.0, false}, hullcook::Tolerance{0.5, false}};
  settings.pixels_per_unit = 32;
  return hullcook::cook({std::filesystem::path(HULLCOOK_SOURCE_DIR) / "samples/sprites"}, settings)
      .assets;
}

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
        {"sprites", sprites_cooked_like_cook_samples()},
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
