// What the commands print: a count with its noun, "1 hull" and "2 hulls".
#pragma once

#include <cstddef>
#include <string>

namespace hullcook::cli {

inline std::string counted(std::size_t count, const char* one, const char* many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

}  // namespace hullcook::cli
