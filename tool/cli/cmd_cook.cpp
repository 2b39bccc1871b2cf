// hullcook cook INPUT... -o OUT.hcb|.gltf|.glb|.json|.hcf
#include "commands.h"
#include "cook_options.h"
#include "outputs.h"
#include "printable.h"
#include "progress.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/depfile.h"
#include "hullcook/cook/html_report.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/cook/process_heap.h"
#include "hullcook/cook/report.h"
#include "hullcook/core/error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace hullcook::cli {
namespace {

struct CookCommand {
  std::vector<std::string> inputs;
  std::string output;
  std::string json;
  std::string name;
  std::string depfile;
  std::string report;
  std::string html;
  bool quiet = false;
  Settings settings;
  CookOptions options;
};

// text padded to width columns: a UTF-8 name takes a column per character, not per byte.
std::string padded(const std::string& text, std::size_t width) {
  std::size_t characters = 0;
  for (unsigned char c : text) characters += (c & 0xC0) != 0x80;  // not a continuation byte
  return text + std::string(width > characters ? width - characters : 0, ' ');
}

void print_summary(const CookResult& result) {
  if (result.assets.empty()) return;  // every input skipped: print_warnings says so
  std::printf("%-56s %9s %7s %9s %13s %9s\n", "asset", "vertices", "pieces", "hulls",
              "max concavity", "ms");
  for (const CookedAsset& asset : result.assets) {
    std::printf("%s %9zu %7zu %9zu %13.4g %9.2f\n", padded(printable(asset.name), 56).c_str(),
                asset.stats.traced_vertices, asset.stats.pieces, asset.stats.hulls,
                asset.stats.max_concavity, asset.stats.total_ms);
  }
}

// Warnings go to stderr even with -q, which only drops the table: a pipeline must still see
// "no region" or a piece left out.
void print_warnings(const CookResult& result) {
  for (const CookedAsset& asset : result.assets) {
    for (const std::string& warning : asset.warnings) {
      std::fprintf(stderr, "hullcook: warning: %s: %s\n", described(asset).c_str(),
                   warning.c_str());
    }
  }
  for (const std::string& warning : result.warnings) {
    std::fprintf(stderr, "hullcook: warning: %s\n", warning.c_str());
  }
  // Once for the cook: with --lod and --max-pieces, most assets of a folder may leave some out.
  const std::size_t short_of_lods =
      std::count_if(result.assets.begin(), result.assets.end(),
                    [](const CookedAsset& asset) { return asset.lods_left_out > 0; });
  if (short_of_lods > 0) {
    std::fprintf(stderr,
                 "hullcook: warning: %zu of %zu assets leave out --lod levels finer than their "
                 "--max-pieces level (the report's \"levels\" counts each asset's)\n",
                 short_of_lods, result.assets.size());
  }
  // Skipping is asked for, image by image: said only when it leaves the output empty.
  if (result.assets.empty() && !result.skipped.empty()) {
    std::fprintf(stderr,
                 "hullcook: warning: every input is skipped by its settings (\"skip\"): the "
                 "output has no assets\n");
  }
}

// --name names the one asset of one input file: refused before cooking otherwise.
void check_asset_name(const CookCommand& command,
                      const std::vector<std::filesystem::path>& inputs) {
  std::error_code error;
  if (inputs.size() != 1 || !std::filesystem::is_regular_file(inputs.front(), error)) {
    throw UsageError("--name names the asset of one input file; cook each file on its own");
  }
  // The bundle stores a name's length in 16 bits (formats/SPEC.md §4).
  if (command.name.empty() || command.name.size() > 65535) {
    throw UsageError("--name: a name is 1 to 65535 bytes");
  }
}

// --name: the one asset of a file is `name`; with --grid its cells are name/INDEX, a sheet's
// frames name/FRAME. The default name (the file's, or a sheet's without .json) holds no '/'.
void rename_assets(CookResult& result, const std::string& name) {
  for (CookedAsset& asset : result.assets) {
    asset.name = name + asset.name.substr(std::min(asset.name.find('/'), asset.name.size()));
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
  app->add_option("inputs", command->inputs,
                  "Image files, directories, .poly files or sprite sheets (TexturePacker or "
                  "Aseprite .json)")
      // A missing input is bad input (exit 2, named by the cook), not a usage error.
      ->required();
  app->add_option("-o,--output", command->output,
                  "Output file; the writer is picked by extension: .hcb, "
                  ".gltf, .glb, .json, or .hcf: a fragment for hullcook link");
  app->add_option("--json", command->json, "Also write the debug JSON here");
  app->add_option("--name", command->name,
                  "The asset's name (default: its file name); with one input file, as when "
                  "cooking fragments one by one from a folder");
  app->add_option("--depfile", command->depfile,
                  "Also write a Make/Ninja depfile here: the outputs depend on every file read "
                  "(images, physics sidecars) and directory searched");
  app->add_option("--report", command->report,
                  "Also write per-asset figures here as JSON (vertices, pieces, hulls, bytes, ms)");
  app->add_option("--html", command->html,
                  "Also write a page here to look at (offline): each asset's sprite, outline and "
                  "hulls with its figures, sortable by pieces or time. Its times differ from run "
                  "to run; the rest of its bytes do not");
  auto* draco =
      app->add_flag("--draco", command->settings.draco, "Compress glTF meshes with Draco");
  app->add_flag("--meshopt", command->settings.meshopt,
                "Compress glTF buffers with EXT_meshopt_compression (16-bit coordinates, as "
                "gltfpack does)")
      ->excludes(draco);
  app->add_flag("-q,--quiet", command->quiet,
                "Print no progress bar and no per-asset table (warnings still go to stderr)");
  add_cook_options(*app, command->settings, command->options);
  app->callback([command, app, &action] {
    action = [command, app] {
      finish_cook_options(*app, command->settings, command->options);
      const std::vector<std::filesystem::path> outputs =
          checked_outputs("cook", command->output, command->json);
      std::vector<std::filesystem::path> inputs(command->inputs.begin(), command->inputs.end());
      for (const std::filesystem::path& output : outputs) check_not_an_input(output, inputs);
      if (!command->name.empty() || app->count("--name") > 0) check_asset_name(*command, inputs);
      check_side_outputs(command->depfile, command->report, outputs, inputs, command->html);
      // Only the debug JSON, fragments (which link may turn into JSON) and the HTML page keep
      // the outlines: without them they are freed asset by asset.
      command->settings.keep_outlines = !command->html.empty();
      for (const std::filesystem::path& output : outputs) {
        if (output.extension() == ".json" || output.extension() == ".hcf") {
          command->settings.keep_outlines = true;
        }
      }
      // A bundle is written as the cook goes (issue 19: the memory of 10,000 assets is that of
      // 100); the hulls stay in memory only when another output needs them.
      std::unique_ptr<BundleStream> stream;
      bool hulls_needed = !command->report.empty() || !command->html.empty();
      for (const std::filesystem::path& output : outputs) {
        if (output.extension() != ".hcb")
          hulls_needed = true;
        else if (!stream)
          stream = std::make_unique<BundleStream>();
      }
      command->settings.bundle_output = stream != nullptr;
      command->settings.keep_hulls = hulls_needed || !stream;
      ProgressBar progress(!command->quiet && ProgressBar::stdout_is_terminal());
      const AssetCooked on_cooked = [&stream, &progress](std::size_t index, std::size_t count,
                                                         const CookedAsset& asset) {
        if (stream) stream->add(index, asset);
        progress.advance(count);
      };
      // A cook is a batch process: its heap is kept. Not on huge pages, as a decomposition's is:
      // a cook touches tens of MB, and where the kernel compacts memory for each huge page on
      // its first fault (defrag "madvise", as on the machines we measure on) one fault can take 35
      // ms. On small pages the cook of blobs_2048 was 0.486 s against 0.510 s (median of 15,
      // paired; the slowest 0.56 s against 1.16 s), samples/sprites 0.192 s against 0.196 s.
      keep_freed_memory();
      CookResult result = cook(inputs, command->settings, on_cooked);
      if (!command->name.empty()) rename_assets(result, command->name);
      // Every file written, side outputs too: a --depfile or --report over an image found in a
      // folder, or over a settings file, replaced it (stop 58).
      std::vector<std::filesystem::path> written = outputs;
      for (const std::string* side : {&command->depfile, &command->report, &command->html}) {
        if (!side->empty()) written.emplace_back(*side);
      }
      check_not_read(result, written);
      auto files = output_files(result, outputs, command->settings, {}, stream.get());
      if (!command->depfile.empty()) {
        files.push_back(
            {command->depfile, depfile_text(outputs, cook_dependencies(result, inputs))});
      }
      if (!command->report.empty()) files.push_back({command->report, cook_report(result, true)});
      if (!command->html.empty()) files.push_back({command->html, html_report(result)});
      write_files_atomically(files);
      progress.finish();
      if (!command->quiet) print_summary(result);
      print_warnings(result);
      return 0;
    };
  });
}

const CommandRegistration registered{20, "cook", add_cook};

}  // namespace
}  // namespace hullcook::cli
