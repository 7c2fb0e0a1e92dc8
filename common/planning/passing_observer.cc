#include "common/planning/passing_observer.h"

#include <algorithm>
#include <cmath>

#include "common/planning/frontier.h"
#include "common/planning/planning_types.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {

PassingObserver::PassingObserver(PassingOptions passing, PlannerOptions planner)
    : passing_(passing), planner_(std::move(planner)) {}

bool PassingObserver::in_view(const highlevel::Supervoxel& sv, const Eigen::Vector3d& position,
                              const OcclusionGrid& occlusion) const {
  if (sv.ground())
    return (sv.center - position).head<2>().norm() <= passing_.ground_reach_m && same_level(sv.center, position);
  const Eigen::Vector3d sensor = position + Eigen::Vector3d(0, 0, planner_.sensor_height_m);
  const ViewGeometry g = view_geometry(sensor, Eigen::Vector3d::UnitZ(), sv.center, sv.normal);
  if (g.distance_m >= passing_.range_m) return false;
  if (g.elevation_rad < passing_.elevation_min_deg * kDegToRad || g.elevation_rad > passing_.elevation_max_deg * kDegToRad)
    return false;
  if (!angles_ok(g, planner_, planner_.shared_view_margin_deg)) return false;
  return occlusion.clear(sensor, sv);
}

void PassingObserver::step(double now_s, const Eigen::Vector3d& position, const highlevel::HighLevelMap& map,
                           GiveUpLedger& ledger) {
  // Judge what settled.
  auto due = [&](const Pending& p) { return p.due_s <= now_s; };
  for (const Pending& p : pending_) {
    if (!due(p)) continue;
    const highlevel::Supervoxel* sv = map.find(p.key);
    if (!sv || !needs_look(map, *sv, planner_.region) || ledger.given_up(p.key, sv->voxel_count)) continue;
    ledger.observed(p.key, p.spot, sv->voxel_count);
    ++observations_;
  }
  pending_.erase(std::remove_if(pending_.begin(), pending_.end(), due), pending_.end());

  // A gap longer than two looks ends every interval (the robot was not looking, or stopped).
  const double gap_s = last_step_s_ < 0.0 ? 0.0 : now_s - last_step_s_;
  last_step_s_ = now_s;
  const OcclusionGrid occlusion(map, planner_.eta_s_m);
  const double reach = std::max(passing_.range_m, passing_.ground_reach_m);
  for (const auto& [key, sv] : map.supervoxels()) {
    if (!needs_look(map, sv, planner_.region) || !planner_.region.contains(sv.center)) continue;
    if (sv.ground() && !sv.traversable()) continue;
    if ((sv.center - position).squaredNorm() > reach * reach) continue;
    if (ledger.given_up(key, sv.voxel_count) || !in_view(sv, position, occlusion)) continue;
    Interval& seen = seen_[key];
    const bool fresh = !seen.started || now_s - seen.last_s > std::max(2.5 * gap_s, 1.5) ||
                       (seen.spot - position).head<2>().norm() > passing_.spot_m;
    if (fresh) seen = Interval{position, now_s, now_s, false, true};
    seen.last_s = now_s;
    const double needed = sv.ground() ? 0.0 : passing_.dwell_s;
    if (!seen.judged && now_s - seen.since_s >= needed) {
      seen.judged = true;
      pending_.push_back({key, seen.spot, now_s + passing_.settle_s});
    }
  }
  // Forget intervals long out of view.
  for (auto it = seen_.begin(); it != seen_.end();)
    it = now_s - it->second.last_s > 30.0 ? seen_.erase(it) : std::next(it);
}

PassingOptions passing_options(const SpeciesCapability& species, double min_elevation_deg, double max_elevation_deg,
                               double observation_time_s) {
  PassingOptions o;
  o.range_m = species.observation_range_m;
  o.elevation_min_deg = min_elevation_deg;
  o.elevation_max_deg = max_elevation_deg;
  o.dwell_s = std::max(1.0, observation_time_s);
  return o;
}

}  // namespace hexplore::planning
