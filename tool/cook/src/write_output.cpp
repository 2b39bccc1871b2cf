#include "asset_settings.h"
#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/cook.h"
#include "hullcook/cook/debug_json.h"
#include "hullcook/cook/fragment.h"
#include "hullcook/cook/gltf_writer.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"
#include "utf8_names.h"

#include <functional>
#include <set>
#include <string>
#include <system_error>

namespace hullcook {
namespace {

enum class OutputFormat { json, bundle, gltf, glb, fragment };

OutputFormat output_format(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".json") return OutputFormat::json;
  if (extension == ".hcb") return OutputFormat::bundle;
  if (extension == ".gltf") return OutputFormat::gltf;
  if (extension == ".glb") return OutputFormat::glb;
  if (extension == ".hcf") return OutputFormat::fragment;
  throw UsageError(path.string() + ": unknown output format '" + extension +
                   "'; use .hcb, .gltf, .glb, .json or .hcf");
}

std::string output_bytes(const CookResult& result, const std::filesystem::path& path,
                         const Settings& settings) {
  const OutputFormat format = output_format(path);
  // Asked of the outputs alone: `inspect --json` of a bundle, which keeps the bytes, prints the
  // names as the debug JSON does.
  if (format == OutputFormat::json) refuse_names_alike_in_utf8(result.assets, "debug JSON");
  if (format == OutputFormat::gltf || format == OutputFormat::glb) {
    refuse_names_alike_in_utf8(result.assets, "glTF");
  }
  switch (format) {
    case OutputFormat::json:
      return debug_json(result.assets);
    case OutputFormat::bundle:
      return write_bundle(result.assets);
    case OutputFormat::gltf:
    case OutputFormat::glb:
      return write_gltf(result.assets,
                        GltfOptions{format == OutputFormat::glb, settings.draco, settings.meshopt});
    case OutputFormat::fragment:
      return write_fragment(result.assets, settings);
  }
  return {};
}

}  // namespace

void check_output_path(const std::filesystem::path& path) {
  output_format(path);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw OutputError(path.string() + ": cannot write: it is a directory");
  }
  check_directory_of(path);
}

void for_each_file_read(const CookResult& result,
                        const std::function<void(const std::filesystem::path&)>& visit) {
  AssetSettings settings_files;
  settings_files.use_listing(result.listed);
  std::set<std::string> seen;
  for (const CookedAsset& asset : result.assets) {
    // A sheet's cells share their source and its settings files.
    if (!seen.insert(asset.source).second) continue;
    visit(asset.source);
    const std::filesystem::path sidecar = physics_sidecar(asset.source);
    if (settings_files.exists(sidecar)) visit(sidecar);
    for (const std::filesystem::path& file : settings_files.files_for(asset.source)) visit(file);
  }
  for (const std::filesystem::path& image : result.sheet_images) visit(image);
  // What made them no assets: un-skipping one must cook again.
  for (const std::filesystem::path& input : result.skipped) {
    for (const std::filesystem::path& file : settings_files.files_for(input)) visit(file);
  }
}

std::vector<std::filesystem::path> files_read(const CookResult& result) {
  std::vector<std::filesystem::path> files;
  for_each_file_read(result, [&](const std::filesystem::path& file) { files.push_back(file); });
  return files;
}

void check_not_read(const CookResult& result, const std::vector<std::filesystem::path>& outputs) {
  for (const std::filesystem::path& output : outputs) {
    const OutputGuard guard(output);
    if (!guard.output_exists()) continue;
    // Each file once: every asset of a folder lists its project file.
    std::set<std::filesystem::path> checked;
    for_each_file_read(result, [&](const std::filesystem::path& file) {
      if (checked.insert(file).second) guard.check(file);
    });
  }
}

void write_output(const CookResult& result, const std::filesystem::path& path,
                  const Settings& settings) {
  write_outputs(result, {path}, settings);
}

std::vector<OutputFile> output_files(const CookResult& result,
                                     const std::vector<std::filesystem::path>& paths,
                                     const Settings& settings,
                                     const std::vector<std::filesystem::path>& inputs,
                                     const BundleStream* stream) {
  std::vector<OutputFile> files;
  for (const std::filesystem::path& path : paths) {
    check_not_an_input(path, inputs);
    if (stream && output_format(path) == OutputFormat::bundle) {
      files.push_back({path, {}, [stream, &result](std::FILE* out) {
                         stream->write(out, result.assets, result.cooked_index);
                       }});
    } else {
      // Named as a streamed bundle's refusal is (output_file.cpp): the writers know no path.
      try {
        files.push_back({path, output_bytes(result, path, settings)});
      } catch (const OutputError& error) {
        throw OutputError(path.string() + ": cannot write: " + error.what());
      }
    }
  }
  return files;
}

void write_outputs(const CookResult& result, const std::vector<std::filesystem::path>& paths,
                   const Settings& settings) {
  check_not_read(result, paths);
  write_files_atomically(output_files(result, paths, settings, {}));
}

}  // namespace hullcook
