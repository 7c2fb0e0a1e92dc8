#pragma once
// Sloped ground as a low sensor sees it from below. A flight of stairs seen from its foot maps
// as a few sloped ground supervoxels with the risers between them, which read as walls: the
// treads above are seen at grazing angles or not at all. Driven up, the flight is ground of the
// graph (tests/highlevel/climb_graph_test.cc), but from its foot the pieces are not joined and
// the top of the known flight is walled, so nothing ever sent a robot up: in the multi-building
// missions of stops 56-57 no robot climbed a flight, and every observable sample they missed
// was upstairs (tools/unseen). Two readings of the planning map (HighLevelMap) take the graph
// and the frontier up the flight:
// - sloped ground pieces on one plane are joined even with a wall between them (a riser), and
// - a wall standing uphill of sloped ground, with no ground seen beyond it, may as well be the
//   next step: that side is a frontier until ground is seen there or a look gives it up.
// In missions robots still stay off flights: the clearance model reads the risers as walls
// too, so no view may stand on a flight (common/planning/README.md, "Flights bridged").

#include <cstdint>

#include <Eigen/Core>

#include "common/highlevel/supervoxel.h"

namespace hexplore::highlevel {

// Ground tilted this much or more is a slope with an uphill side (noise on flat ground tilts
// normals by a few degrees; the flights of the built-in scenes are 30-33 deg, ramps 18 deg).
inline constexpr double kSlopeTiltDeg = 15.0;

bool sloped(const Supervoxel& ground);

// The sides among `sides` (bit i: rim_side_direction(i)) that face uphill of sloped ground
// (within 45 deg); none for ground that is not sloped.
uint8_t uphill_sides(const Supervoxel& ground, uint8_t sides);

// Whether two sloped ground supervoxels lie on one plane (each centre within 0.15 m of the
// other's plane, normals within 10 deg) and at most `reach_m` apart in the plane: a flight's
// pieces on either side of a riser. Symmetric.
bool on_one_slope(const Supervoxel& a, const Supervoxel& b, double reach_m);

// Whether a facade near ground (centre and normal of each) is a step of the ground's slope
// rather than a wall: the ground is sloped, the facade's centre lies on the ground's plane
// (within a quarter metre: a riser's centre is a few centimetres off it) and it does not face
// across the slope (a riser faces downhill, a tread seen too steeply faces up; a wall beside a
// flight faces across it). A step neither keeps a body off the ground nor closes its rim.
bool step_of_slope(const Eigen::Vector3d& ground_center, const Eigen::Vector3d& ground_normal,
                   const Eigen::Vector3d& facade_center, const Eigen::Vector3d& facade_normal);

}  // namespace hexplore::highlevel
