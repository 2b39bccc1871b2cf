// Internal: Algorithm 4.1's concave(P) for one node: the outer boundary's concavity (§5.1) and
// the holes' (§5.2, Eq. 5).
#pragma once

#include "decomposition_types.h"
#include "outer_concavity.h"

namespace hullcook::detail {

// Evaluates into e, whose storage is reused (see measure_outer).
void evaluate(const Region& region, Measure measure, double tau, Evaluation& e,
              PocketCache* cache = nullptr, const ParentHint* hint = nullptr);

}  // namespace hullcook::detail
