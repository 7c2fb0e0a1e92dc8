#include "services/planning/solution_gate.h"

namespace hexplore::planning_service {

std::string SolutionGate::signature(const v1::TeamSolution& solution) {
  // Route lengths, centres and fitness change with every robot's position; what the team
  // acts on is who takes which clusters in which order.
  std::string s = solution.planner();
  for (const auto& seq : solution.sequences()) {
    s += '|';
    s += seq.robot_id();
    for (uint64_t id : seq.cluster_ids()) s.append(reinterpret_cast<const char*>(&id), sizeof id);
  }
  return s;
}

bool SolutionGate::should_send(const v1::TeamSolution& solution, bool news, double now_s) {
  std::string sig = signature(solution);
  const bool send = !sent_any_ || news || sig != sent_signature_ || now_s - sent_at_s_ >= refresh_s_;
  if (send) {
    sent_any_ = true;
    sent_at_s_ = now_s;
    sent_signature_ = std::move(sig);
  }
  return send;
}

}  // namespace hexplore::planning_service
