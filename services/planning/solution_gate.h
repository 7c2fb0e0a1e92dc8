#pragma once
// Whether a round's team solution goes on the radio. A robot with nothing left to do replans
// every second ("route finished" holds while its route is empty) and gets the same solution
// each time: on small-building, seed 1, the SLUGCAT planned 227 rounds, 189 of them after 97 %
// with an empty route for 136 s, and every copy was exploration-route traffic (issue 14).
// A solution is sent when its planner or any robot's cluster sequence differs from the last
// one sent, when it has given-up changes to pass on, or when `refresh_s` (eta_t) has passed
// since the last one, so that teammates still get its route lengths and round now and then.
// A solution without sequences (none worth sending: planning::RouteSharing) changes nothing
// the teammates hold of the last sequences sent, so it is compared by its planner only.

#include <cstdint>
#include <string>

#include "hexplore/v1/plan.pb.h"

namespace hexplore::planning_service {

class SolutionGate {
 public:
  explicit SolutionGate(double refresh_s) : refresh_s_(refresh_s) {}

  // Whether to send `solution` now (`news`: it carries given-up changes); a true answer counts
  // it as sent at `now_s`.
  bool should_send(const v1::TeamSolution& solution, bool news, double now_s);

 private:
  static std::string signature(const v1::TeamSolution& solution);

  double refresh_s_;
  bool sent_any_ = false;
  double sent_at_s_ = 0.0;
  std::string sent_planner_;
  std::string sent_signature_;  // of the last solution sent with sequences
};

}  // namespace hexplore::planning_service
