#pragma once
// Body clearance on the high-level map: how far a ground point lies from the facade
// supervoxels around body height (walls, rubble, vehicles), and where to move a path waypoint
// so that a body of a given radius fits there. Facades are known only by centre and normal, so
// each is taken as a patch: a strip along the surface for wall-like ones, a disc for the rest.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/supervoxel.h"

namespace hexplore::highlevel {

struct ClearanceOptions {
  std::vector<double> body_radius_m;      // per species index (footprint half-diagonal); empty: off
  std::vector<double> body_half_width_m;  // per species index: the least clearance a body stands in
  double facade_half_extent_m = 0.5;  // a facade patch reaches this far from its centre (eta_s / 2)
  double below_m = 0.2;               // facades centred from this far below the ground ...
  double above_m = 1.5;               // ... to this far above it are in a body's way there
  double max_shift_m = 0.5;           // a waypoint moves at most this far from its vertex

  bool enabled() const { return !body_radius_m.empty(); }
};

// Footprint half-diagonal and half-width of every species of the team (species index order).
std::vector<double> body_radii(const core::TeamConfig& team);
std::vector<double> body_half_widths(const core::TeamConfig& team);
// Both, for the map of a team.
ClearanceOptions clearance_options(const core::TeamConfig& team);

// Supervoxel centres on a planar grid, for clearance queries and for finding the ground
// vertices near a changed facade.
class ClearanceIndex {
 public:
  explicit ClearanceIndex(ClearanceOptions options = {}, double cell_m = 1.0);
  void insert(const Supervoxel& sv);
  void erase(const Supervoxel& sv);
  void clear() { cells_.clear(); }

  // Distance in the plane from p to the nearest facade patch in p's height band, looked for
  // within `search_m`; search_m when there is none that close.
  double clearance(const Eigen::Vector3d& p, double search_m) const;
  // p moved (at most max_shift_m, same z) away from the facades closer than `radius`, when
  // that gains clearance; else p.
  Eigen::Vector3d clear_position(const Eigen::Vector3d& p, double radius) const;
  // Keys of ground supervoxels centred within `radius` (in the plane) of p.
  std::vector<uint64_t> ground_near(const Eigen::Vector3d& p, double radius) const;

  const ClearanceOptions& options() const { return options_; }

 private:
  struct Entry {
    uint64_t key = 0;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    bool facade = false;
  };
  uint64_t cell_key(const Eigen::Vector3d& p) const;
  template <typename F>
  void for_each_near(const Eigen::Vector3d& p, double radius, F&& f) const;
  Eigen::Vector2d nearest_point(const Entry& facade, const Eigen::Vector2d& p) const;
  bool in_band(const Entry& facade, const Eigen::Vector3d& p) const;

  ClearanceOptions options_;
  double cell_m_;
  std::unordered_map<uint64_t, std::vector<Entry>> cells_;
};

}  // namespace hexplore::highlevel
