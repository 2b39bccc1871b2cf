// hullcook link FRAGMENT.hcf... -o OUT.hcb|.gltf|.glb|.json
#include "commands.h"
#include "counted.h"
#include "outputs.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/depfile.h"
#include "hullcook/cook/fragment.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/cook/report.h"
#include "hullcook/core/error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

namespace hullcook::cli {
namespace {

struct LinkCommand {
  std::vector<std::string> fragments;
  std::string output;
  std::string json;
  std::string depfile;
  std::string report;
  bool draco = false;
  bool meshopt = false;
  bool quiet = false;
};

// Every fragment's assets, sorted by name as `cook DIR` orders a directory's images, so that
// the bundle does not depend on the order the fragments are given in.
CookResult link_fragments(const std::vector<std::filesystem::path>& fragments) {
  CookResult result;
  std::map<std::string, std::string> fragment_of;
  for (const std::filesystem::path& path : fragments) {
    for (CookedAsset& asset : read_fragment(path).assets) {
      auto [it, added] = fragment_of.emplace(asset.name, path.string());
      if (!added) {
        throw InputError(path.string() + ": asset '" + asset.name + "' is also in " + it->second +
                         "; give one of them another --name");
      }
      result.assets.push_back(std::move(asset));
    }
  }
  std::stable_sort(result.assets.begin(), result.assets.end(),
                   [](const CookedAsset& a, const CookedAsset& b) { return a.name < b.name; });
  return result;
}

void add_link(CLI::App& root, CommandAction& action) {
  auto command = std::make_shared<LinkCommand>();
  CLI::App* app = root.add_subcommand(
      "link",
      "Join cooked fragments (hullcook cook INPUT -o X.hcf) into one bundle, glTF or debug JSON "
      "without cooking again.\nAssets are ordered by name, as cook orders a directory, so that "
      "linking the fragments of a directory's images writes the bytes cooking it writes.");
  app->add_option("fragments", command->fragments, "Fragment files (.hcf)")
      // A missing fragment is bad input (exit 2, named by read_fragment), not a usage error.
      ->required();
  app->add_option("-o,--output", command->output,
                  "Output file; the writer is picked by extension: .hcb, .gltf, .glb, .json");
  app->add_option("--json", command->json, "Also write the debug JSON here");
  app->add_option("--depfile", command->depfile,
                  "Also write a Make/Ninja depfile here: the outputs depend on the fragments");
  app->add_option("--report", command->report,
                  "Also write per-asset figures here as JSON (vertices, pieces, hulls, bytes)");
  auto* draco = app->add_flag("--draco", command->draco, "Compress glTF meshes with Draco");
  app->add_flag("--meshopt", command->meshopt,
                "Compress glTF buffers with EXT_meshopt_compression (16-bit coordinates)")
      ->excludes(draco);
  app->add_flag("-q,--quiet", command->quiet, "Print nothing on success");
  app->callback([command, &action] {
    action = [command] {
      const std::vector<std::filesystem::path> outputs =
          checked_outputs("link", command->output, command->json);
      for (const std::filesystem::path& output : outputs) {
        if (output.extension() == ".hcf") {
          throw UsageError(output.string() +
                           ": link writes .hcb, .gltf, .glb or .json, not fragments");
        }
      }
      const std::vector<std::filesystem::path> fragments(command->fragments.begin(),
                                                         command->fragments.end());
      for (const std::filesystem::path& output : outputs) check_not_an_input(output, fragments);
      check_side_outputs(command->depfile, command->report, outputs, fragments);
      const CookResult result = link_fragments(fragments);
      Settings settings;
      settings.draco = command->draco;
      settings.meshopt = command->meshopt;
      auto files = output_files(result, outputs, settings, fragments);
      if (!command->depfile.empty()) {
        files.push_back({command->depfile, depfile_text(outputs, fragments)});
      }
      if (!command->report.empty()) files.push_back({command->report, cook_report(result, false)});
      write_files_atomically(files);
      if (!command->quiet) {
        std::printf("linked %s from %s into %s\n",
                    counted(result.assets.size(), "asset", "assets").c_str(),
                    counted(fragments.size(), "fragment", "fragments").c_str(),
                    outputs.front().string().c_str());
      }
      return 0;
    };
  });
}

const CommandRegistration registered{25, "link", add_link};

}  // namespace
}  // namespace hullcook::cli
