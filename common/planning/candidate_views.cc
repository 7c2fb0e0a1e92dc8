#include "common/planning/candidate_views.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "common/planning/frontier.h"
#include "common/planning/labels.h"
#include "common/planning/view_costs.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {
namespace {

int species_mask(const TaskView& v, const TeamCapabilities& team, const std::vector<std::unordered_set<uint64_t>>& reachable) {
  int mask = 0;
  for (size_t k = 0; k < team.species.size() && k < reachable.size(); ++k)
    if (species_can_take(v, team.species[k], reachable[k])) mask |= 1 << k;
  return mask;
}

struct Seen {
  uint64_t target;
  int requirement;  // observation level needed to see it from here
  double score;
  bool facade;
  Eigen::Vector3d center;
  bool frontier = false;  // ground at the frontier of the known ground (seen from its own vertex only)
};

}  // namespace

std::vector<CandidateView> candidate_views(const MapContext& ctx, const std::vector<TaskView>& views,
                                           const TeamCapabilities& team, const PlannerOptions& o, double radius,
                                           const std::vector<std::unordered_set<uint64_t>>& reachable) {
  std::vector<CandidateView> out;
  for (const auto& v : views) {
    CandidateView c;
    c.view = v;
    std::sort(c.view.targets.begin(), c.view.targets.end());
    c.quality = v.facade ? v.score : 1.0;
    c.task_view = true;
    c.species_mask = species_mask(v, team, reachable);
    if (c.species_mask != 0) out.push_back(std::move(c));
  }

  // Ground near each task view, and which task views' targets it should be scored against
  // (the MNSS neighbourhood: a candidate serves the views within `radius` of it).
  std::map<uint64_t, std::vector<int>> near;
  for (size_t v = 0; v < views.size(); ++v)
    for (const auto* g : ctx.ground.within(views[v].position, radius)) near[g->key].push_back(int(v));

  std::vector<int> levels;
  for (const auto& s : team.species) levels.push_back(s.observation_level);
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  const double max_range = team.max_observation_range();

  std::vector<Seen> seen;
  for (const auto& [ground_key, near_views] : near) {
    const highlevel::Supervoxel* g = ctx.map.find(ground_key);
    if (!g) continue;
    const Eigen::Vector3d sensor = g->center + g->normal.normalized() * o.sensor_height_m;
    seen.clear();
    for (int v : near_views)
      for (uint64_t t : views[size_t(v)].targets) {
        const highlevel::Supervoxel* sv = ctx.map.find(t);
        if (!sv || ctx.tried_from(t, g->center)) continue;  // its task view stays a candidate
        if (sv->facade()) {
          const ViewGeometry geo = view_geometry(sensor, g->normal, sv->center, sv->normal);
          if (geo.distance_m >= max_range || !angles_ok(geo, o, o.shared_view_margin_deg)) continue;
          const int req = observation_requirement((g->center - sv->center).norm(), team);
          if (req == 0 || !ctx.occlusion.clear(sensor, *sv)) continue;
          seen.push_back({t, req, visibility_score(geo, o), true, sv->center});
        } else {
          const double score = ground_target_score(ctx.map, *g, *sv, o);
          if (score <= 0.0) continue;
          seen.push_back({t, 1, score, false, sv->center, at_frontier(ctx.map, *sv, o.region)});
        }
      }
    if (seen.empty()) continue;
    std::sort(seen.begin(), seen.end(), [](const Seen& a, const Seen& b) { return a.target < b.target; });
    size_t kept = 0;
    for (int level : levels) {
      CandidateView c;
      c.view.key = ground_key;
      c.view.ground_key = ground_key;
      c.view.position = g->center;
      c.view.look_at = g->center;
      c.view.traversal_requirement = g->traversal_requirement;
      c.view.observation_requirement = level;
      double best = -1.0;
      for (const Seen& s : seen) {
        if (s.requirement > level) continue;
        c.view.targets.push_back(s.target);
        c.view.frontier = c.view.frontier || s.frontier;
        c.quality += s.score;
        if (s.facade && s.score > best) {
          best = s.score;
          c.view.facade = true;
          c.view.look_at = s.center;
          c.view.score = s.score;
        }
      }
      // A higher level is a separate candidate only where it sees more than the lower one.
      if (c.view.targets.size() <= kept) continue;
      kept = c.view.targets.size();
      c.view.label = task_label(level, c.view.traversal_requirement, team, o.beta_zeta, o.beta_varsigma);
      c.species_mask = species_mask(c.view, team, reachable);
      if (c.species_mask != 0) out.push_back(std::move(c));
    }
  }
  std::sort(out.begin(), out.end(), [](const CandidateView& a, const CandidateView& b) {
    return std::make_tuple(a.view.ground_key, a.view.observation_requirement, !a.task_view, a.view.key) <
           std::make_tuple(b.view.ground_key, b.view.observation_requirement, !b.task_view, b.view.key);
  });
  return out;
}

}  // namespace hexplore::planning
