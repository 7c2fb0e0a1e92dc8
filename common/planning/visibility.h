#pragma once
// The visibility function J and score Vis of the paper ("Task-View Generation") over the
// supervoxel map: a line of sight is blocked by facade supervoxels (walls, obstacles), each
// taken as a plate through its centre across its normal, as wide as its eta_s cell; ground is
// treated as non-occluding because views are lifted to sensor height above it.

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "common/core/seed_key.h"
#include "common/highlevel/high_level_map.h"
#include "common/planning/capabilities.h"

namespace hexplore::planning {

inline constexpr double kDegToRad = M_PI / 180.0;
inline constexpr double kRadToDeg = 180.0 / M_PI;

// Plates rather than whole cells: a cube that blocks every ray through it must spare the last
// cell before the target, or a target's own wall patch hides it; sparing it let rays through
// the wall the target is on (the inside face of an outer wall was "seen" from outside), and six
// in ten of the MR1000's looks were at targets the scene hid from the spot (common/planning/
// README.md, "Lines of sight through the wall: plates, not cells").
class OcclusionGrid {
 public:
  OcclusionGrid(const highlevel::HighLevelMap& map, double cell_m);
  // True when the segment from `from` to the centre of `target` crosses no plate before it
  // arrives within kTargetMarginM of it, except plates of the target's own surface: within a
  // cell of it and facing within 60 deg of its way (a surface's supervoxels are not exactly
  // coplanar; at a corner they overlap). The wall in front of an inside face faces the other way.
  bool clear(const Eigen::Vector3d& from, const highlevel::Supervoxel& target) const;
  size_t plates() const { return plates_.size(); }

  // A plate reaches this far from its centre, in units of the cell: past half the cell's
  // diagonal (0.71), so that a wall's plates, one per cell, leave no gap between four of them.
  static constexpr double kPlateRadiusCells = 0.75;
  static constexpr double kTargetMarginM = 0.15;
  static constexpr double kOwnSurfaceCos = 0.5;

 private:
  struct Plate {
    Eigen::Vector3d center;
    Eigen::Vector3d normal;  // unit
  };

  double cell_m_;
  std::vector<Plate> plates_;
  // Every cell a plate reaches into, with the plates that reach into it.
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

// Geometry of one (view, target) pair.
struct ViewGeometry {
  double distance_m = 0.0;     // |m|
  double incidence_rad = 0.0;  // angle between the reversed view direction and the target normal; > 90 deg: from behind
  double elevation_rad = 0.0;  // observation angle: elevation of the target above the view's plane
};

ViewGeometry view_geometry(const Eigen::Vector3d& sensor, const Eigen::Vector3d& view_normal,
                           const Eigen::Vector3d& target, const Eigen::Vector3d& target_normal);

// The angle part of J (incidence < gamma_th, observation angle within [theta_l, theta_u]),
// `margin_deg` inside each limit (PlannerOptions::shared_view_margin_deg where a spot stands in
// for other targets' views; 0 for a target's own view).
bool angles_ok(const ViewGeometry& g, const PlannerOptions& o, double margin_deg = 0.0);

// Vis = J / (beta_i * Inc + beta_l * |m|), Inc in degrees and |m| in metres; 0 when J = 0 is
// known. The paper gives no units; with equal weights (0.5, 0.5) degrees make the two terms
// comparable (0-45 deg, 0-27 m). In radians the angle term (at most 0.4) hardly counted, so the
// nearest view that passed J won: the MR1000 looked up at high targets from 16 m at 40 deg
// incidence, and 87 % of what it dwelt for stayed open (common/planning/README.md).
inline double visibility_score(const ViewGeometry& g, const PlannerOptions& o) {
  return 1.0 / (o.beta_i * g.incidence_rad * kRadToDeg + o.beta_l * g.distance_m + 1e-9);
}

// How well standing on the ground supervoxel `ground` observes the ground target `target`:
// within the composite radius 1 / (beta_l d), beyond it 0. Ground at the frontier of the known
// ground (frontier.h) is observed only from its own vertex: beyond the rim is seen from the rim.
double ground_target_score(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& ground,
                           const highlevel::Supervoxel& target, const PlannerOptions& o);

// What a robot standing on the ground supervoxel `ground` scores for `target` (MNSS and route
// pruning ask the same question): a facade target nearer than `range_m` from the sensor that
// passes J (angles, then a line of sight through `occlusion`, counted in `rays`) scores Vis; a
// ground target scores ground_target_score. 0: not seen.
double ground_view_score(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& ground,
                         const highlevel::Supervoxel& target, double range_m, const OcclusionGrid& occlusion,
                         const PlannerOptions& o, int64_t& rays);

}  // namespace hexplore::planning
