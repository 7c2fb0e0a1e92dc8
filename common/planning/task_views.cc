#include "common/planning/task_views.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "common/planning/frontier.h"
#include "common/planning/labels.h"
#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::planning {

const char* to_string(TargetOutcome o) {
  switch (o) {
    case TargetOutcome::kView: return "has_view";
    case TargetOutcome::kGivenUp: return "given_up";
    case TargetOutcome::kNoViewpoint: return "no_viewpoint";
    case TargetOutcome::kOccluded: return "occluded";
    case TargetOutcome::kUnreachable: return "unreachable";
    case TargetOutcome::kUnassignable: return "unassignable";
  }
  return "unknown";
}

namespace {

// Whether a robot of some species can stand on `ground` and observe from there a target
// `distance_m` away (ground centre to target, as observation_requirement measures it).
bool some_species_can_take(const MapContext& ctx, const TeamCapabilities& team, const highlevel::Supervoxel& ground,
                           double distance_m) {
  const int observation = observation_requirement(distance_m, team);
  if (observation == 0) return false;  // beyond every species' range
  for (size_t k = 0; k < team.species.size(); ++k) {
    if (!matches(observation, ground.traversal_requirement, team.species[k])) continue;
    if (k < ctx.reachable_by_species.size() && !ctx.reachable_by_species[k].count(ground.key)) continue;
    return true;
  }
  return false;
}

// The observation ranges a facade target's task view is searched within, in turn. The paper
// labels a view by the weakest species that can take it, "to prevent overloading
// high-capability robots", but picks the view by visibility score alone, and Vis = 1 / (beta_i Inc +
// beta_l |m|) prefers a frontal view from 12 m to a 30 deg view from 4 m: a low target the
// SLUGCAT sees well from its 10 m became the MR1000's alone, whose private work then set the
// length of the whole mission (common/planning/README.md, "Whose work a view is"). So the
// best view within the shortest species range comes first, and a longer range is searched
// only for targets that range does not see.
std::vector<double> view_range_tiers(const TeamCapabilities& team, const PlannerOptions& o) {
  std::vector<double> tiers;
  if (o.weakest_species_views)
    for (const auto& s : team.species)
      if (s.observation_range_m > 0.0) tiers.push_back(s.observation_range_m);
  tiers.push_back(team.max_observation_range());
  std::sort(tiers.begin(), tiers.end());
  tiers.erase(std::unique(tiers.begin(), tiers.end()), tiers.end());
  return tiers;
}

}  // namespace

bool best_facade_view(const MapContext& ctx, const highlevel::Supervoxel& target,
                      const std::vector<const highlevel::Supervoxel*>& candidates, double range,
                      const PlannerOptions& o, TaskView& view, int64_t* rays, bool* sighted,
                      const TeamCapabilities* team) {
  struct Scored {
    double score;
    const highlevel::Supervoxel* ground;
    ViewGeometry geometry;
    bool tried;  // the target stayed open when observed from here: taken only when no other spot sees it
  };
  std::vector<Scored> ok;
  ok.reserve(candidates.size());
  // Cheap rejections first, on cosines and squared distances (no trigonometry).
  const double cos_gamma = std::cos(o.gamma_th_deg * M_PI / 180.0);
  const double sin_lo = std::sin(o.theta_l_deg * M_PI / 180.0), sin_hi = std::sin(o.theta_u_deg * M_PI / 180.0);
  const double tn = target.normal.norm();
  const Eigen::Vector3d target_n = tn > 1e-9 ? Eigen::Vector3d(target.normal / tn) : Eigen::Vector3d::UnitZ();
  for (const auto* g : candidates) {
    const Eigen::Vector3d gn = g->normal.normalized();
    const Eigen::Vector3d m = target.center - (g->center + gn * o.sensor_height_m);
    const double d2 = m.squaredNorm();
    if (d2 >= range * range || d2 < 1e-12) continue;
    const double inv = 1.0 / std::sqrt(d2);
    if (-m.dot(target_n) * inv <= cos_gamma) continue;  // in front of the surface, within gamma_th
    const double s = m.dot(gn) * inv;
    if (s < sin_lo || s > sin_hi) continue;
    const Eigen::Vector3d sensor = g->center + gn * o.sensor_height_m;
    const ViewGeometry geo = view_geometry(sensor, g->normal, target.center, target.normal);
    if (!angles_ok(geo, o)) continue;
    ok.push_back({visibility_score(geo, o), g, geo, ctx.tried_from(target.key, g->center)});
  }
  if (sighted && !ok.empty()) *sighted = true;
  // Ray casts are the expensive part: try candidates best-first and stop at the first clear one.
  std::sort(ok.begin(), ok.end(), [](const Scored& a, const Scored& b) {
    if (a.tried != b.tried) return b.tried;
    return a.score != b.score ? a.score > b.score : a.ground->key < b.ground->key;
  });
  for (const auto& s : ok) {
    if (team != nullptr && !some_species_can_take(ctx, *team, *s.ground, (s.ground->center - target.center).norm()))
      continue;
    if (rays) ++*rays;
    const Eigen::Vector3d sensor = s.ground->center + s.ground->normal.normalized() * o.sensor_height_m;
    if (!ctx.occlusion.clear(sensor, target)) continue;
    view = TaskView{};
    view.key = target.key;
    view.ground_key = s.ground->key;
    view.position = s.ground->center;
    view.look_at = target.center;
    view.facade = true;
    view.targets = {target.key};
    view.traversal_requirement = s.ground->traversal_requirement;
    view.score = s.score;
    return true;
  }
  return false;
}

std::vector<TaskView> generate_task_views(const MapContext& ctx, const TeamCapabilities& team,
                                          const PlannerOptions& o, ViewGenerationStats* stats,
                                          std::vector<TargetRecord>* targets) {
  ViewGenerationStats local;
  ViewGenerationStats& st = stats ? *stats : local;
  st = {};
  // Where the task view of a facade target is searched for: within the whole team's reach,
  // or (PlannerOptions::weakest_species_views) within the shortest range that sees it first.
  const std::vector<double> range_tiers = view_range_tiers(team, o);
  std::vector<TaskView> views;
  std::unordered_set<uint64_t> covered_ground;
  auto record = [&](uint64_t key, TargetOutcome outcome) {
    if (targets) targets->push_back({key, outcome});
  };

  // A target outside the exploration region or given up by the team gets no view (counted).
  auto excluded = [&](uint64_t key, const auto& sv) {
    if (!o.region.contains(sv.center)) {
      ++st.outside_region;
      return true;
    }
    if (ctx.is_ignored(key)) {
      ++st.ignored;
      record(key, TargetOutcome::kGivenUp);
      return true;
    }
    return false;
  };

  for (const auto& [key, sv] : ctx.map.supervoxels()) {
    if (!sv.facade() || sv.covered || excluded(key, sv)) continue;
    ++st.facade_targets;
    // Growing search radius: Vis <= 1 / (beta_l * distance), so once the best visible view
    // within r scores at least what any view beyond r could, it is the best within range.
    TaskView view;
    bool found = false, sighted = false;
    for (double tier : range_tiers) {
      for (double r = std::min(4.0, tier);; r = std::min(tier, 2.0 * r)) {
        found = best_facade_view(ctx, sv, ctx.ground.within(sv.center, r, /*sorted=*/false), r, o, view,
                                 &st.rays_cast, &sighted, &team);
        if (r >= tier) break;
        const double beyond = r - o.sensor_height_m;
        // (A spot the target was observed from in vain is only a fallback: look farther first.)
        if (found && beyond > 0 && view.score >= 1.0 / (o.beta_l * beyond) && !ctx.tried_from(sv.key, view.position)) break;
      }
      if (found) break;
    }
    if (!found) {
      ++st.unobservable_facades;
      record(key, sighted ? TargetOutcome::kOccluded : TargetOutcome::kNoViewpoint);
      continue;
    }
    view.observation_requirement = observation_requirement((view.position - sv.center).norm(), team);
    // Composite view: ground-ISE supervoxels next to where the robot stands are seen too.
    view.label = task_label(view.observation_requirement, view.traversal_requirement, team, o.beta_zeta, o.beta_varsigma);
    if (view.label == kUnassignable) {
      record(key, TargetOutcome::kUnassignable);
      continue;
    }
    for (const auto* g : ctx.ground.within(view.position, o.ground_cover_radius_m)) {
      // Ground at the frontier is looked at from its own spot (beyond the rim is seen from the rim).
      if (g->covered || at_frontier(ctx.map, *g, o.region) || covered_ground.count(g->key) || ctx.is_ignored(g->key) || !o.region.contains(g->center)) continue;
      if (ctx.tried_from(g->key, view.position)) continue;
      view.targets.push_back(g->key);
      covered_ground.insert(g->key);
      ++st.composite_ground;
    }
    for (uint64_t t : view.targets) record(t, TargetOutcome::kView);
    views.push_back(std::move(view));
    ++st.facade_views;
  }
  for (const auto& [key, sv] : ctx.map.supervoxels()) {
    if (!sv.traversable() || !needs_look(ctx.map, sv, o.region) || covered_ground.count(key) || excluded(key, sv)) continue;
    if (!ctx.is_reachable(key)) {
      ++st.unreachable_ground;
      record(key, TargetOutcome::kUnreachable);
      continue;
    }
    TaskView view;
    view.key = key;
    view.ground_key = key;
    view.position = sv.center;
    view.look_at = sv.center;
    view.targets = {key};
    view.frontier = at_frontier(ctx.map, sv, o.region);
    view.traversal_requirement = sv.traversal_requirement;
    view.observation_requirement = 1;
    view.label = task_label(1, view.traversal_requirement, team, o.beta_zeta, o.beta_varsigma);
    if (view.label == kUnassignable) {
      record(key, TargetOutcome::kUnassignable);
      continue;
    }
    record(key, TargetOutcome::kView);
    st.frontier_views += view.frontier ? 1 : 0;
    views.push_back(std::move(view));
    ++st.ground_views;
  }
  std::sort(views.begin(), views.end(), [](const TaskView& a, const TaskView& b) { return a.key < b.key; });
  st.public_views = int(std::count_if(views.begin(), views.end(), [](const TaskView& v) { return v.label == kPublic; }));
  return views;
}

}  // namespace hexplore::planning
