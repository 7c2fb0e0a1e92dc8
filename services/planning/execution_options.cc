#include "services/planning/execution_options.h"

#include <algorithm>

namespace hexplore::planning_service {

ExecutionOptions execution_options(const service::Options& opts, const core::SpeciesConfig& species,
                                   const planning::SpeciesCapability& capability,
                                   const planning::PlannerOptions& planner) {
  ExecutionOptions out;
  planning::GiveUpRules& rules = out.give_up;
  rules.views = opts.integer("give-up-views", rules.views, 1);
  rules.attempts = opts.integer("give-up-attempts", rules.attempts, 1);

  planning::FollowerOptions& follow = out.follow;
  follow.reach_m = opts.positive("reach-m", follow.reach_m);
  follow.observe_reach_m = opts.positive("observe-reach-m", follow.observe_reach_m);
  follow.blocked_s = opts.positive("blocked-s", follow.blocked_s);
  follow.stuck_s = opts.positive("stuck-s", follow.stuck_s);
  follow.settle_s = opts.positive("judge-lag-s", follow.settle_s);
  follow.min_aim_s = opts.positive("min-aim-s", follow.min_aim_s);
  follow.keep_stretch_m = opts.positive("keep-stretch-m", follow.keep_stretch_m);
  follow.switch_gain_m = opts.positive("switch-gain-m", follow.switch_gain_m);
  follow.region = planner.region;
  // The cost model charges 1 / observation speed per facade task view (one per target);
  // --dwell per-target spends it on each open target (one at a time where a gimbal aims the
  // sensor), per-view on each view's targets together (common/planning/README.md).
  follow.observation_time_s =
      species.observation_speed_views_per_s > 0 ? 1.0 / species.observation_speed_views_per_s : 0.0;
  follow.aim_each_target = std::any_of(species.lidars.begin(), species.lidars.end(),
                                       [](const core::LidarConfig& l) { return l.gimbal; });
  if (opts.choice("dwell", "per-view", {"per-view", "per-target"}) == "per-target")
    follow.dwell = planning::FollowerOptions::Dwell::kPerTarget;
  if (!opts.flag("observe", true)) follow.observation_time_s = 0.0;

  // What the robot sees on its way counts too: the band its fixed (not gimbal-aimed) LiDARs cover.
  double low = 90.0, high = -90.0;
  for (const auto& l : species.lidars)
    if (!l.gimbal) {
      low = std::min(low, l.vertical_min_deg + l.mount_pitch_deg);
      high = std::max(high, l.vertical_max_deg + l.mount_pitch_deg);
    }
  out.passing = planning::passing_options(capability, std::max(low, planner.theta_l_deg),
                                          std::min(high, planner.theta_u_deg), follow.observation_time_s);
  out.passing.settle_s = follow.settle_s;
  out.passing.spot_m = rules.distinct_m;
  out.passing.ground_reach_m = follow.reach_m;
  return out;
}

}  // namespace hexplore::planning_service
