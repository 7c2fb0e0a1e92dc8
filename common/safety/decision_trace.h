#pragma once
// The safety service's decision trace (--trace-dir: safety-<robot>.jsonl), one JSON object per
// line: what the resolver decided, why, and where the teammates near the robot were believed to
// be. Written when a decision changes and at every decision while a teammate is near, so a
// contact in a long mission can be replayed from the trace (services/safety/README.md).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/safety/fragment.h"
#include "common/safety/resolver.h"

namespace hexplore::safety {

struct DecisionTraceOptions {
  double near_m = 3.0;  // teammates' centres this close make every decision worth a line
};

// Whether `decision` goes into the trace: it differs from `previous` (kind, reason, whom it
// waits for, detour), or a teammate's possible centre (fragment position or trail) is near.
bool worth_tracing(const Decision& decision, const Decision& previous, const Eigen::Vector3d& position,
                   const std::vector<Fragment>& peers, const DecisionTraceOptions& options = {});

// The JSON line (with its newline): time, position, decision (kind, reason, yielding_to,
// detoured, the approved path's first waypoints) and every teammate within twice near_m
// (position, stationary, speed, centre distance, trail length).
std::string decision_trace_json(double t_s, const Eigen::Vector3d& position, const Decision& decision,
                                const std::vector<Fragment>& peers, const DecisionTraceOptions& options = {});

}  // namespace hexplore::safety
