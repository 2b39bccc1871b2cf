// Writing outputs without ever leaving a partial file behind.
#pragma once

#include <filesystem>
#include <string_view>

namespace hullcook {

// Writes bytes to a temporary file beside path, then renames it over path.
// Throws OutputError naming the file and the reason; on failure nothing is left behind.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace hullcook
