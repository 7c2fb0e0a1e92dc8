#include "common/evaluation/completeness_evaluator.h"

#include <algorithm>
#include <set>
#include <tuple>

#include "common/core/log.h"
#include "common/sim/ground_truth.h"
#include "common/sim/observability.h"
#include "common/sim/ray_caster.h"
#include "common/sim/scenes.h"

namespace hexplore::evaluation {

CompletenessEvaluator::CompletenessEvaluator(const core::TeamConfig& team, EvaluatorOptions options)
    : scene_(std::make_unique<sim::SceneInfo>(
          sim::load_team_scene(team))) {
  samples_ = std::make_unique<sim::SurfaceSamples>(
      sim::sample_surface(scene_->mesh, options.sample_spacing_m, team.params.seed, &scene_->site));
  if (options.observable) {
    const sim::RayCaster caster(scene_->mesh);
    observable_mask_ = sim::observable_mask(caster, *samples_, team, scene_->site);
  }
  core::LogLine(core::LogLevel::kInfo, "station")
      << "evaluator: scene '" << team.scene << "', " << samples_->points.size() << " ground-truth samples, "
      << observable_count() << " observable";
}

CompletenessEvaluator::~CompletenessEvaluator() = default;

void CompletenessEvaluator::set_robot_map(const std::string& robot, double resolution_m,
                                          std::span<const int32_t> keys_xyz) {
  auto& map = maps_[robot];
  map.resolution_m = resolution_m;
  map.keys_xyz.assign(keys_xyz.begin(), keys_xyz.end());
}

CompletenessSample CompletenessEvaluator::evaluate(double mission_time_s) const {
  CompletenessSample sample;
  sample.sim_time_s = mission_time_s;
  if (maps_.empty()) return sample;
  // Robots share one resolution in practice; the union is built at the first robot's.
  const double resolution = maps_.begin()->second.resolution_m;
  std::vector<int32_t> all;
  for (const auto& [robot, map] : maps_) {
    const auto set = sim::VoxelSet::from_keys(map.resolution_m, map.keys_xyz);
    sample.per_robot[robot] = sim::completeness(*samples_, set).fraction;
    all.insert(all.end(), map.keys_xyz.begin(), map.keys_xyz.end());
  }
  const auto team_set = sim::VoxelSet::from_keys(resolution, all);
  sample.team = sim::completeness(*samples_, team_set).fraction;
  sample.team_observable = observable_mask_.empty()
                               ? sample.team
                               : sim::completeness(*samples_, team_set, &observable_mask_).fraction;
  return sample;
}

std::vector<Eigen::Vector3f> CompletenessEvaluator::union_points() const {
  // Teammates map the same cells: each cell once (robots share the map resolution).
  std::set<std::tuple<int32_t, int32_t, int32_t>> seen;
  std::vector<Eigen::Vector3f> points;
  for (const auto& [robot, map] : maps_)
    for (size_t i = 0; i + 2 < map.keys_xyz.size(); i += 3) {
      if (!seen.emplace(map.keys_xyz[i], map.keys_xyz[i + 1], map.keys_xyz[i + 2]).second) continue;
      points.emplace_back(static_cast<float>((map.keys_xyz[i] + 0.5) * map.resolution_m),
                          static_cast<float>((map.keys_xyz[i + 1] + 0.5) * map.resolution_m),
                          static_cast<float>((map.keys_xyz[i + 2] + 0.5) * map.resolution_m));
    }
  return points;
}

size_t CompletenessEvaluator::sample_count() const { return samples_->points.size(); }

size_t CompletenessEvaluator::observable_count() const {
  if (observable_mask_.empty()) return samples_->points.size();
  return static_cast<size_t>(std::count(observable_mask_.begin(), observable_mask_.end(), uint8_t{1}));
}

}  // namespace hexplore::evaluation
