// Does a task view do what the planner assumes? On a built-in scene, each species first
// surveys the site (one frame from every few metres of the ground it can reach, as a robot
// would see it in passing), the survey maps become a fused high-level map, and task views
// are generated from it as in a planning round. Then, for a sample of facade views, a robot
// of a species the view is labelled for stands at the view, points its sensors at the
// view's target and scans for the species' observation time; the figures say how often the
// target supervoxel became complete (Q = 1), how far its voxels got, and what the others
// still lack (core::CoverageGap). Exploration finishes only if this is high.
//
// Usage: bench_view_efficacy [--scene single-building] [--views 60] [--scan-hz 2]
//                            [--dwell-s S (default: the species' 1 / observation speed)]
//                            [--survey-spacing-m 4] [--seed 1] [--lidar-pattern livox|fixed]
//                            [--density all_points|qualifying_points|neighbour_occupancy] [--rho-th X]
//                            [--ise-patch N] [--params-from TEAM.yaml]
//                            [--verbose true]
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <array>
#include <unordered_map>
#include <memory>
#include <string>
#include <vector>

#include "common/core/team_config.h"
#include "common/highlevel/map_fusion.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/segmenter.h"
#include "common/perception/perception_map.h"
#include "common/perception/voxel_proto.h"
#include "common/planning/capabilities.h"
#include "common/planning/labels.h"
#include "common/planning/mtsp/mtsp_problem.h"
#include "common/planning/round_inputs.h"
#include "common/sim/lidar.h"
#include "common/sim/observability.h"
#include "common/sim/ray_caster.h"
#include "common/sim/scenes.h"

namespace {

using namespace hexplore;

struct Args {
  std::string scene = "single-building";
  int views = 60;
  double scan_hz = 2.0;
  double dwell_s = -1.0;
  double survey_spacing_m = 4.0;
  uint64_t seed = 1;
  bool fixed_pattern = false;
  bool verbose = false;        // one line per view
  std::string params_from;     // team file whose params: (rho_th, patch size, ...) replace the paper's
  std::string density;         // overrides params.rho_measure
  double rho_th = -1.0;        // overrides the team default
  int ise_patch = 0;           // overrides params.min_ise_patch_voxels when > 0
  double extent_m = -1.0;      // overrides PlannerOptions::target_half_extent_m  // rotating LiDARs with a repetitive pattern instead of Livox-style
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--scene") a.scene = v;
    else if (k == "--views") a.views = std::atoi(v.c_str());
    else if (k == "--scan-hz") a.scan_hz = std::atof(v.c_str());
    else if (k == "--dwell-s") a.dwell_s = std::atof(v.c_str());
    else if (k == "--survey-spacing-m") a.survey_spacing_m = std::atof(v.c_str());
    else if (k == "--seed") a.seed = std::strtoull(v.c_str(), nullptr, 10);
    else if (k == "--lidar-pattern") a.fixed_pattern = v == "fixed";
    else if (k == "--verbose") a.verbose = v == "true";
    else if (k == "--density") a.density = v;
    else if (k == "--params-from") a.params_from = v;
    else if (k == "--rho-th") a.rho_th = std::atof(v.c_str());
    else if (k == "--ise-patch") a.ise_patch = std::atoi(v.c_str());
    else if (k == "--extent-m") a.extent_m = std::atof(v.c_str());
    else {
      std::fprintf(stderr, "unknown option %s\n", k.c_str());
      std::exit(2);
    }
  }
  return a;
}

// One robot of a species with its LiDARs, its perception map and the supervoxels of it.
struct Robot {
  core::SpeciesConfig species;
  std::vector<sim::LidarModel> lidars;
  std::unique_ptr<perception::PerceptionMap> map;
  std::unique_ptr<highlevel::SupervoxelSegmenter> segmenter;

  // Scans one frame of every LiDAR from a body standing at ground point `g`, aimed at `aim`.
  void scan_from(const sim::RayCaster& caster, const Eigen::Vector3d& g, const Eigen::Vector3d& aim) {
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.translation() = g + Eigen::Vector3d(0, 0, species.body_half_extents_m.z());
    for (sim::LidarModel& lidar : lidars) {
      lidar.aim_at(aim, body);
      const sim::LidarScan s = lidar.scan(caster, body);
      perception::ScanPoints in;
      in.sensor_origin = s.origin;
      in.xyz = reinterpret_cast<const float*>(s.points.data());
      in.count = s.points.size();
      in.max_range_m = lidar.config().max_range_m;
      map->integrate(in, {});
    }
  }
  // Feeds the map's changes to the segmenter, as mapping -> hlmap does (through the wire form).
  highlevel::SegmentationChange segment() {
    std::vector<highlevel::VoxelSample> samples;
    for (const perception::VoxelView& v : map->take_changes()) {
      v1::Voxel m;
      perception::to_proto(v, &m);
      samples.push_back(highlevel::from_proto(m));
    }
    return segmenter->update(samples);
  }
  highlevel::MapUpdate contribution() const {
    highlevel::MapUpdate u;
    u.full_snapshot = true;
    for (const auto& [key, sv] : segmenter->supervoxels()) u.upserts.push_back(highlevel::wire_rounded(sv));
    u.edge_upserts = segmenter->edges();
    return u;
  }
};

struct Outcome {
  int tested = 0, completed = 0;
  int front_completed = 0;  // the voxels on the view's side of the target's plane all complete
  double before = 0.0, after = 0.0;  // summed covered fractions
  int over90 = 0;                    // >= 90 % of its voxels complete afterwards
  // No connected patch (26-neighbourhood) of >= k incomplete voxels left, k = 3, 5, 10: the
  // target would be complete if specks of incomplete voxels counted as noise.
  int no_patch[3] = {0, 0, 0};
  std::map<core::CoverageGap, int> gap_after;
  // Other supervoxels of the species' map the dwell completed besides its target (its sensors
  // see far more than the target), and voxels it completed in all.
  long others_completed = 0, voxels_completed = 0;
};

// Size of the largest 26-connected set among `cells`.
int largest_patch(const std::set<std::array<int32_t, 3>>& cells) {
  std::set<std::array<int32_t, 3>> left = cells;
  int best = 0;
  while (!left.empty()) {
    std::vector<std::array<int32_t, 3>> stack{*left.begin()};
    left.erase(left.begin());
    int size = 0;
    while (!stack.empty()) {
      const auto c = stack.back();
      stack.pop_back();
      ++size;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            auto it = left.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == left.end()) continue;
            stack.push_back(*it);
            left.erase(it);
          }
    }
    best = std::max(best, size);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  const sim::SceneInfo scene = sim::generate_scene(args.scene, args.seed);
  const sim::RayCaster caster(scene.mesh);
  core::TeamConfig team;
  // The paper's parameters unless a team file's are asked for: the team files lower rho_th for
  // the simulator's 2 Hz LiDARs, so a bench run without them judges by a stricter density.
  if (!args.params_from.empty()) team.params = core::load_team_config(args.params_from).params;
  team.species = {core::builtin_slugcat(), core::builtin_mr1000()};
  if (args.fixed_pattern)
    for (auto& s : team.species)
      for (auto& l : s.lidars) l.non_repetitive = false;
  for (size_t i = 0; i < team.species.size(); ++i)
    team.robots.push_back({team.species[i].name, team.species[i].name, scene.suggested_starts.at(i), 0});
  if (args.rho_th >= 0) team.params.rho_th = args.rho_th;
  if (!args.density.empty()) team.params.rho_measure = args.density;
  if (args.ise_patch > 0) team.params.min_ise_patch_voxels = args.ise_patch;
  const core::AlgorithmParams& params = team.params;
  const Eigen::Vector3d centre = scene.site.center();
  std::printf("scene %s, seed %llu, rho_th %.3g (%s), ISE patch %d voxels, LiDARs at %.3g Hz\n", args.scene.c_str(),
              static_cast<unsigned long long>(args.seed), params.rho_th, params.rho_measure.c_str(),
              params.min_ise_patch_voxels, args.scan_hz);

  std::vector<Robot> robots;
  const highlevel::SegmenterParams seg = highlevel::SegmenterParams::from(params);
  for (size_t k = 0; k < team.species.size(); ++k) {
    Robot r;
    r.species = team.species[k];
    for (size_t i = 0; i < r.species.lidars.size(); ++i) r.lidars.emplace_back(r.species.lidars[i], 11 + 7 * k + i);
    perception::MapParams mp = perception::make_map_params(params, team.species, r.species);

    r.map = std::make_unique<perception::PerceptionMap>(mp);
    r.segmenter = std::make_unique<highlevel::SupervoxelSegmenter>(seg, highlevel::species_levels(team));
    // Survey: a frame from every survey_spacing of the ground this species reaches, aimed at the site centre.
    const std::vector<Eigen::Vector3d> starts = {scene.suggested_starts.at(k)};
    size_t frames = 0;
    for (const Eigen::Vector3d& g : sim::reachable_ground(caster, r.species, starts, scene.site)) {
      const double s = args.survey_spacing_m;
      if (std::fmod(std::abs(g.x()), s) >= 0.5 || std::fmod(std::abs(g.y()), s) >= 0.5) continue;
      r.scan_from(caster, g, centre);
      ++frames;
    }
    r.segment();
    std::map<core::CoverageGap, int> facade_gaps;
    std::map<std::string, std::array<int, 2>> by_kind;  // kind -> {voxels, angle-short}
    int facade_voxels = 0;
    for (const perception::VoxelView& v : r.map->voxels()) {
      if (v.ground() || !scene.site.contains(v.mean.cast<double>())) continue;
      ++facade_voxels;
      ++facade_gaps[v.coverage_gap];
      if (args.verbose) {
        const double nz = v.normal.z();
        const std::string kind = v.normal.norm() < 0.5 ? "no-normal"
                                 : nz < -0.7           ? "ceiling"
                                 : nz > 0.7            ? "up-facing"
                                 : std::abs(nz) < 0.3  ? (v.mean.z() < 1.0 ? "wall<1m" : v.mean.z() < 3.5 ? "wall<3.5m" : "wall>3.5m")
                                                       : "sloped";
        auto& k = by_kind[kind];
        ++k[0];
        k[1] += v.coverage_gap == core::CoverageGap::kAngle ? 1 : 0;
      }
    }
    for (const auto& [kind, k] : by_kind)
      std::printf("    %-10s %6d voxels (%4.1f%%), %4.1f%% of them angle-short\n", kind.c_str(), k[0],
                  100.0 * k[0] / std::max(1, facade_voxels), 100.0 * k[1] / std::max(1, k[0]));
    std::printf("survey %-8s %4zu frames, %7zu voxels, %6zu supervoxels; facade voxels %d:", r.species.name.c_str(),
                frames, r.map->voxel_count(), r.segmenter->supervoxels().size(), facade_voxels);
    for (const auto& [g, n] : facade_gaps)
      std::printf(" %s %.1f%%", std::string(core::to_string(g)).c_str(), 100.0 * n / std::max(1, facade_voxels));
    std::printf("\n");
    robots.push_back(std::move(r));
  }

  highlevel::MapFusion fusion(highlevel::species_levels(team));
  for (const Robot& r : robots) fusion.apply(r.species.name, r.contribution());
  const highlevel::HighLevelMap& fused = fusion.map();
  const planning::TeamCapabilities caps = planning::capabilities_from(team);
  planning::PlannerOptions o = planning::PlannerOptions::from(params);
  o.region = scene.site;
  if (args.extent_m >= 0) o.target_half_extent_m = args.extent_m;
  planning::PlanRequest req;
  req.map = &fused;
  for (size_t k = 0; k < team.robots.size(); ++k)
    req.robots.push_back({team.robots[k].id, int(k), scene.suggested_starts.at(k)});
  const planning::RoundInputs in = planning::prepare_round(req, caps, o);
  std::vector<const planning::TaskView*> facade;
  for (const auto& v : in.views)
    if (v.facade) facade.push_back(&v);
  int open_facades = 0;
  for (const auto& [key, sv] : fused.supervoxels()) open_facades += sv.facade() && !sv.covered && o.region.contains(sv.center);
  std::printf("fused map: %zu supervoxels, %d open facade targets, %zu task views (%zu facade)\n", fused.size(),
              open_facades, in.views.size(), facade.size());
  {
    // Open facade targets by facing and size, and how many of them have a view.
    std::set<uint64_t> viewed;
    for (const auto& v : in.views)
      for (uint64_t t : v.targets) viewed.insert(t);
    const char* facings[] = {"none", "+x", "-x", "+y", "-y", "up", "down"};
    std::map<std::string, std::array<int, 2>> by;  // "facing size" -> {targets, with a view}
    for (const auto& [key, sv] : fused.supervoxels()) {
      if (!sv.facade() || sv.covered || !o.region.contains(sv.center)) continue;
      const int f = int(highlevel::facing_of_key(key));
      const char* size = sv.voxel_count < 5 ? "1-4" : sv.voxel_count < 10 ? "5-9" : sv.voxel_count < 20 ? "10-19" : "20+";
      auto& row = by[std::string(facings[f]) + " " + size];
      ++row[0];
      row[1] += viewed.count(key) ? 1 : 0;
    }
    std::printf("open facade targets by facing and voxels (with a view):");
    for (const auto& [k, n] : by) std::printf(" [%s] %d (%d)", k.c_str(), n[0], n[1]);
    std::printf("\n");
  }

  // Each species' voxels per supervoxel of its own map (the targets' voxel sets).
  std::vector<std::unordered_map<uint64_t, std::vector<core::GridCell>>> members(robots.size());
  for (size_t k = 0; k < robots.size(); ++k)
    for (const perception::VoxelView& v : robots[k].map->voxels())
      members[k][robots[k].segmenter->supervoxel_of({v.key.x, v.key.y, v.key.z})].push_back(v.key);

  std::map<std::string, Outcome> outcomes;
  const int min_patch = team.params.min_ise_patch_voxels;
  const size_t step = std::max<size_t>(1, facade.size() / size_t(std::max(1, args.views)));
  for (size_t i = 0; i < facade.size(); i += step) {
    const planning::TaskView& v = *facade[i];
    for (size_t k = 0; k < robots.size(); ++k) {
      if (v.label != planning::kPublic && v.label != int(k)) continue;
      if (!in.reachable[k].count(v.ground_key)) continue;
      Robot& r = robots[k];
      const highlevel::Supervoxel* mine = r.segmenter->find(v.key);
      if (!mine || mine->covered) continue;  // this species' own map has no such incomplete supervoxel
      // A copy of the survey map: the view's frames on top of what the robot knew.
      Robot trial;
      trial.species = r.species;
      trial.lidars = r.lidars;
      trial.map = std::make_unique<perception::PerceptionMap>(*r.map);
      const double dwell = args.dwell_s >= 0 ? args.dwell_s : 1.0 / r.species.observation_speed_views_per_s;
      const int frames = std::max(1, int(std::lround(dwell * args.scan_hz)));
      const Eigen::Vector3d ground = fused.find(v.ground_key)->center;
      for (int f = 0; f < frames; ++f) trial.scan_from(caster, ground, v.look_at);
      // The target's voxels (as the survey segmented them) after the view.
      const auto& voxels = members[k][v.key];
      int covered = 0, hit = 0, front = 0, front_covered = 0, angle_n = 0;
      std::set<std::array<int32_t, 3>> open_voxels;
      double angle_off = 0.0, angle_seen = 0.0;  // angle-short voxels: normal vs target normal, vs the view
      const highlevel::Supervoxel* target = fused.find(v.key);
      const Eigen::Vector3d sensor = ground + Eigen::Vector3d(0, 0, o.sensor_height_m);
      const double side = (sensor - target->center).dot(target->normal);
      double short_density = 0.0;
      std::map<core::CoverageGap, int> gaps;
      for (const core::GridCell& key : voxels) {
        const auto view = trial.map->find(key);
        if (!view) continue;
        const auto before = r.map->find(key);
        if (before && view->point_count > before->point_count) ++hit;
        if (view->covered()) ++covered;
        else {
          ++gaps[view->coverage_gap];
          open_voxels.insert({key.x, key.y, key.z});
        }
        const double offset = (view->mean.cast<double>() - target->center).dot(target->normal);
        if (offset * side >= -0.03 * std::abs(side) / std::max(1e-6, std::abs(side)) || std::abs(offset) < 0.03) {
          ++front;
          front_covered += view->covered() ? 1 : 0;
        }
        if (view->coverage_gap == core::CoverageGap::kDensity) short_density += view->observation_density;
        if (args.verbose && view->coverage_gap == core::CoverageGap::kAngle && view->normal.norm() > 0.5) {
          const double off = std::acos(std::clamp(std::abs(view->normal.cast<double>().dot(target->normal)), 0.0, 1.0));
          const Eigen::Vector3d dir = (sensor - view->mean.cast<double>()).normalized();
          const double seen = std::acos(std::clamp(std::abs(view->normal.cast<double>().dot(dir)), 0.0, 1.0));
          angle_off += off * 57.3;
          angle_seen += seen * 57.3;
          ++angle_n;
        }
      }
      if (args.verbose) {
        const highlevel::Supervoxel* t = fused.find(v.key);
        std::printf("  %-8s view at (%.1f %.1f %.1f) -> target (%.1f %.1f %.1f) %.1f m, n=(%.2f %.2f %.2f): %zu voxels, "
                    "%d hit, %d complete",
                    r.species.name.c_str(), ground.x(), ground.y(), ground.z(), t->center.x(), t->center.y(),
                    t->center.z(), (t->center - ground).norm(), t->normal.x(), t->normal.y(), t->normal.z(),
                    voxels.size(), hit, covered);
        for (const auto& [g, n] : gaps) std::printf(", %s %d", std::string(core::to_string(g)).c_str(), n);
        if (gaps.count(core::CoverageGap::kDensity))
          std::printf(" (mean density %.3f)", short_density / gaps.at(core::CoverageGap::kDensity));
        if (angle_n > 0)
          std::printf(" (angle-short voxels: normal %.0f deg off the target's, seen at %.0f deg)", angle_off / angle_n,
                      angle_seen / angle_n);
        std::printf("\n");
      }
      Outcome& out = outcomes[r.species.name];
      for (const auto& [sv_key, sv_voxels] : members[k]) {
        bool was_open = false, now_complete = true;
        for (const core::GridCell& key : sv_voxels) {
          const auto b = r.map->find(key);
          const auto a = trial.map->find(key);
          const bool before_ok = b && b->covered(), after_ok = a && a->covered();
          was_open |= !before_ok;
          now_complete &= after_ok;
          out.voxels_completed += after_ok && !before_ok ? 1 : 0;
        }
        out.others_completed += sv_key != v.key && was_open && now_complete ? 1 : 0;
      }
      ++out.tested;
      out.before += double(mine->covered_voxels) / std::max(1, mine->voxel_count);
      const double frac = double(covered) / std::max<size_t>(1, voxels.size());
      out.after += frac;
      // Complete as the segmenter judges it: no patch of min_ise_patch_voxels incomplete voxels.
      const int patch = largest_patch(open_voxels);
      out.completed += patch < min_patch ? 1 : 0;
      out.front_completed += front > 0 && front_covered == front ? 1 : 0;
      out.over90 += frac >= 0.9 ? 1 : 0;
      for (int j = 0; j < 3; ++j) out.no_patch[j] += patch < std::array{3, 5, 10}[j] ? 1 : 0;
      if (covered < int(voxels.size())) {
        auto common = std::max_element(gaps.begin(), gaps.end(), [](auto& a, auto& b) { return a.second < b.second; });
        if (common != gaps.end()) ++out.gap_after[common->first];
      }
    }
  }
  std::printf("facade views observed for the species' dwell at %.1f Hz:\n", args.scan_hz);
  for (const auto& [name, out] : outcomes) {
    if (out.tested == 0) continue;
    std::printf("  %-8s %3d views: complete %5.1f%% (front face %5.1f%%), >= 90%% voxels %5.1f%%, covered voxels %4.1f%% -> %4.1f%%; still open by gap:",
                name.c_str(), out.tested, 100.0 * out.completed / out.tested, 100.0 * out.front_completed / out.tested,
                100.0 * out.over90 / out.tested,
                100.0 * out.before / out.tested, 100.0 * out.after / out.tested);
    std::printf(" no open patch of >= 3/5/10 voxels %4.1f%% %4.1f%% %4.1f%%;", 100.0 * out.no_patch[0] / out.tested,
                100.0 * out.no_patch[1] / out.tested, 100.0 * out.no_patch[2] / out.tested);
    for (const auto& [gap, n] : out.gap_after) std::printf(" %s %d", std::string(core::to_string(gap)).c_str(), n);
    std::printf("\n           per dwell besides its target: %.1f other supervoxels completed, %.0f voxels completed in all\n",
                double(out.others_completed) / out.tested, double(out.voxels_completed) / out.tested);
  }
  return 0;
}
