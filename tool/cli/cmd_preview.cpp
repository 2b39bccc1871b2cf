// hullcook preview INPUT [cook options] -o OUT.png|OUT.svg
#include "commands.h"
#include "cook_options.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/cook/preview.h"
#include "hullcook/core/error.h"
#include "hullcook/trace/trace.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

namespace hullcook::cli {
namespace {

struct PreviewCommand {
  std::filesystem::path input;
  std::filesystem::path output;
  Settings settings;
  CookOptions options;
};

int run_preview(const CLI::App& command, PreviewCommand& preview) {
  finish_cook_options(command, preview.settings, preview.options);
  std::string extension = preview.output.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png" && extension != ".svg") {
    throw UsageError("-o " + preview.output.string() + ": a preview is written as .png or .svg");
  }
  std::error_code error;
  if (std::filesystem::is_directory(preview.input, error)) {
    throw UsageError(preview.input.string() + ": preview draws one file, not a directory");
  }
  check_not_an_input(preview.output, {preview.input});
  CookResult result = cook({preview.input}, preview.settings);
  if (result.assets.empty()) {
    throw InputError(preview.input.string() + (result.skipped.empty()
                                                   ? ": nothing to draw"
                                                   : ": skipped by its settings (\"skip\"): "
                                                     "nothing to draw"));
  }
  const CookedAsset& asset = result.assets.front();
  for (const std::string& warning : asset.warnings)
    std::cerr << "hullcook: warning: " << warning << "\n";
  std::filesystem::path image =
      is_image_file(preview.input) ? preview.input : std::filesystem::path{};
  render_preview(image, asset, preview.output);
  std::cout << preview.output.string() << ": " << asset.stats.traced_vertices
            << " vertices traced, " << asset.stats.pieces << " pieces, " << asset.stats.hulls
            << " hulls\n";
  return 0;
}

void add_preview(CLI::App& root, CommandAction& action) {
  auto preview = std::make_shared<PreviewCommand>();
  CLI::App* command = root.add_subcommand(
      "preview",
      "Cook one sprite and draw it with its traced outline (red), the cuts between pieces "
      "(yellow) and the pieces' hulls (coloured), scaled up for small sprites");
  command->add_option("input", preview->input, "An image (.png .tga .bmp .webp) or a .poly file")
      ->required();
  command->add_option("-o,--output", preview->output, "The picture to write: OUT.png or OUT.svg")
      ->required();
  add_cook_options(*command, preview->settings, preview->options);
  command->callback([command, preview, &action] {
    action = [command, preview] { return run_preview(*command, *preview); };
  });
}

const CommandRegistration registered{30, "preview", add_preview};

}  // namespace
}  // namespace hullcook::cli
