#pragma once
// A short manoeuvre for a body the coarse path has wedged: the straight line to the next
// waypoint clips a door jamb, or there is no room to turn where it stands (office scene,
// seed 1: the SLUGCAT stood at a room's door for 300 s, blocked on every path out). A
// robot's local planner finds its way with its costmap; this one searches the ground truth
// the same way every move is checked: Hybrid A* over positions (0.1 m cells, continuous
// within them) and headings (32 per turn), with straight moves forwards and backwards and
// turns in place as the actions, each checked by the TerrainProbe like any move, and kept
// clear of teammates' bodies (a local planner's costmap has them; the safety layer's detours
// are not followed while the body manoeuvres). Used by RobotMotion only when a move or a turn
// is refused, so free driving costs nothing.

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "common/sim/proxy_box.h"
#include "common/sim/terrain_probe.h"

namespace hexplore::sim {

struct ManeuverOptions {
  double cell_m = 0.1;             // lattice cell, and the length of one move
  int headings = 32;               // heading lattice per full turn (11.25 deg: a body 0.2-0.3 m
                                   // narrower than a door passes it within half a step)
  double reach_m = 0.08;           // the goal counts as reached this close
  double window_m = 2.0;           // search no farther than this around start and goal
  double max_goal_m = 3.0;         // a goal farther away is planned for through the point this
                                   // far along the straight line to it (the path takes the body on)
  int max_expansions = 8000;       // then give up (the body is blocked): about 0.3 s
  double reverse_cost = 1.5;       // per metre backwards, against 1 forwards
  double turn_cost_m = 0.05;       // per heading step, in metres of driving
  double teammate_margin_m = 0.15; // the body, grown by this, never overlaps a teammate's
};

// The body of `probe`'s species at `pose`, grown by `margin_m` on every side.
ProxyBox body_box_at(const TerrainProbe& probe, const Footprint& pose, double margin_m = 0.0);

// The poses, from the first after `from` to one within reach of `goal` (or of its stand-in
// max_goal_m along the way when it is farther), each one move or one turn away from the
// previous (so each can be driven as it stands); nullopt when no manoeuvre within the window
// reaches it.
std::optional<std::vector<Footprint>> plan_maneuver(const TerrainProbe& probe, const Footprint& from,
                                                    const Eigen::Vector2d& far_goal, std::span<const ProxyBox> teammates,
                                                    const ManeuverOptions& options = {});

}  // namespace hexplore::sim
