#include "services/planning/execution_options.h"

#include <algorithm>
#include <stdexcept>

namespace hexplore::planning_service {

double parse_positive(const Arguments& args, const std::string& key, double fallback) {
  const auto it = args.find(key);
  if (it == args.end()) return fallback;
  try {
    size_t used = 0;
    const double v = std::stod(it->second, &used);
    if (used == it->second.size() && v > 0) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("planning: --" + key + " expects a positive number, got '" + it->second + "'");
}

ExecutionOptions execution_options(const Arguments& args, const core::SpeciesConfig& species,
                                   const planning::SpeciesCapability& capability,
                                   const planning::PlannerOptions& planner) {
  ExecutionOptions out;
  planning::GiveUpRules& rules = out.give_up;
  rules.views = std::max(1, int(parse_positive(args, "give-up-views", rules.views)));
  rules.attempts = std::max(1, int(parse_positive(args, "give-up-attempts", rules.attempts)));

  planning::FollowerOptions& follow = out.follow;
  follow.reach_m = parse_positive(args, "reach-m", follow.reach_m);
  follow.observe_reach_m = parse_positive(args, "observe-reach-m", follow.observe_reach_m);
  follow.blocked_s = parse_positive(args, "blocked-s", follow.blocked_s);
  follow.stuck_s = parse_positive(args, "stuck-s", follow.stuck_s);
  follow.settle_s = parse_positive(args, "settle-s", follow.settle_s);
  follow.min_aim_s = parse_positive(args, "min-aim-s", follow.min_aim_s);
  follow.keep_stretch_m = parse_positive(args, "keep-stretch-m", follow.keep_stretch_m);
  follow.switch_gain_m = parse_positive(args, "switch-gain-m", follow.switch_gain_m);
  // The cost model charges 1 / observation speed per facade task view (one per target);
  // --dwell per-target spends it on each open target (one at a time where a gimbal aims the
  // sensor), per-view on each view's targets together (common/planning/README.md).
  follow.observation_time_s =
      species.observation_speed_views_per_s > 0 ? 1.0 / species.observation_speed_views_per_s : 0.0;
  follow.aim_each_target = std::any_of(species.lidars.begin(), species.lidars.end(),
                                       [](const core::LidarConfig& l) { return l.gimbal; });
  if (auto it = args.find("dwell"); it != args.end()) {
    if (it->second == "per-target") follow.dwell = planning::FollowerOptions::Dwell::kPerTarget;
    else if (it->second == "per-view") follow.dwell = planning::FollowerOptions::Dwell::kPerView;
    else throw std::invalid_argument("planning: --dwell expects per-view or per-target, got '" + it->second + "'");
  }
  if (auto it = args.find("observe"); it != args.end()) {
    if (it->second == "false") follow.observation_time_s = 0.0;
    else if (it->second != "true")
      throw std::invalid_argument("planning: --observe expects true or false, got '" + it->second + "'");
  }

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
