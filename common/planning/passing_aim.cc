#include "common/planning/passing_aim.h"

#include <algorithm>

#include "common/planning/visibility.h"

namespace hexplore::planning {

PassingAim::PassingAim(PassingAimOptions aim, PlannerOptions planner) : aim_(aim), planner_(std::move(planner)) {}

double PassingAim::score(const highlevel::Supervoxel& sv, const Eigen::Vector3d& sensor,
                         const GiveUpLedger& ledger) const {
  if (!sv.facade() || sv.covered || !planner_.region.contains(sv.center)) return 0.0;
  if ((sv.center - sensor).squaredNorm() >= aim_.range_m * aim_.range_m) return 0.0;
  if (ledger.given_up(sv.key, sv.voxel_count)) return 0.0;
  const ViewGeometry g = view_geometry(sensor, Eigen::Vector3d::UnitZ(), sv.center, sv.normal);
  if (g.distance_m >= aim_.range_m || !angles_ok(g, planner_)) return 0.0;
  return visibility_score(g, planner_);
}

std::optional<Eigen::Vector3d> PassingAim::step(double now_s, const Eigen::Vector3d& position,
                                                const highlevel::HighLevelMap& map, const GiveUpLedger& ledger,
                                                std::span<const uint64_t> ahead) {
  // The time since the last step went to the current aim (a long gap: the robot was not driving).
  if (current_ != 0 && last_s_ >= 0.0) looked_s_[current_] += std::clamp(now_s - last_s_, 0.0, 2.0);
  last_s_ = now_s;
  const Eigen::Vector3d sensor = position + Eigen::Vector3d(0, 0, planner_.sensor_height_m);
  auto spent = [&](uint64_t key) {
    const auto it = looked_s_.find(key);
    return it == looked_s_.end() ? 0.0 : it->second;
  };
  const OcclusionGrid occlusion(map, planner_.eta_s_m);
  auto visible = [&](uint64_t key) -> const highlevel::Supervoxel* {
    const highlevel::Supervoxel* sv = map.find(key);
    if (sv == nullptr || spent(key) >= aim_.budget_s || score(*sv, sensor, ledger) <= 0.0) return nullptr;
    return occlusion.clear(sensor, sv->center) ? sv : nullptr;
  };

  // Keep the current aim for its hold time while it stays worth it.
  if (current_ != 0 && now_s - since_s_ < aim_.hold_s && visible(current_) != nullptr) return current_at_;
  // Else the first target ahead, in route order, that passes J from here.
  for (uint64_t key : ahead) {
    const highlevel::Supervoxel* sv = visible(key);
    if (sv == nullptr) continue;
    if (key != current_) {
      current_ = key;
      since_s_ = now_s;
      ++aims_;
    }
    current_at_ = sv->center;
    return current_at_;
  }
  current_ = 0;
  return std::nullopt;
}

}  // namespace hexplore::planning
