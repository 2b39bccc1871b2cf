// The cooker's driver, shaped like gltfpack: a Settings struct with defaults and one cook()
// call that the command line and the tests share.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/cook/output_file.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hullcook {

class ListedFiles;  // tool/cook/src/listed_files.h

// A length given either absolutely (in input units: pixels for images) or relative to the
// radius R of the shape's minimum enclosing circle ("1%").
struct Tolerance {
  double value = 2.0;
  bool relative = false;  // value is a fraction of R (0.01 for "1%")

  // Parses "0.5", "2px" or "1%". Throws UsageError on anything else, or a value below 0 or
  // above 1e9.
  static Tolerance parse(const std::string& text);
  double resolve(double enclosing_radius) const {
    return relative ? value * enclosing_radius : value;
  }
};

// A uniform grid of cells in every input image, each cell one asset (`--grid 64x64`).
struct Grid {
  int cell_width = 0, cell_height = 0;  // [px]
  int margin = 0;                       // [px] before the first row and column
  int spacing = 0;                      // [px] between cells
  // --tile [--snap PX]: each cell's shape stays inside the cell, and outline points this near
  // its border lie exactly on it, so that neighbouring solid tiles meet without seams or bumps.
  std::optional<double> tile_snap = std::nullopt;  // [px]

  // The cell size: "64x32", or "64" for a square. Throws UsageError.
  static Grid parse(const std::string& text);
};

// An RGB colour "#ff00ff" (or "ff00ff"), as --color-key and a project rule's "color_key" give
// one. Throws UsageError on anything else.
std::array<std::uint8_t, 3> parse_color(const std::string& text);
// The colour as "#rrggbb".
std::string color_text(const std::array<std::uint8_t, 3>& rgb);

struct Settings {
  // Decomposition (issue 3).
  Tolerance tau{2.0, false};    // [input units] or relative to R
  std::string measure = "h1";   // sl | sp | h1 | h2
  double sc = 0.1;              // Eq. 8 weight of the concavity of the cut's far end
  double sd = 1.0;              // Eq. 8 weight of the cut's length
  std::size_t max_pieces = 0;   // 0: no budget; else the finest level with at most this many
  std::vector<Tolerance> lods;  // extra levels of detail (coarser τ), read off the tree

  // Tracing (issue 4).
  int alpha = 128;                                       // opaque where alpha >= this
  std::optional<std::array<std::uint8_t, 3>> color_key;  // RGB traced as transparent
  double min_blob_area = 4.0;                            // [px²]
  double min_hole_area = 4.0;                            // [px²]
  std::optional<double> simplify;                        // [px] default: τ / 4
  std::uint64_t max_pixels = 64ull * 1000 * 1000;
  // Images cut into cells, each non-empty cell an asset named NAME/INDEX (row-major from 0).
  std::optional<Grid> grid;

  // Pixels to world.
  double pixels_per_unit = 1.0;
  double pivot_u = 0.5, pivot_v = 0.5;  // normalised image coordinates of the origin, at most
                                        // kLargestPivot from 0
  bool y_down = false;                  // keep image orientation (y down) in the output

  // Engine constraints.
  std::size_t max_verts = 8;   // per hull; 0 = unlimited
  std::optional<double> weld;  // [output units] default kDefaultWeld
  // Merge neighbouring pieces whose union is one piece within τ and fits one hull within the
  // limits (--merge): fewer hulls under the same error bound, for more cooking time.
  bool merge_pieces = false;

  // Output.
  std::optional<PhysicsProperties> physics;
  bool draco = false;
  bool meshopt = false;  // glTF: EXT_meshopt_compression + KHR_mesh_quantization
  // An output is a bundle, which stores image sides in 16 bits: an image with a larger side is
  // refused as soon as it is decoded, not after its cook (a 16 x 65,536 px maze cooked for 581 s
  // before the bundle refused it, stop 60).
  bool bundle_output = false;
  unsigned threads = 0;  // 0: hardware concurrency; outputs never depend on it
  // Keep each asset's regions and pieces (with their components) and its cutout's image path in
  // the result: the debug JSON and the HTML report need them, the bundle and glTF writers only
  // the levels' hulls. Without them a cook's memory grows with its hulls alone (issue 19: 10,000
  // assets in the memory of 100).
  bool keep_outlines = true;
  // Keep the levels' hulls in the result. A streamed output (BundleStream) takes them as each
  // asset is cooked (cook's on_cooked), after which they may go: CookedStats keeps their count.
  bool keep_hulls = true;

  // The image is no asset (a project rule's or a sidecar's "skip": true). Sheet JSON inputs are
  // never skipped: they share their sidecar with their atlas image.
  bool skip = false;
};

// The farthest a pivot (Settings, or a sheet frame's) may lie [image sizes]: beyond it the
// origin, times an image's size, leaves the outline no finite coordinate.
constexpr double kLargestPivot = 1e6;

// Box2D 2.4's b2_linearSlop [m]: with 1 unit = 1 m, b2PolygonShape::Set welds vertices closer
// than half of it, so hulls keep their vertices at least this far apart.
inline constexpr double kDefaultWeld = 0.005;

struct CookResult {
  std::vector<CookedAsset> assets;        // in name order, whatever the order of the inputs
  std::vector<std::size_t> cooked_index;  // per asset: the index on_cooked was given with it
  std::vector<std::filesystem::path> sheet_images;  // the atlases of sheet JSON inputs
  // Inputs whose settings say "skip", sorted by path: no assets, but their settings files are
  // read (so dependencies of the output).
  std::vector<std::filesystem::path> skipped;
  // The names the walk of directory inputs saw, to look sidecars up in.
  std::shared_ptr<const ListedFiles> listed;
  // About inputs that gave no asset, each "PATH: what": a sheet whose every --grid cell is
  // empty, among inputs that gave assets.
  std::vector<std::string> warnings;
};

// Called once per asset as soon as it is cooked and checked, on the thread that cooked it (so
// from several threads at once, in no particular order), with the asset's index among the count
// cooked: CookResult::cooked_index maps the result's assets back to it.
using AssetCooked =
    std::function<void(std::size_t index, std::size_t count, const CookedAsset& asset)>;

// Cooks images (files or directories, recursing over images), .poly files and sprite sheets
// (TexturePacker or Aseprite JSON named as inputs, each frame an asset SHEET/FRAME).
// Throws InputError naming the file and the problem (or whatever on_cooked throws, for the
// first failing asset in input order); nothing is written.
CookResult cook(const std::vector<std::filesystem::path>& inputs, const Settings& settings,
                const AssetCooked& on_cooked = {});

// Checks before cooking what write_output would refuse about path alone: an unknown extension
// (UsageError), a directory or a missing directory (OutputError).
void check_output_path(const std::filesystem::path& path);

// Throws InputError naming source and the region if a region has too many holes for its
// vertices to decompose in reasonable time and memory (holes x vertices above 5e7; see cook.cpp),
// with a hint about what to change: for an image traced from its alpha channel or by a colour
// key (keyed), the alpha channel's or the key's noise.
enum class TracedFrom { polygons, alpha, color_key };
void refuse_too_many_holes(const std::vector<Region>& regions, const std::string& source,
                           TracedFrom traced);

// The physics sidecar of an input image: NAME.physics.json beside NAME.png.
std::filesystem::path physics_sidecar(const std::filesystem::path& input);

// The files a cook read: every asset's source, and its physics sidecar and settings files where
// there are some, and the sheets' atlases.
std::vector<std::filesystem::path> files_read(const CookResult& result);

// Calls visit with each of files_read(result) without holding them all (a path keeps a list of its
// components: at 10,000 assets the list was 2.8 MB of a cook's 15.3 MB peak heap).
void for_each_file_read(const CookResult& result,
                        const std::function<void(const std::filesystem::path&)>& visit);

// Throws UsageError when an output exists and is one of the files the cook read (see
// check_not_an_input).
void check_not_read(const CookResult& result, const std::vector<std::filesystem::path>& outputs);

class BundleStream;

// The bytes of every output path, by extension (.hcb, .gltf, .glb, .json, or .hcf, a fragment:
// see fragment.h), ready for write_files_atomically. With a stream (that every asset was added
// to as cook's on_cooked, under its cooked_index), a .hcb is written from it instead of from the
// result's hulls. Throws UsageError for an unknown extension or a path that is one of inputs.
std::vector<OutputFile> output_files(const CookResult& result,
                                     const std::vector<std::filesystem::path>& paths,
                                     const Settings& settings,
                                     const std::vector<std::filesystem::path>& inputs,
                                     const BundleStream* stream = nullptr);

// Writes the result to path, picking the writer by extension (.hcb, .gltf, .glb, .json, .hcf).
// Writes to a temporary file and renames it; throws OutputError, or UsageError for an unknown
// extension or a path that is one of files_read(result).
void write_output(const CookResult& result, const std::filesystem::path& path,
                  const Settings& settings);

// write_output to every path as one output: if any cannot be written, none is (see
// write_files_atomically).
void write_outputs(const CookResult& result, const std::vector<std::filesystem::path>& paths,
                   const Settings& settings);

}  // namespace hullcook
