// Validation of the hull and vertex sections (SPEC §8, §11 item 9), the bulk of Bundle::open's
// work after the checksum: every hull's vertex range, and every hull strictly convex and
// counter-clockwise. Internal to the runtime.
#pragma once

#include "hullcook/runtime.h"

#include <cstdint>

namespace hullcook::runtime::detail {

// hull_records: hull_count HullRecords; vertices: vertex_count VertexRecords (both in bounds).
// Returns malformed when hull 0 does not start at vertex 0, when a range is reversed or holds
// fewer than 3 vertices, or when a hull is not strictly convex and counter-clockwise;
// out_of_bounds when a range ends past vertex_count. A range error is reported only when every
// hull before it is convex, as a hull-by-hull check would. Allocates nothing (uses 6 KB of
// stack).
Status validate_hulls(const unsigned char* hull_records, std::uint32_t hull_count,
                      const unsigned char* vertices, std::uint32_t vertex_count) noexcept;

}  // namespace hullcook::runtime::detail
