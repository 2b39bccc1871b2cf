// Cooked fragments (.hcf, formats/FRAGMENT.md): the compile half of `cook` then `link`. A
// fragment holds cooked assets losslessly, so that linking fragments writes the same bundle as
// cooking their inputs in one command, and depends only on the input bytes, the settings and
// the tool version (never on paths, times or thread counts), so that a build system may cache
// it or run it anywhere.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/cook/cook.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// The version of this hullcook, stored in every fragment it writes.
const char* tool_version();

// Every setting that can change a cooked asset, as canonical text (one `key=value` a line,
// numbers in hexadecimal floating point, so exact). Threads and Draco are left out: they
// never change an asset.
std::string settings_text(const Settings& settings);

struct Fragment {
  std::string tool_version;
  std::uint64_t settings_hash = 0;  // FNV-1a 64 of settings
  std::string settings;             // settings_text() of the cook that wrote it
  std::vector<CookedAsset> assets;  // sources are file names only; timings are 0
};

// The fragment of assets cooked with settings. Deterministic: stores of each asset's source
// only its file name, and none of its timings.
std::string write_fragment(const std::vector<CookedAsset>& assets, const Settings& settings);

// Reads a fragment's bytes. Throws InputError naming file and the problem: not a fragment,
// another format or tool version, truncated, a bad checksum, or malformed content.
Fragment parse_fragment(std::string_view bytes, const std::string& file);

// Reads and parses the file at path (InputError when it cannot be read).
Fragment read_fragment(const std::filesystem::path& path);

}  // namespace hullcook
