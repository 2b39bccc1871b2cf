#include "hullcook/runtime.h"

namespace hullcook {

const char* runtime_version() noexcept { return "0.1.0"; }

}  // namespace hullcook
