// Per-asset settings without a GUI (issue 18): a sidecar NAME.hullcook.json beside an image, and
// a project file hullcook.json whose rules map globs to settings for the images below it. Both
// change a cook's Settings for one asset only: the project's matching rules in order, then the
// sidecar, over the command line's.
//
//   hullcook.json:      {"assets": [{"match": "tiles/**", "tau": "1%", "max_verts": 6},
//                                   {"match": "**/hero*.png", "physics": {"density": 2}}]}
//   hero.hullcook.json: {"alpha": 64, "lods": ["4", "8"]}
//
// Keys: tau and lods (as --tau and --lod: "2", "2px", "1%"), alpha (0-255), color_key (as
// --color-key: "#ff00ff", or null for none), max_verts (0 or 3-65535), merge (as --merge: true
// or false), measure (sl, sp, h1, h2),
// physics (an object as in NAME.physics.json), skip (true: the image is no asset). A project file
// applies to the images in its directory and below; the nearest one up from an image is used,
// its globs matched against the image's path relative to the project file's directory ('*' and
// '?' within a folder, '**' across folders), so that cooking a folder and cooking its images one
// by one give each image the same settings.
#pragma once

#include "hullcook/cook/cook.h"
#include "listed_files.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// NAME.hullcook.json beside NAME.png.
std::filesystem::path settings_sidecar(const std::filesystem::path& input);

// Whether name matches glob: '*' and '?' match within a path segment ('/'-separated), "**"
// matches any number of whole segments (and "**/" none).
bool glob_matches(std::string_view glob, std::string_view name);

// The JSON object in the file at path (a sidecar or project file of what, e.g. "settings"). Throws
// InputError "PATH: not a file of WHAT" / "cannot read" / "not a JSON object of WHAT".
nlohmann::json read_json_object(const std::filesystem::path& path, const char* what);

// Settings with the keys of json (see above) applied. Throws InputError naming file and the key
// on an unknown key or a bad value.
Settings with_overrides(Settings settings, const nlohmann::json& json, const std::string& file);

// Sets the physics properties of json (density, friction, restitution, sensor, category, mask)
// on physics. Throws InputError naming file and the property.
void apply_physics_json(PhysicsProperties& physics, const nlohmann::json& json,
                        const std::string& file);

// Resolves each input's settings, reading every project file once; safe from several threads.
class AssetSettings {
 public:
  explicit AssetSettings(const Settings& base = {}) : base_(base) {}

  // The settings of the image at path; null when no project rule or sidecar changes the base.
  // Throws InputError naming a malformed project file or sidecar.
  std::shared_ptr<const Settings> for_input(const std::filesystem::path& path);

  // The settings files that exist for the image at path: its project file and its sidecar.
  std::vector<std::filesystem::path> files_for(const std::filesystem::path& path);

  // Sidecars are looked up in listing where it holds their directory (see ListedFiles).
  void use_listing(std::shared_ptr<const ListedFiles> listing) { listing_ = std::move(listing); }
  // Whether a file exists at path (a sidecar): ListedFiles::exists, or std::filesystem's.
  bool exists(const std::filesystem::path& path) const;

 private:
  struct Rule {
    std::string glob;
    std::shared_ptr<const nlohmann::json> settings;
  };
  struct Project {
    std::filesystem::path file;  // empty: no project file at or above the directory
    std::vector<Rule> rules;
  };
  std::shared_ptr<const Project> project_for(const std::filesystem::path& directory);

  Settings base_;
  std::shared_ptr<const ListedFiles> listing_;
  std::mutex mutex_;
  std::map<std::filesystem::path, std::shared_ptr<const Project>> projects_;  // by directory
  // The settings made by the same rules of one project, for images without a sidecar: one copy
  // for every image a rule such as "**" matches (a cook of 10,000 images holds one, not 10,000).
  using RulesKey = std::pair<const Project*, std::vector<std::size_t>>;
  std::map<RulesKey, std::shared_ptr<const Settings>> by_rules_;
};

}  // namespace hullcook
