#include "common/planning/round_trace.h"

#include <cstdio>
#include <sstream>

#include "common/core/coverage_gap.h"
#include "common/highlevel/high_level_map.h"

namespace hexplore::planning {
namespace {

std::string vec(const Eigen::Vector3d& p) {
  char b[96];
  std::snprintf(b, sizeof(b), "[%.2f, %.2f, %.2f]", p.x(), p.y(), p.z());
  return std::string(b);
}

}  // namespace

std::string round_trace_json(const RoundTrace& round, const PlanRequest& req, const PlanResult& res,
                             const FollowerCounters& f, const highlevel::HighLevelMap& map,
                             const Eigen::AlignedBox3d& region) {
  const RobotPlan& mine = res.robots[size_t(req.self)];
  int complete[2] = {0, 0}, incomplete[2] = {0, 0};  // [ground, facade] supervoxels in the region
  for (const auto& [key, sv] : map.supervoxels()) {
    if (!region.contains(sv.center)) continue;
    (sv.covered ? complete : incomplete)[sv.facade() ? 1 : 0]++;
  }
  std::ostringstream j;
  j << "{\"t\": " << round.t_s << ", \"round\": " << round.round << ", \"reason\": \"" << round.reason
    << "\", \"planner\": \"" << round.planner << "\", \"position\": " << vec(round.position)
    << ", \"odometry_m\": " << round.odometry_m << ", \"live\": " << req.robots.size() << ", \"views\": " << res.views
    << ", \"clusters\": " << res.clusters << ", \"open_views\": " << res.open_views
    << ", \"given_up\": " << round.given_up << ", \"reference\": \"" << res.reference_source
    << "\", \"agreement\": " << res.agreement.value_or(-1.0) << ", \"time_s\": " << res.times.total_s
    << ", \"public_views\": " << res.view_stats.public_views << ", \"frontier_views\": " << res.view_stats.frontier_views << ", \"supervoxels\": {\"ground_complete\": " << complete[0]
    << ", \"ground_incomplete\": " << incomplete[0] << ", \"facade_complete\": " << complete[1]
    << ", \"facade_incomplete\": " << incomplete[1] << "}, \"clusters_per_robot\": [";
  for (size_t r = 0; r < res.robots.size(); ++r) j << (r ? ", " : "") << res.robots[r].cluster_ids.size();
  j << "], \"cost_s_per_robot\": [";
  for (size_t r = 0; r < res.robots.size(); ++r) j << (r ? ", " : "") << res.robots[r].cost_s;
  j << "], \"private_cost_s_per_robot\": [";
  for (size_t r = 0; r < res.robots.size(); ++r) j << (r ? ", " : "") << res.robots[r].private_cost_s;
  j << "], \"own_clusters\": [";
  for (size_t i = 0; i < mine.cluster_centers.size(); ++i) j << (i ? ", " : "") << vec(mine.cluster_centers[i]);
  j << "], \"route\": [";
  for (size_t i = 0; i < mine.route.size(); ++i)
    j << (i ? ", " : "") << "{\"p\": " << vec(mine.route[i].position) << ", \"facade\": " << (mine.route[i].facade ? 1 : 0)
      << ", \"targets\": " << mine.route[i].targets.size() << "}";
  j << "], \"follower\": {\"reached\": " << f.views_reached << ", \"observed\": " << f.views_observed
    << ", \"skipped\": " << f.views_skipped << ", \"observed_short\": " << f.views_observed_short
    << ", \"without_path\": " << f.views_without_path
    << ", \"cut_off\": " << f.views_cut_off
    << ", \"done_before\": " << f.views_done_before << ", \"cut_short\": " << f.dwells_cut_short
    << ", \"not_aimed\": " << f.targets_not_aimed
    << ", \"legs_kept\": " << f.legs_kept << ", \"legs_switched\": " << f.legs_switched << ", \"stretch_views_kept\": " << f.stretch_views_kept << ", \"passing_observations\": " << round.passing_observations
    << ", \"observing_s\": " << f.observing_s << ", \"targets_judged\": " << f.targets_judged
    << ", \"targets_complete_when_judged\": " << f.targets_complete_when_judged << ", \"next\": [";
  for (size_t i = 0; i < round.follower_next.size(); ++i) j << (i ? ", " : "") << vec(round.follower_next[i]);
  j << "]}, \"judged\": [";
  for (size_t i = 0; i < round.judged.size(); ++i) {
    const TargetJudgement& t = round.judged[i];
    char b[200];
    std::snprintf(b, sizeof(b),
                  "{\"target\": %llu, \"complete\": %d, \"voxels\": %d, \"covered\": %d, \"gap\": \"%s\", "
                  "\"distance_m\": %.2f, \"incidence_deg\": %.1f, \"elevation_deg\": %.1f}",
                  static_cast<unsigned long long>(t.target), t.complete ? 1 : 0, t.voxels, t.covered_voxels,
                  std::string(core::to_string(core::CoverageGap(t.gap))).c_str(), t.distance_m, t.incidence_deg, t.elevation_deg);
    j << (i ? ", " : "") << b;
  }
  j << "]}\n";
  return j.str();
}

}  // namespace hexplore::planning
