#pragma once
// The station's ground-truth evaluator (the only place besides sim that reads ground truth):
// completeness of each robot's occupied voxels and of their union against surface samples of
// the scene, and the "observable" variant restricted to what the team could see.

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/core/team_config.h"
#include "common/evaluation/experiment_record.h"

namespace hexplore::sim {
struct SceneInfo;
struct SurfaceSamples;
}  // namespace hexplore::sim

namespace hexplore::evaluation {

struct EvaluatorOptions {
  double sample_spacing_m = 0.1;  // issue 3: ~0.1 m ground-truth samples
  bool observable = true;         // also compute the observable mask (seconds, once)
};

class CompletenessEvaluator {
 public:
  // Loads or generates the team's scene (TeamConfig::scene, seed params.seed). Throws
  // sim::SceneError for a scene that cannot be loaded.
  CompletenessEvaluator(const core::TeamConfig& team, EvaluatorOptions options = {});
  ~CompletenessEvaluator();

  // Replaces one robot's map: its occupied voxels as (ix, iy, iz) triples at `resolution_m`.
  void set_robot_map(const std::string& robot, double resolution_m, std::span<const int32_t> keys_xyz);
  // Completeness now, team (union), observable and per robot.
  CompletenessSample evaluate(double mission_time_s) const;
  // Occupied voxel centres of the union of all robot maps, each cell once (the reconstruction
  // the results export).
  std::vector<Eigen::Vector3f> union_points() const;

  size_t sample_count() const;
  size_t observable_count() const;

 private:
  struct RobotMap {
    double resolution_m = 0.1;
    std::vector<int32_t> keys_xyz;
  };
  std::unique_ptr<sim::SceneInfo> scene_;
  std::unique_ptr<sim::SurfaceSamples> samples_;
  std::vector<uint8_t> observable_mask_;
  std::map<std::string, RobotMap> maps_;
};

}  // namespace hexplore::evaluation
