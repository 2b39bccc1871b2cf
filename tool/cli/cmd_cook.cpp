// hullcook cook INPUT... -o OUT.hcb|.gltf|.glb|.json
#include "commands.h"
#include "cook_options.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace hullcook::cli {
namespace {

struct CookCommand {
  std::vector<std::string> inputs;
  std::string output;
  std::string json;
  bool quiet = false;
  Settings settings;
  CookOptions options;
};

void print_summary(const CookResult& result) {
  std::printf("%-56s %9s %7s %9s %13s %9s\n", "asset", "vertices", "pieces", "hulls",
              "max concavity", "ms");
  for (const CookedAsset& asset : result.assets) {
    std::size_t hulls = asset.levels.empty() ? 0 : asset.levels.front().hulls.size();
    std::printf("%-56s %9zu %7zu %9zu %13.4g %9.2f\n", asset.name.c_str(),
                asset.stats.traced_vertices, asset.stats.pieces, hulls, asset.stats.max_concavity,
                asset.stats.total_ms);
  }
}

// Warnings go to stderr even with -q, which only drops the table: a pipeline must still see
// "nothing opaque" or a piece left out.
void print_warnings(const CookResult& result) {
  for (const CookedAsset& asset : result.assets) {
    for (const std::string& warning : asset.warnings) {
      std::fprintf(stderr, "hullcook: warning: %s: %s\n", asset.source.c_str(), warning.c_str());
    }
  }
}

void add_cook(CLI::App& root, CommandAction& action) {
  auto command = std::make_shared<CookCommand>();
  CLI::App* app =
      root.add_subcommand("cook",
                          "Trace images (or read .poly files), decompose them and write "
                          "engine-ready hulls.\n"
                          "Directories are searched for images recursively; each image is "
                          "one asset named by its "
                          "path relative to the directory.");
  app->add_option("inputs", command->inputs, "Image files, directories or .poly files")
      ->required()
      ->check(CLI::ExistingPath);
  app->add_option("-o,--output", command->output,
                  "Output file; the writer is picked by extension: .hcb, "
                  ".gltf, .glb, .json");
  app->add_option("--json", command->json, "Also write the debug JSON here");
  auto* draco =
      app->add_flag("--draco", command->settings.draco, "Compress glTF meshes with Draco");
  app->add_flag("--meshopt", command->settings.meshopt,
                "Compress glTF buffers with EXT_meshopt_compression (16-bit coordinates, as "
                "gltfpack does)")
      ->excludes(draco);
  app->add_flag("-q,--quiet", command->quiet,
                "Print no per-asset table (warnings still go to stderr)");
  add_cook_options(*app, command->settings, command->options);
  app->callback([command, app, &action] {
    action = [command, app] {
      if (command->output.empty() && command->json.empty()) {
        throw UsageError(
            "cook: give an output with -o "
            "OUT.hcb|.gltf|.glb|.json or --json OUT");
      }
      finish_cook_options(*app, command->settings, command->options);
      // What can be refused before cooking is: a long cook must not end in a usage error.
      std::vector<std::filesystem::path> outputs;
      if (!command->output.empty()) outputs.emplace_back(command->output);
      if (!command->json.empty()) {
        if (std::filesystem::path(command->json).extension() != ".json") {
          throw UsageError("--json " + command->json + ": the debug JSON is written as .json");
        }
        outputs.emplace_back(command->json);
      }
      for (const std::filesystem::path& output : outputs) check_output_path(output);
      std::error_code error;
      if (outputs.size() == 2 && std::filesystem::weakly_canonical(outputs[0], error) ==
                                     std::filesystem::weakly_canonical(outputs[1], error)) {
        throw UsageError("-o and --json name the same file: " + command->json);
      }
      std::vector<std::filesystem::path> inputs(command->inputs.begin(), command->inputs.end());
      for (const std::filesystem::path& output : outputs) check_not_an_input(output, inputs);
      CookResult result = cook(inputs, command->settings);
      write_outputs(result, outputs, command->settings);
      if (!command->quiet) print_summary(result);
      print_warnings(result);
      return 0;
    };
  });
}

const CommandRegistration registered{20, add_cook};

}  // namespace
}  // namespace hullcook::cli
