// `hullcook inspect`: the readers behind it, one per format (cmd_inspect.cpp picks one).
#pragma once

#include <filesystem>

namespace hullcook::cli {

// Prints a glTF written by hullcook (.gltf or .glb): its assets, levels, hulls and vertices, read
// from the asset nodes' extras (docs/gltf-extras.md); with json, the debug JSON instead.
// Returns 0, or 2 after a message on stderr naming the file and the problem when the file is
// unreadable, not glTF, or holds no hullcook data.
int inspect_gltf(const std::filesystem::path& path, bool json);

}  // namespace hullcook::cli
