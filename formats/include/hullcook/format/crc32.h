// CRC-32 (ISO-HDLC, the zlib/PNG polynomial 0xEDB88320, reflected, initial and final XOR
// 0xFFFFFFFF). The bundle's checksum; shared by the writer and the reader.
// Portable slicing-by-16 in three interleaved streams; on x86 with GCC or Clang, folding with
// PCLMULQDQ when the CPU has it (detected at each call; compiler intrinsics, no library).
#pragma once

#include <cstddef>
#include <cstdint>

namespace hullcook::format {

// Continues a running CRC: crc32(crc32(0, a, n), b, m) == crc32(0, a||b, n+m).
std::uint32_t crc32(std::uint32_t crc, const void* data, std::size_t size) noexcept;

// The same by the portable method only, whatever the CPU (for tests and benchmarks).
std::uint32_t crc32_portable(std::uint32_t crc, const void* data, std::size_t size) noexcept;

}  // namespace hullcook::format
