#pragma once
// Ground-truth evaluation: surface samples of the scene (area-weighted, ~spacing apart,
// deterministic per seed) and the completeness of a map given as a set of occupied voxels:
// the fraction of samples within one voxel (26-neighbourhood) of an occupied voxel.

#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/seed_key.h"
#include "common/sim/triangle_mesh.h"

namespace hexplore::sim {

struct SurfaceSamples {
  std::vector<Eigen::Vector3f> points;
  double spacing_m = 0.1;
};

// About one sample per spacing^2 of surface, placed uniformly on each triangle. With
// `crop`, only samples inside it are kept (the scene's evaluation site).
SurfaceSamples sample_surface(const TriangleMesh& mesh, double spacing_m, uint64_t seed,
                              const Eigen::AlignedBox3d* crop = nullptr);

// Occupied voxels of a map at one resolution (cells as core::cell_of: floor(p / resolution)).
class VoxelSet {
 public:
  explicit VoxelSet(double resolution_m) : resolution_m_(resolution_m) {}
  // From OccupiedVoxels.keys_xyz (ix, iy, iz triples).
  static VoxelSet from_keys(double resolution_m, std::span<const int32_t> keys_xyz);
  static VoxelSet from_points(double resolution_m, std::span<const Eigen::Vector3f> points);

  void insert(const core::GridCell& c) { keys_.insert(core::seed_key(c)); }
  bool contains(const core::GridCell& c) const { return keys_.count(core::seed_key(c)) > 0; }
  // Whether the voxel holding p or one of its 26 neighbours is occupied.
  bool near(const Eigen::Vector3f& p) const;
  size_t size() const { return keys_.size(); }
  template <typename F>
  void for_each_cell(F&& f) const {
    for (uint64_t key : keys_) f(core::cell_of_key(key));
  }
  double resolution_m() const { return resolution_m_; }

 private:
  double resolution_m_;
  std::unordered_set<uint64_t> keys_;
};

struct Completeness {
  double fraction = 0.0;  // covered / total (0 when total is 0)
  size_t covered = 0;
  size_t total = 0;
};

// Completeness of `map` over the samples; with `mask`, only samples whose mask entry is
// non-zero count (the observable variant).
Completeness completeness(const SurfaceSamples& samples, const VoxelSet& map,
                          const std::vector<uint8_t>* mask = nullptr);

}  // namespace hexplore::sim
