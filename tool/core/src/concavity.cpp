#include "concavity.h"

#include "hole_concavity.h"

namespace hullcook {
namespace detail {

void evaluate(const Region& region, Measure measure, double tau, Evaluation& e, PocketCache* cache,
              const ParentHint* hint) {
  measure_outer(region.outer, measure, tau, e.outer, cache, hint);
  e.value = e.outer.value;
  e.holes.clear();
  e.hole_ends.clear();
  e.deepest_hole = -1;
  if (!region.holes.empty()) {
    static const std::vector<HoleEnds> kNothingInherited;
    e.holes =
        measure_holes(region, e.outer, hint ? hint->hole_ends : kNothingInherited, e.hole_ends);
    for (std::size_t h = 0; h < e.holes.size(); ++h) {
      if (e.deepest_hole < 0 || e.holes[h].value > e.holes[std::size_t(e.deepest_hole)].value) {
        e.deepest_hole = static_cast<int>(h);
      }
    }
    e.value = std::max(e.value, e.holes[std::size_t(e.deepest_hole)].value);
  }
}

}  // namespace detail

using detail::Evaluation;
using detail::OuterConcavity;

double measure_concavity(const Region& region, Measure measure, double tau) {
  Evaluation e;
  evaluate(region, measure, tau, e);
  return e.value;
}

std::vector<double> outer_vertex_concavity(const Ring& outer, Measure measure, double tau) {
  OuterConcavity result;
  measure_outer(outer, measure, tau, result);
  return result.vertex;
}

}  // namespace hullcook
