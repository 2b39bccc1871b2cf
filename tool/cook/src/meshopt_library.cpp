#include "hullcook/cook/meshopt_library.h"

#include <dlfcn.h>

#include <mutex>

namespace hullcook {
namespace {

struct Loaded {
  MeshoptLibrary library;
  bool complete = false;
  std::string problem;
};

template <typename Function>
bool resolve(void* handle, const char* name, Function& function, std::string& problem) {
  function = reinterpret_cast<Function>(dlsym(handle, name));
  if (function == nullptr && problem.empty()) {
    problem = std::string(HULLCOOK_MESHOPT_LIBRARY) + " has no " + name;
  }
  return function != nullptr;
}

Loaded load() {
  Loaded loaded;
  // The name the build linked against (its soname), so that the library is the version built for.
  void* handle = dlopen(HULLCOOK_MESHOPT_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    loaded.problem = why ? why : std::string(HULLCOOK_MESHOPT_LIBRARY) + " cannot be loaded";
    return loaded;
  }
  MeshoptLibrary& l = loaded.library;
  std::string& p = loaded.problem;
  bool complete = resolve(handle, "meshopt_encodeVertexBufferBound", l.encodeVertexBufferBound, p);
  complete &= resolve(handle, "meshopt_encodeVertexBuffer", l.encodeVertexBuffer, p);
  complete &= resolve(handle, "meshopt_encodeIndexVersion", l.encodeIndexVersion, p);
  complete &= resolve(handle, "meshopt_encodeIndexBufferBound", l.encodeIndexBufferBound, p);
  complete &= resolve(handle, "meshopt_encodeIndexBuffer", l.encodeIndexBuffer, p);
  complete &= resolve(handle, "meshopt_decodeVertexBuffer", l.decodeVertexBuffer, p);
  complete &= resolve(handle, "meshopt_decodeIndexBuffer", l.decodeIndexBuffer, p);
  complete &= resolve(handle, "meshopt_decodeIndexSequence", l.decodeIndexSequence, p);
  loaded.complete = complete;
  return loaded;
}

}  // namespace

const MeshoptLibrary* meshopt_library(std::string* problem) {
  static std::once_flag once;
  static Loaded loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.complete) {
    if (problem) *problem = loaded.problem;
    return nullptr;
  }
  return &loaded.library;
}

}  // namespace hullcook
