// hullcook runtime: loads cooked hull bundles (.hcb) inside a game.
// C++17, standard library only, no exceptions, no RTTI, no heap allocation while loading.
#pragma once

namespace hullcook {

// The runtime's version as "major.minor.patch"; a static string, never null.
const char* runtime_version() noexcept;

}  // namespace hullcook
