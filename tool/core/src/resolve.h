// Internal: Algorithm 4.2, Resolve(P, r): the cuts that remove a concave feature.
#pragma once

#include "decomposition_types.h"

#include <optional>
#include <utility>

namespace hullcook::detail {

// Algorithm 4.2 for a notch r of ∂P0: the best valid diagonal by Eq. 8. None when every valid
// diagonal grazes a vertex or cuts off a sliver and the notch is no deeper than the sliver width.
std::optional<std::pair<Region, Region>> resolve_notch(const Region& region,
                                                       const OuterConcavity& concavity,
                                                       std::size_t r,
                                                       const DecomposeSettings& settings,
                                                       std::pair<ParentHint, ParentHint>& hints);

// Algorithm 4.2 for a hole: join p to the closest visible vertex of ∂P0, and its antipode to the
// best vertex of ∂P0 by Eq. 8, so the hole opens into two simple pieces.
std::optional<std::pair<Region, Region>> resolve_hole(const Region& region, const Evaluation& e,
                                                      std::size_t h,
                                                      const DecomposeSettings& settings,
                                                      std::pair<ParentHint, ParentHint>& hints);

}  // namespace hullcook::detail
