#pragma once
// When a teammate counts as gone. Every service that keeps a table of teammates decides it
// here, in one way: a teammate is gone once nothing was heard from it for longer than the
// time-out of that use. The uses differ in what a wrong answer costs, so each has its own
// time-out in the team file (params.liveness) and picks it explicitly:
//   planning_team_s   planning: a silent teammate leaves the team the assignment divides
//                     the work among (too short: its clusters are taken twice; too long: its
//                     work waits for a robot that is gone);
//   obstacle_s        safety: a teammate's path fragment or pose older than this no longer
//                     moves it; it stays a stopped box where it was last seen (never shorter
//                     than two radio heartbeats, eta_c, plus 0.5 s, so a teammate that
//                     only heartbeats is never dropped between beats);
//   body_filter_s     mapping: a teammate's body is cut out of this robot's scans while its
//                     pose is this fresh;
//   sim_body_s        sim: a teammate's simulated body (what the LiDARs hit) goes when its
//                     sim has been silent this long;
//   station_s         station: a robot whose planning status is older than this is not live
//                     (never shorter than two route time-outs, eta_t).
// Times are on the service's loop clock (sim time in lockstep, wall time otherwise), except
// planning's: its robot's sim time, the clock of its route time-outs (eta_t), so that a lost
// teammate's share is taken within the same number of rounds at any real-time factor.

#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include "common/core/clock.h"

namespace hexplore::core {

struct LivenessParams {
  double planning_team_s = 5.0;
  double obstacle_s = 2.5;
  double body_filter_s = 10.0;
  double sim_body_s = 2.0;
  double station_s = 10.0;
};

class Liveness {
 public:
  // Throws std::invalid_argument unless `silent_after_s` is a positive number.
  explicit Liveness(double silent_after_s) : silent_after_s_(silent_after_s) {
    if (!(silent_after_s > 0.0) || !std::isfinite(silent_after_s))
      throw std::invalid_argument("Liveness: time-out must be a positive number of seconds, got " +
                                  std::to_string(silent_after_s));
  }

  double silent_after_s() const { return silent_after_s_; }
  // Whether something heard `age_s` seconds ago still counts.
  bool fresh(double age_s) const { return age_s <= silent_after_s_; }

  // The table of teammates: `heard` records a message from `id`; `alive` says whether `id`
  // was heard within the time-out of `now_ns` (never heard: not alive).
  void heard(const std::string& id, int64_t now_ns) { heard_ns_[id] = now_ns; }
  bool alive(const std::string& id, int64_t now_ns) const {
    const auto it = heard_ns_.find(id);
    return it != heard_ns_.end() && fresh(ns_to_s(now_ns - it->second));
  }

 private:
  double silent_after_s_;
  std::map<std::string, int64_t> heard_ns_;
};

}  // namespace hexplore::core
