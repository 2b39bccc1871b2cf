#include "cook_inputs.h"

#include "hullcook/core/error.h"

#include <algorithm>
#include <iterator>
#include <set>
#include <system_error>

namespace hullcook {
namespace {

// A sheet JSON's frames, each named SHEET/FRAME (SHEET: the file's name without .json). The atlas
// is decoded here, once; its errors name the JSON, which named it.
void add_sheet_frames(std::vector<InputFile>& files, const std::filesystem::path& path,
                      const std::string& name, const Settings& settings,
                      AssetSettings& asset_settings) {
  auto sheet = std::make_shared<const Sheet>(read_sheet(path, settings.max_pixels));
  const auto start = Clock::now();
  // With the sheet's own alpha (its sidecar or project rule), as a grid's sheet.
  const std::shared_ptr<const Settings> own = asset_settings.for_input(path);
  std::shared_ptr<const AlphaImage> atlas;
  try {
    atlas = std::make_shared<const AlphaImage>(
        load_alpha(sheet->image, trace_settings(own ? *own : settings, 0)));
  } catch (const InputError& e) {
    throw InputError(path.string() + ": meta.image: " + e.what());
  }
  const double decode_ms = milliseconds_since(start);
  check_frames_inside(*sheet, path, atlas->width, atlas->height);
  const std::string sheet_name = name.substr(0, name.size() - path.extension().string().size());
  for (std::size_t i = 0; i < sheet->frames.size(); ++i) {
    files.push_back({path.string(),
                     sheet_name + "/" + sheet->frames[i].name,
                     atlas,
                     {},
                     i == 0 ? decode_ms : 0,
                     sheet,
                     i,
                     own,
                     true});
  }
}

// An image that holds no whole cell of the grid.
struct GridMisfit {
  std::string path;
  int width = 0, height = 0;  // [px]
};

// Refuses the inputs when an image holds no whole cell (a wrong --grid or --margin, most likely,
// or an image that is no sheet): the first in name order, and how many more, so that one cook
// shows them all.
void refuse_grid_misfits(const std::vector<GridMisfit>& misfits, const Grid& grid) {
  if (misfits.empty()) return;
  auto size = [](const GridMisfit& misfit) {
    return std::to_string(misfit.width) + "x" + std::to_string(misfit.height);
  };
  const GridMisfit& first = misfits.front();
  std::string message = first.path + ": a " + size(first) + " image holds no whole " +
                        std::to_string(grid.cell_width) + "x" + std::to_string(grid.cell_height) +
                        " cell at margin " + std::to_string(grid.margin) + " (--grid, --margin)";
  if (misfits.size() > 1) {
    constexpr std::size_t kNamed = 5;
    message += "; nor do " + std::to_string(misfits.size() - 1) + " more image" +
               (misfits.size() == 2 ? "" : "s") + ": ";
    for (std::size_t i = 1; i < misfits.size() && i <= kNamed; ++i) {
      message += (i > 1 ? ", " : "") + misfits[i].path + " (" + size(misfits[i]) + ")";
    }
    if (misfits.size() - 1 > kNamed) message += ", ...";
  }
  throw InputError(message);
}

// Adds an input file; with --grid an image adds its cells instead, named NAME/INDEX (Tiled's
// row-major tile number), sorted by name as link sorts assets. The sheet is decoded here, once.
void add_input_file(std::vector<InputFile>& files, const std::filesystem::path& path,
                    const std::string& name, const Settings& settings,
                    AssetSettings& asset_settings, std::vector<std::filesystem::path>& skipped,
                    std::vector<GridMisfit>& misfits) {
  // Malformed settings are not reported here but when the asset is cooked, in input order (a
  // directory is walked in no particular order).
  std::shared_ptr<const Settings> own;
  bool own_resolved = false;
  try {
    own = asset_settings.for_input(path);
    own_resolved = true;
  } catch (const InputError&) {
  }
  // A sheet JSON shares its sidecar (hero.hullcook.json) with its atlas (hero.png), which a folder
  // cook would take for an image: skipping the atlas must not skip the sheet named beside it.
  if (!is_sheet_file(path) && (own ? *own : settings).skip) {
    skipped.push_back(path);
    return;
  }
  if (is_sheet_file(path)) {
    add_sheet_frames(files, path, name, settings, asset_settings);
    return;
  }
  if (!settings.grid || is_poly_file(path)) {
    files.push_back(
        {path.string(), name, nullptr, {}, 0, nullptr, 0, std::move(own), own_resolved});
    return;
  }
  const auto start = Clock::now();
  // Decoded once for its cells: with the sheet's own alpha (its sidecar or project rule).
  if (!own_resolved) own = asset_settings.for_input(path);  // throws what it met above
  auto sheet = std::make_shared<const AlphaImage>(
      load_alpha(path, trace_settings(own ? *own : settings, 0)));
  const double decode_ms = milliseconds_since(start);
  const Grid& grid = *settings.grid;
  const std::vector<GridCell> cells = grid_cells(sheet->width, sheet->height, grid);
  if (cells.empty()) {
    misfits.push_back({path.string(), sheet->width, sheet->height});
    return;
  }
  const std::size_t first = files.size();
  for (const GridCell& cell : cells) {
    files.push_back({path.string(), name + "/" + std::to_string(cell.index), sheet, cell,
                     files.size() == first ? decode_ms : 0, nullptr, 0, own, true});
  }
  std::sort(files.begin() + static_cast<std::ptrdiff_t>(first), files.end(),
            [](const InputFile& a, const InputFile& b) { return a.name < b.name; });
}

}  // namespace

TraceSettings trace_settings(const Settings& settings, double simplify_px) {
  TraceSettings trace;
  trace.alpha = settings.alpha;
  trace.color_key = settings.color_key;
  trace.min_blob_area = settings.min_blob_area;
  trace.min_hole_area = settings.min_hole_area;
  trace.max_pixels = settings.max_pixels;
  trace.simplify = simplify_px;
  return trace;
}

// Expands directories (recursively) into image files; files are taken as given. In name order.
std::vector<InputFile> collect_inputs(const std::vector<std::filesystem::path>& inputs,
                                      const Settings& settings, AssetSettings& asset_settings,
                                      ListedFiles& listed,
                                      std::vector<std::filesystem::path>& skipped) {
  std::vector<InputFile> files;
  std::vector<GridMisfit> misfits;
  for (const std::filesystem::path& input : inputs) {
    std::error_code error;
    if (std::filesystem::is_directory(input, error)) {
      std::vector<InputFile> found;
      const std::size_t skipped_before = skipped.size(), misfits_before = misfits.size();
      // The whole walk first: the images' sidecars are then looked up in its listing.
      std::vector<std::filesystem::path> images;
      // The entries named as images that cannot be read, by path: the first by name is refused
      // once the walk is over (the file system lists them in no particular order).
      std::vector<std::pair<std::string, std::string>> unreadable;
      for (auto it = std::filesystem::recursive_directory_iterator(input, error);
           !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
        listed.add(it->path());
        // The non-throwing form: a symbolic link loop is an entry that is no regular file.
        std::error_code entry_error;
        if (it->is_regular_file(entry_error) && is_image_file(it->path())) {
          images.push_back(it->path());
        } else if (is_image_file(it->path()) && it->is_symlink(entry_error) &&
                   !it->exists(entry_error)) {
          // An asset moved or renamed under its link: left out, the game would miss it.
          unreadable.emplace_back(
              it->path().generic_string(),
              it->path().string() + ": a broken symbolic link (to " +
                  std::filesystem::read_symlink(it->path(), entry_error).string() + ")");
        } else if (is_image_file(it->path())) {
          // A pipe or a device named as an image: left out, the game would miss an asset; read,
          // it may block or never end.
          try {
            refuse_unless_regular_file(it->path());
          } catch (const InputError& refused) {
            unreadable.emplace_back(it->path().generic_string(), refused.what());
          }
        }
      }
      if (error) throw InputError(input.string() + ": cannot read directory: " + error.message());
      if (!unreadable.empty()) {
        throw InputError(std::min_element(unreadable.begin(), unreadable.end())->second);
      }
      listed.seal();
      // In name order, as the assets are cooked: a sheet or atlas is decoded here, and of two
      // broken ones the error named whichever the file system listed first.
      std::vector<std::pair<std::string, std::filesystem::path>> named;
      named.reserve(images.size());
      for (std::filesystem::path& image : images) {
        named.emplace_back(image.lexically_relative(input).generic_string(), std::move(image));
      }
      std::sort(named.begin(), named.end());
      for (const auto& [name, image] : named) {
        add_input_file(found, image, name, settings, asset_settings, skipped, misfits);
      }
      // Its images are there, but too small for the grid: that is what to say.
      if (found.empty() && misfits.size() > misfits_before) {
        refuse_grid_misfits(misfits, *settings.grid);
      }
      // Likely a wrong path (or polygons, which are only read when named): an empty bundle would
      // hide it.
      if (found.empty() && skipped.size() > skipped_before) {
        throw InputError(input.string() +
                         ": every image in this directory is skipped by its settings (\"skip\" "
                         "in a hullcook.json rule or a sidecar)");
      }
      if (found.empty()) {
        throw InputError(input.string() +
                         ": no images in this directory (.png, .tga, .bmp, .webp; .poly files "
                         "are cooked only when named)");
      }
      std::sort(found.begin(), found.end(),
                [](const InputFile& a, const InputFile& b) { return a.name < b.name; });
      files.insert(files.end(), std::make_move_iterator(found.begin()),
                   std::make_move_iterator(found.end()));
    } else if (std::filesystem::is_regular_file(input, error)) {
      add_input_file(files, input, input.filename().generic_string(), settings, asset_settings,
                     skipped, misfits);
    } else {
      refuse_unless_regular_file(input);
      // A loop of links, or a directory on the way that cannot be searched, is said as such: "no
      // such file" sent the user looking for a typo (a chain of 46 links, stop 60).
      if (error && error != std::errc::no_such_file_or_directory &&
          error != std::errc::not_a_directory) {
        throw InputError(input.string() + ": " + error.message());
      }
      throw InputError(input.string() + ": no such file or directory");
    }
  }
  if (!misfits.empty()) refuse_grid_misfits(misfits, *settings.grid);
  std::set<std::string> names;
  for (const InputFile& file : files) {
    if (!names.insert(file.name).second) {
      throw InputError(file.path + ": two inputs would both be named '" + file.name +
                       "'; cook them separately or from a common directory");
    }
  }
  // Assets in name order, whatever the order of the command line (issue 19: the same inputs give
  // the same bytes).
  std::sort(files.begin(), files.end(),
            [](const InputFile& a, const InputFile& b) { return a.name < b.name; });
  return files;
}

}  // namespace hullcook
