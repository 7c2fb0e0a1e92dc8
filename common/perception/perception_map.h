#pragma once
// One robot's basic perception map (paper: "Basic Perception-Map Representation"): an octree of
// Gaussian voxels with terrain metrics, per-species traversal risk, team traversability and
// observation metrics, updated scan by scan; tracks which voxels changed since the last
// publication and saves/loads itself so a restarted mapping service resumes its map.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/core/coverage_gap.h"
#include "common/perception/flat_key_map.h"
#include "common/perception/map_params.h"
#include "common/perception/neighbour_lookup.h"
#include "common/perception/teammate_filter.h"
#include "common/perception/terrain_metrics.h"
#include "common/perception/voxel_octree.h"
#include "common/perception/voxel_view.h"

namespace hexplore::perception {

// One LiDAR frame: points already in the world frame, packed x,y,z float triples.
struct ScanPoints {
  Eigen::Vector3d sensor_origin = Eigen::Vector3d::Zero();
  const float* xyz = nullptr;
  size_t count = 0;
  double max_range_m = 0.0;  // > 0: points farther from the sensor are dropped as implausible
};

// What one integrate() call did with the points it was given.
struct IntegrationStats {
  size_t points_in = 0;
  size_t points_integrated = 0;
  size_t dropped_non_finite = 0;
  size_t dropped_teammate = 0;
  size_t dropped_out_of_range = 0;
  size_t dropped_outside_map = 0;   // beyond the octree's +-4.9 km (at 0.15 m) extent
  size_t voxels_touched = 0;
  size_t voxels_created = 0;
  size_t voxels_recomputed = 0;     // metric updates: touched voxels and their dependants
};

// A map file that cannot be read: says which file and what is wrong with it.
class MapFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PerceptionMap {
 public:
  // Throws std::invalid_argument when the parameters are invalid.
  explicit PerceptionMap(MapParams params);

  const MapParams& params() const { return params_; }
  double resolution() const { return params_.resolution_m; }

  // Integrates one scan. Points that are non-finite, beyond max range or inside a teammate's
  // (margin-grown) body box are dropped and counted. Throws std::invalid_argument for a
  // non-finite sensor origin or a null point buffer; the map is then unchanged.
  IntegrationStats integrate(const ScanPoints& scan, const std::vector<OrientedBox>& teammates);

  core::GridCell key_of(const Eigen::Vector3d& p) const;
  Eigen::Vector3d centre_of(const core::GridCell& key) const;
  std::optional<VoxelView> find(const core::GridCell& key) const;

  size_t voxel_count() const { return voxel_count_; }
  // Every occupied voxel (snapshot for the evaluator, full deltas after a restart).
  std::vector<VoxelView> voxels() const;
  // Voxels whose published attributes changed since the previous call (new voxels, flag or
  // risk-mask changes, mean moved > mean_tolerance_m, normal turned > normal_tolerance_deg);
  // their current state becomes the published state.
  std::vector<VoxelView> take_changes();
  size_t pending_changes() const { return changed_.size(); }

  // Heap bytes held by the octree and the change list (octomap's accounting, no malloc overhead).
  size_t memory_bytes() const;

  // Whole-map save/load: header (magic, version, resolution, species count, voxel layout,
  // voxel count, payload length and checksum) followed by octomap's binary node stream.
  // load() replaces this map's contents; on any error it throws MapFileError naming the file
  // and the problem, and leaves the map as it was. The change list is empty after load().
  void save(const std::string& path) const;
  void load(const std::string& path);

 private:
  struct Touched {
    octomap::OcTreeKey key;
    VoxelNode* node;
    uint32_t points;
    bool propagates;  // new, or at least doubled: its neighbours' metrics are recomputed
    bool created;
  };
  struct Accumulator {
    octomap::OcTreeKey key;
    uint64_t order = 0;  // Morton code of key
    uint32_t n = 0;
    double s[3] = {0, 0, 0};
    double q[6] = {0, 0, 0, 0, 0, 0};
  };
  struct Pending {
    octomap::OcTreeKey key;
    VoxelNode* node;
  };

  // The steps of integrate(), in order (each says what it does where it is defined).
  void group_points(const ScanPoints& scan, const BodyFilter& bodies, IntegrationStats& stats);
  void fold_into_leaves(IntegrationStats& stats);
  void update_metrics(const Eigen::Vector3d& sensor_origin, NeighbourLookup& lookup);
  void refresh_terrain_around_new(NeighbourLookup& lookup);

  Eigen::Vector3d centre_of(const octomap::OcTreeKey& key) const;
  VoxelView view_of(const octomap::OcTreeKey& key, const VoxelData& d) const;
  void update_observation(VoxelData& d, const Eigen::Vector3d& centre, const Eigen::Vector3d& sensor,
                          uint32_t points) const;
  void refresh_state(const octomap::OcTreeKey& key, VoxelData& d, NeighbourLookup& lookup);
  // Why the voxel is not a CSE yet (kNone when it is): the first unmet term of eq. 2.
  core::CoverageGap coverage_gap(const VoxelData& d) const;
  double observation_density(const VoxelData& d) const;  // rho(v) as MapParams::density says
  // gamma_th for a voxel with this normal: the ground threshold below s_th, else the facade one.
  double angle_threshold_deg(const float normal[3]) const;
  bool published_state_moved(const VoxelData& d, const Eigen::Vector3d& centre) const;

  MapParams params_;
  TerrainWindow window_;
  VoxelOcTree tree_;
  size_t voxel_count_ = 0;
  std::vector<uint64_t> changed_;
  // Scan-local scratch, kept between scans for its capacity.
  FlatKeyMap<uint32_t> groups_;
  std::vector<Accumulator> accumulators_;
  std::vector<Touched> touched_;
  std::vector<Pending> geometry_set_;
  std::vector<Pending> risk_set_;
  std::vector<NeighbourLookup::Brick> bricks_;
  FlatKeyMap<uint32_t> brick_index_;
};

}  // namespace hexplore::perception
