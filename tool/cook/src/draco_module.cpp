// draco_encode() through the Draco module, loaded the first time a glTF is Draco-compressed:
// most cooks never need Draco, and a process that links it pays for loading it at start-up.
#include "gltf_draco.h"

#include "hullcook/core/error.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace hullcook {
namespace {

struct DracoModule {
  DracoEntryPoint encode = nullptr;
  std::string problem;  // why it could not be loaded
};

// Beside the installed layout (bin/hullcook, lib/hullcook/hullcook_draco.so), which the build
// tree repeats for the executable (tool/cli/hullcook, tool/lib/hullcook/), then where the build
// put it (for test programs elsewhere in the build tree).
DracoModule load_module() {
  DracoModule module;
  std::vector<std::filesystem::path> candidates;
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    candidates.push_back(executable.parent_path() / "../lib/hullcook/hullcook_draco.so");
  }
#ifdef HULLCOOK_DRACO_MODULE_BUILT_AT
  const std::filesystem::path built_at = HULLCOOK_DRACO_MODULE_BUILT_AT;
  if (candidates.empty() || candidates.front().lexically_normal() != built_at.lexically_normal()) {
    candidates.push_back(built_at);
  }
#endif
  for (const std::filesystem::path& candidate : candidates) {
    if (!std::filesystem::exists(candidate, error)) continue;
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      module.problem = why ? why : candidate.string() + ": cannot be loaded";
      continue;
    }
    module.encode = reinterpret_cast<DracoEntryPoint>(dlsym(handle, kDracoEntryPoint));
    if (module.encode != nullptr) return module;
    module.problem = candidate.string() + ": no " + kDracoEntryPoint;
  }
  if (module.problem.empty()) {
    module.problem = "hullcook_draco.so is not installed beside the executable";
    for (const std::filesystem::path& candidate : candidates) {
      module.problem += std::string(module.problem.back() == 'e' ? " (" : ", ") +
                        candidate.lexically_normal().string();
    }
    if (!candidates.empty()) module.problem += ")";
  }
  return module;
}

}  // namespace

DracoMesh draco_encode(const TriangleMesh& mesh, int position_bits, const std::string& name) {
  static std::once_flag loaded;
  static DracoModule module;
  std::call_once(loaded, [] { module = load_module(); });
  if (module.encode == nullptr) {
    throw OutputError("mesh " + name + ": cannot compress with Draco: " + module.problem);
  }
  DracoMesh out;
  std::string problem;
  if (!module.encode(&mesh, position_bits, &name, &out, &problem)) throw OutputError(problem);
  return out;
}

}  // namespace hullcook
