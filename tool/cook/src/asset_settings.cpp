#include "asset_settings.h"

#include "strict_json.h"

#include "hullcook/core/decompose.h"
#include "hullcook/core/error.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <string_view>

namespace hullcook {

using json = nlohmann::json;

json read_json_object(const std::filesystem::path& path, const char* what) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, error))) {
      throw InputError(path.string() + ": a broken link (or a loop of links) where a file of " +
                       what + " is looked for");
    }
    throw InputError(path.string() + ": not a file of " + what);
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path.string() + ": cannot read");
  const std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (stream.bad()) throw InputError(path.string() + ": cannot read");
  // A key given twice kept only its last value, silently (a helper's project files, stop 59).
  std::string refusal;
  json object = parse_strict<json>(text, refusal);
  if (!refusal.empty()) throw InputError(path.string() + ": " + refusal);
  if (object.is_discarded() || !object.is_object()) {
    throw InputError(path.string() + ": not a JSON object of " + what);
  }
  return object;
}

namespace {

// A link counts, broken or not: a settings file that a broken link stands for is refused, not
// silently taken as absent (stop 58).
bool file_exists(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::exists(std::filesystem::symlink_status(path, error));
}

// The one segment glob (no '/') against one segment of name.
// Wildcard matching by the classic greedy walk: an element that fails resumes from the last
// star, one element further on, which is enough because every other glob element matches exactly
// one element of the name. O(glob x name) at worst, where the recursion that tried every split
// at every star was exponential (stop 57: "*a*a*a*a*a*a*a*a*a*b" against a name of 64 a's, or
// twelve "**" against a path 30 folders deep, did not finish in 120 s). is_star(g) tells a star;
// matches(g, n) whether element g, not a star, matches element n.
template <typename IsStar, typename Matches>
bool wildcard_match(std::size_t glob_size, std::size_t name_size, IsStar is_star, Matches matches) {
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::size_t g = 0, n = 0, star = kNone, resume = 0;
  while (n < name_size) {
    if (g < glob_size && is_star(g)) {
      star = g++;
      resume = n;
    } else if (g < glob_size && matches(g, n)) {
      ++g, ++n;
    } else if (star != kNone) {
      g = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (g < glob_size && is_star(g)) ++g;
  return g == glob_size;
}

// One path segment: '*' any run of characters, '?' any one.
bool segment_matches(std::string_view glob, std::string_view name) {
  return wildcard_match(
      glob.size(), name.size(), [&](std::size_t g) { return glob[g] == '*'; },
      [&](std::size_t g, std::size_t n) { return glob[g] == '?' || glob[g] == name[n]; });
}

std::vector<std::string_view> segments(std::string_view path) {
  std::vector<std::string_view> parts;
  while (true) {
    const std::size_t slash = path.find('/');
    parts.push_back(path.substr(0, slash));
    if (slash == std::string_view::npos) return parts;
    path.remove_prefix(slash + 1);
  }
}

// Whole paths: a "**" segment any run of segments.
bool segments_match(const std::vector<std::string_view>& glob,
                    const std::vector<std::string_view>& name) {
  return wildcard_match(
      glob.size(), name.size(), [&](std::size_t g) { return glob[g] == "**"; },
      [&](std::size_t g, std::size_t n) { return segment_matches(glob[g], name[n]); });
}

Tolerance tolerance_of(const json& value, const std::string& file, const std::string& key) {
  try {
    if (value.is_number()) return Tolerance::parse(value.dump());
    if (value.is_string()) return Tolerance::parse(value.get<std::string>());
  } catch (const UsageError& e) {
    throw InputError(file + ": '" + key + "': " + e.what());
  }
  throw InputError(file + ": '" + key + "' must be a length: a number, \"2px\" or \"1%\"");
}

}  // namespace

std::filesystem::path settings_sidecar(const std::filesystem::path& input) {
  std::filesystem::path sidecar = input;
  sidecar.replace_extension(".hullcook.json");
  return sidecar;
}

bool glob_matches(std::string_view glob, std::string_view name) {
  return segments_match(segments(glob), segments(name));
}

void apply_physics_json(PhysicsProperties& physics, const json& object, const std::string& file) {
  if (!object.is_object()) throw InputError(file + ": 'physics' must be an object");
  for (const auto& [key, value] : object.items()) {
    auto number = [&, &key = key, &value = value]() {
      if (!value.is_number() || !(value.get<double>() >= 0.0) ||
          !(value.get<double>() <= kMaxPhysicsValue)) {
        throw InputError(file + ": '" + key + "' must be a finite non-negative number (an f32)");
      }
      return value.get<double>();
    };
    auto bits = [&, &key = key, &value = value]() {
      const std::optional<long long> whole = whole_number(value);
      if (!whole || *whole < 0 || *whole > 0xFFFF) {
        throw InputError(file + ": '" + key + "' must be an integer in 0..65535");
      }
      return static_cast<std::uint16_t>(*whole);
    };
    if (key == "density") {
      physics.density = static_cast<float>(number());
    } else if (key == "friction") {
      physics.friction = static_cast<float>(number());
    } else if (key == "restitution") {
      physics.restitution = static_cast<float>(number());
    } else if (key == "sensor" && value.is_boolean()) {
      physics.sensor = value.get<bool>();
    } else if (key == "category") {
      physics.category_bits = bits();
    } else if (key == "mask") {
      physics.mask_bits = bits();
    } else {
      throw InputError(file + ": unknown or mistyped property '" + key +
                       "' (density, friction, restitution, sensor, category, mask)");
    }
  }
}

Settings with_overrides(Settings settings, const json& object, const std::string& file) {
  for (const auto& [key, value] : object.items()) {
    if (key == "tau") {
      settings.tau = tolerance_of(value, file, key);
    } else if (key == "lods") {
      if (!value.is_array()) throw InputError(file + ": 'lods' must be an array of lengths");
      settings.lods.clear();
      for (const json& lod : value) settings.lods.push_back(tolerance_of(lod, file, key));
    } else if (key == "alpha") {
      const std::optional<long long> whole = whole_number(value);
      if (!whole || *whole < 0 || *whole > 255) {
        throw InputError(file + ": 'alpha' must be an integer in 0..255");
      }
      settings.alpha = static_cast<int>(*whole);
    } else if (key == "max_verts") {
      const std::optional<long long> whole = whole_number(value);
      if (!whole || !(*whole == 0 || (*whole >= 3 && *whole <= 65535))) {
        throw InputError(file + ": 'max_verts' must be 0 (no limit) or 3..65535");
      }
      settings.max_verts = static_cast<std::size_t>(*whole);
    } else if (key == "measure") {
      if (!value.is_string() || !parse_measure(value.get<std::string>())) {
        throw InputError(file + ": 'measure' must be one of \"sl\", \"sp\", \"h1\", \"h2\"");
      }
      settings.measure = value.get<std::string>();
    } else if (key == "color_key") {
      // null undoes the command line's --color-key for these images.
      if (value.is_null()) {
        settings.color_key.reset();
        continue;
      }
      if (!value.is_string()) {
        throw InputError(file + ": 'color_key' must be a colour like \"#ff00ff\", or null");
      }
      try {
        settings.color_key = parse_color(value.get<std::string>());
      } catch (const UsageError& e) {
        throw InputError(file + ": 'color_key': " + e.what());
      }
    } else if (key == "skip") {
      if (!value.is_boolean()) throw InputError(file + ": 'skip' must be true or false");
      settings.skip = value.get<bool>();
    } else if (key == "merge") {
      if (!value.is_boolean()) throw InputError(file + ": 'merge' must be true or false");
      settings.merge_pieces = value.get<bool>();
    } else if (key == "physics") {
      PhysicsProperties physics = settings.physics.value_or(PhysicsProperties{});
      apply_physics_json(physics, value, file);
      settings.physics = physics;
    } else {
      throw InputError(file + ": unknown setting '" + key +
                       "' (tau, lods, alpha, color_key, max_verts, merge, measure, physics, skip)");
    }
  }
  return settings;
}

std::shared_ptr<const AssetSettings::Project> AssetSettings::project_for(
    const std::filesystem::path& directory) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = projects_.find(directory);
    if (found != projects_.end()) return found->second;
  }
  auto project = std::make_shared<Project>();
  const std::filesystem::path file = directory / "hullcook.json";
  if (file_exists(file)) {
    project->file = file;
    const json object = read_json_object(file, "project settings");
    for (const auto& [key, value] : object.items()) {
      if (key != "assets") {
        throw InputError(file.string() + ": unknown key '" + key + "' (assets)");
      }
      if (!value.is_array()) throw InputError(file.string() + ": 'assets' must be an array");
      for (const json& rule : value) {
        if (!rule.is_object() || !rule.contains("match") || !rule["match"].is_string()) {
          throw InputError(file.string() + ": every rule of 'assets' needs a \"match\" glob");
        }
        json settings = rule;
        settings.erase("match");
        with_overrides(Settings{}, settings, file.string());  // refused here, once, if malformed
        project->rules.push_back(
            {rule["match"].get<std::string>(), std::make_shared<const json>(std::move(settings))});
      }
    }
  } else if (directory.has_parent_path() && directory.parent_path() != directory) {
    std::shared_ptr<const Project> parent = project_for(directory.parent_path());
    const std::lock_guard<std::mutex> lock(mutex_);
    return projects_.emplace(directory, parent).first->second;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  return projects_.emplace(directory, std::move(project)).first->second;
}

std::shared_ptr<const Settings> AssetSettings::for_input(const std::filesystem::path& path) {
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  const std::shared_ptr<const Project> project = project_for(absolute.parent_path());
  const std::filesystem::path sidecar = settings_sidecar(path);
  const bool has_sidecar = exists(sidecar);
  std::vector<std::size_t> matched;
  if (!project->rules.empty()) {
    const std::string name =
        absolute.lexically_relative(project->file.parent_path()).generic_string();
    for (std::size_t k = 0; k < project->rules.size(); ++k) {
      if (glob_matches(project->rules[k].glob, name)) matched.push_back(k);
    }
  }
  if (matched.empty() && !has_sidecar) return nullptr;
  const RulesKey key{project.get(), matched};
  if (!has_sidecar) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = by_rules_.find(key);
    if (found != by_rules_.end()) return found->second;
  }
  Settings settings = base_;
  for (std::size_t k : matched) {
    settings =
        with_overrides(std::move(settings), *project->rules[k].settings, project->file.string());
  }
  if (has_sidecar) {
    settings = with_overrides(std::move(settings), read_json_object(sidecar, "settings"),
                              sidecar.string());
  }
  // The levels keep the units of τ, as --lod must.
  for (const Tolerance& lod : settings.lods) {
    if (lod.relative != settings.tau.relative) {
      throw InputError(path.string() + ": its settings give 'lods' and 'tau' in different units (" +
                       (has_sidecar ? sidecar : project->file).string() + ")");
    }
  }
  auto shared = std::make_shared<const Settings>(std::move(settings));
  if (has_sidecar) return shared;
  const std::lock_guard<std::mutex> lock(mutex_);
  return by_rules_.emplace(key, std::move(shared)).first->second;
}

std::vector<std::filesystem::path> AssetSettings::files_for(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  const std::shared_ptr<const Project> project = project_for(absolute.parent_path());
  if (!project->file.empty()) files.push_back(project->file);
  if (exists(settings_sidecar(path))) files.push_back(settings_sidecar(path));
  return files;
}

bool AssetSettings::exists(const std::filesystem::path& path) const {
  return listing_ ? listing_->exists(path) : file_exists(path);
}

}  // namespace hullcook
