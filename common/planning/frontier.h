#pragma once
// The frontier of the known ground, as a coverage target. The paper's targets are surfaces the
// map holds but has not observed well enough (ISE supervoxels); ground nobody has seen at all
// makes none, so a climb whose top a low sensor cannot see over never gets a view: in the
// multi-storey scene the tracked robot mapped ramp B up to its crest from below, the roof deck
// beyond stayed unseen (the crest hides it until the sensor is within about a metre of it), and
// nothing made the robot drive the last metres (common/planning/README.md, "The frontier of
// the known ground"). So ground where the known ground ends (the map's rim: a side with neither
// ground about one seed interval out nor a wall, highlevel::ClearanceIndex::rim_sides; and
// the walled uphill side of a slope, highlevel/slopes.h: HighLevelMap::frontier_sides) facing
// into the exploration region needs a look like an ISE supervoxel: a ground view at its centre.
// A look that leaves the rim where it was (the edge of a drop, ground no sensor reaches) gives
// it up like any other target.

#include <Eigen/Geometry>

#include "common/highlevel/high_level_map.h"
#include "common/highlevel/supervoxel.h"

namespace hexplore::planning {

// Whether ground vertex `sv` has a side where the known ground ends and what lies beyond is
// inside `region` (beyond the region nothing is a target). False on a map without clearance
// options.
bool at_frontier(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& sv, const Eigen::AlignedBox3d& region);

// Whether a supervoxel still needs a look: an ISE supervoxel, or traversable ground at the frontier.
bool needs_look(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& sv, const Eigen::AlignedBox3d& region);

}  // namespace hexplore::planning
