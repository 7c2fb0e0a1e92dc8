#pragma once
// The "observable" part of the ground truth for a team: samples visible within sensor range
// from ground that some species of the team can reach. Reachability is a flood fill over a
// coarse grid from the species' start poses, each move checked with the same terrain limits
// the motion model enforces; visibility is a ray cast from the sample to nearby viewpoints
// on that reachable ground. Bounded in work by the options; results are cached per key.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/team_config.h"
#include "common/sim/ground_truth.h"
#include "common/sim/ray_caster.h"

namespace hexplore::sim {

struct ObservabilityOptions {
  double grid_m = 0.5;              // flood-fill cell size
  size_t max_cells = 300000;        // flood-fill budget per species
  double viewpoint_spacing_m = 2.0;  // reachable ground thinned to one viewpoint per cell of this size
  int max_candidates = 12;          // nearest viewpoints tried per sample
};

// Ground points (x, y, support z) a robot of `species` reaches from `starts` inside `region`.
std::vector<Eigen::Vector3d> reachable_ground(const RayCaster& caster, const core::SpeciesConfig& species,
                                              std::span<const Eigen::Vector3d> starts,
                                              const Eigen::AlignedBox3d& region, const ObservabilityOptions& options = {});

// One byte per sample: 1 when some species of the team sees it from its reachable ground
// (sensor height above the ground, within its longest LiDAR range), else 0.
std::vector<uint8_t> observable_mask(const RayCaster& caster, const SurfaceSamples& samples,
                                     const core::TeamConfig& team, const Eigen::AlignedBox3d& region,
                                     const ObservabilityOptions& options = {});

// A key naming what the mask depends on: scene (name and seed), species limits and starts.
std::string observability_key(const std::string& scene, uint64_t seed, const core::TeamConfig& team);

// Thread-safe memo of observable masks per key.
class ObservableCache {
 public:
  template <typename Compute>
  std::shared_ptr<const std::vector<uint8_t>> get(const std::string& key, Compute&& compute) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = masks_.find(key);
      if (it != masks_.end()) return it->second;
    }
    auto mask = std::make_shared<const std::vector<uint8_t>>(compute());
    std::lock_guard<std::mutex> lock(mutex_);
    return masks_.emplace(key, std::move(mask)).first->second;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const std::vector<uint8_t>>> masks_;
};

}  // namespace hexplore::sim
