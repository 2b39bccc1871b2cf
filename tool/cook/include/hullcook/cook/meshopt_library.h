// meshoptimizer's codecs (EXT_meshopt_compression), loaded from its shared library the first time
// a glTF is meshopt-compressed (cook, link) or read (inspect). Most runs never need them, and a
// process linked against libmeshoptimizer also loads the shared C++ runtime at start-up, which the
// hullcook executable otherwise carries itself: about 50 page faults and 2 ms a process (issue 17).
#pragma once

#include <meshoptimizer.h>

#include <cstddef>
#include <string>

namespace hullcook {

// The functions of meshoptimizer.h that hullcook calls, typed by that header's declarations (the
// static_casts pick the C functions among the header's C++ overloads, and fail to compile if their
// declarations change).
struct MeshoptLibrary {
  using IndexEncoder = std::size_t (*)(unsigned char*, std::size_t, const unsigned int*,
                                       std::size_t);
  using Decoder = int (*)(void*, std::size_t, std::size_t, const unsigned char*, std::size_t);

  decltype(&meshopt_encodeVertexBufferBound) encodeVertexBufferBound = nullptr;
  decltype(&meshopt_encodeVertexBuffer) encodeVertexBuffer = nullptr;
  decltype(&meshopt_encodeIndexVersion) encodeIndexVersion = nullptr;
  decltype(&meshopt_encodeIndexBufferBound) encodeIndexBufferBound = nullptr;
  decltype(static_cast<IndexEncoder>(&meshopt_encodeIndexBuffer)) encodeIndexBuffer = nullptr;
  decltype(&meshopt_decodeVertexBuffer) decodeVertexBuffer = nullptr;
  decltype(static_cast<Decoder>(&meshopt_decodeIndexBuffer)) decodeIndexBuffer = nullptr;
  decltype(static_cast<Decoder>(&meshopt_decodeIndexSequence)) decodeIndexSequence = nullptr;
};

// The library, loaded once per process (thread-safe); nullptr when it cannot be loaded, with the
// reason in *problem (the library's name and the loader's message).
const MeshoptLibrary* meshopt_library(std::string* problem);

}  // namespace hullcook
