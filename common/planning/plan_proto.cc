#include "common/planning/plan_proto.h"

#include "common/radio/vec3_proto.h"

namespace hexplore::planning {

using radio::set;
using radio::vec;

v1::TeamSolution to_proto(const PlanResult& r) {
  v1::TeamSolution out;
  out.set_round(r.round);
  out.set_planner(r.planner);
  out.set_fitness(r.fitness);
  out.set_planning_time_s(r.times.total_s);
  for (const auto& plan : r.robots) {
    auto* seq = out.add_sequences();
    seq->set_robot_id(plan.robot_id);
    for (uint64_t id : plan.cluster_ids) seq->add_cluster_ids(id);
    for (const auto& c : plan.cluster_centers) set(seq->add_cluster_centers_m(), c);
    seq->set_route_length_m(plan.route_length_m);
  }
  return out;
}

ReferenceSolution reference_from_proto(const v1::TeamSolution& s, const std::string& source_robot) {
  ReferenceSolution out;
  out.source_robot = source_robot;
  out.round = s.round();
  for (const auto& seq : s.sequences()) {
    ReferenceRoute r;
    r.robot_id = seq.robot_id();
    r.cluster_ids.assign(seq.cluster_ids().begin(), seq.cluster_ids().end());
    for (const auto& c : seq.cluster_centers_m()) r.centers.push_back(vec(c));
    r.length_m = seq.route_length_m();
    out.routes.push_back(std::move(r));
  }
  return out;
}

v1::TaskView to_proto(const TaskView& v) {
  v1::TaskView out;
  set(out.mutable_position_m(), v.position);
  out.set_ground_supervoxel(v.ground_key);
  for (uint64_t t : v.targets) out.add_target_supervoxels(t);
  set(out.mutable_look_at_m(), v.look_at);
  return out;
}

v1::ExplorationRoute route_to_proto(uint64_t round, const std::vector<TaskView>& views) {
  v1::ExplorationRoute out;
  out.set_round(round);
  for (const auto& v : views) *out.add_views() = to_proto(v);
  return out;
}

v1::ExecutablePath path_to_proto(uint64_t round, const ExecutablePlan& path, double speed_mps) {
  v1::ExecutablePath out;
  out.set_round(round);
  for (const auto& w : path.waypoints) set(out.add_waypoints_m(), w);
  *out.mutable_goal() = to_proto(path.goal);
  out.set_speed_mps(speed_mps);
  return out;
}

}  // namespace hexplore::planning
