#include "merge_retries.h"

#include <utility>

namespace hullcook {

void MergeRetries::reset(std::size_t slots) {
  always_ = slots > std::numeric_limits<std::uint32_t>::max();
  worth_trying_.assign(slots, 1);
  listed_.assign(slots, 0);
  merged_.assign(slots, 0);
  watchers_.assign(slots, {});
  joined_at_.assign(slots, kNone);
  point_numbers_.clear();
}

std::uint32_t MergeRetries::point_number(Vec2 p) {
  // -0 and 0 are one point, as boundary_points_shared compares them (it finds no NaN: a point
  // shared lies on a boundary).
  p += Vec2{0.0, 0.0};
  if (const auto found = point_numbers_.find(p); found != point_numbers_.end()) {
    return found->second;
  }
  if (point_numbers_.size() >= kTwoPoints) return kTwoPoints;
  const auto number = static_cast<std::uint32_t>(point_numbers_.size());
  point_numbers_.emplace(p, number);
  return number;
}

void MergeRetries::failed(std::size_t k, const std::vector<Touch>& touching) {
  if (always_) return;
  worth_trying_[k] = 0;
  if (listed_[k]) return;
  listed_[k] = 1;
  const auto watcher = static_cast<std::uint32_t>(k);
  for (const Touch& touch : touching) {
    const std::uint32_t point = touch.shared >= 2 ? kTwoPoints : point_number(touch.point);
    watchers_[touch.slot].push_back({watcher, point});
  }
}

void MergeRetries::merged(std::size_t from, std::size_t into) {
  if (always_) return;
  merged_[from] = 1;
  worth_trying_[into] = 1;
  listed_[into] = 0;
  // Each failed slot listed by either is listed once, with the points it shared with both.
  std::vector<Watcher> joined;
  joined.reserve(watchers_[into].size() + watchers_[from].size());
  for (const std::vector<Watcher>* list : {&watchers_[into], &watchers_[from]}) {
    for (const Watcher& watcher : *list) {
      if (merged_[watcher.slot] || watcher.slot == into) continue;  // into is marked anyway
      std::size_t& at = joined_at_[watcher.slot];
      if (at == kNone) {
        at = joined.size();
        joined.push_back(watcher);
      } else if (joined[at].point != watcher.point) {
        joined[at].point = kTwoPoints;
      }
    }
  }
  // One that shares two points with the grown slot's parts may merge into it now (one that
  // shared two with into before may too: into changed).
  for (const Watcher& watcher : joined) {
    joined_at_[watcher.slot] = kNone;
    if (watcher.point == kTwoPoints) worth_trying_[watcher.slot] = 1;
  }
  watchers_[into] = std::move(joined);
  std::vector<Watcher>().swap(watchers_[from]);
}

}  // namespace hullcook
