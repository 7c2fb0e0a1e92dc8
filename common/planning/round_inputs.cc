#include "common/planning/round_inputs.h"

#include <algorithm>
#include <stdexcept>

#include "common/core/clock.h"
#include "common/planning/mtsp/local_search.h"
#include "common/planning/robot_vertex.h"

namespace hexplore::planning {
namespace {

std::unordered_set<uint64_t> union_of(const std::vector<std::unordered_set<uint64_t>>& sets) {
  std::unordered_set<uint64_t> all;
  for (const auto& s : sets) all.insert(s.begin(), s.end());
  return all;
}

}  // namespace

void check_request(const std::string& planner, const PlanRequest& req, const TeamCapabilities& team) {
  if (!req.map) throw std::invalid_argument(planner + ": no map in the request");
  if (req.self < 0 || size_t(req.self) >= req.robots.size())
    throw std::invalid_argument(planner + ": self index " + std::to_string(req.self) + " outside the team");
  for (const auto& r : req.robots)
    if (r.species < 0 || size_t(r.species) >= team.species.size())
      throw std::invalid_argument(planner + ": robot '" + r.id + "' has unknown species index " +
                                  std::to_string(r.species));
}

std::vector<std::optional<uint64_t>> robot_vertices(const highlevel::TopologyGraph& graph,
                                                    const std::vector<RobotState>& robots,
                                                    const TeamCapabilities& team) {
  std::vector<std::optional<uint64_t>> out;
  out.reserve(robots.size());
  for (const auto& r : robots) out.push_back(robot_vertex(graph, r.position, team.graph_species_of(r.species)));
  return out;
}

// Limited to the stand region (below) and to vertices with room for the species' body (not,
// e.g., the ground seen under a vehicle: paths may pass such spots, views may not stand there).
std::vector<std::unordered_set<uint64_t>> reachable_ground(const highlevel::TopologyGraph& graph,
                                                           const std::vector<RobotState>& robots,
                                                           const std::vector<std::optional<uint64_t>>& robot_vertices,
                                                           const TeamCapabilities& team,
                                                           const Eigen::AlignedBox3d& region) {
  std::vector<std::unordered_set<uint64_t>> out(team.species.size());
  for (size_t i = 0; i < robots.size(); ++i) {
    const RobotState& r = robots[i];
    if (size_t(r.species) >= out.size()) continue;
    const int g = team.graph_species_of(r.species);
    const auto& start = robot_vertices[i];
    if (!start) continue;
    auto& set = out[size_t(r.species)];
    if (set.count(*start)) continue;  // a teammate of the same species is in the same component
    for (const auto& [key, d] : graph.distances_from(*start, g))
      if (const auto p = graph.position(key); p && region.contains(*p) && graph.room_to_stand(key, g)) set.insert(key);
  }
  return out;
}

Eigen::AlignedBox3d stand_region(const Eigen::AlignedBox3d& region, double max_range_m) {
  if (region.isEmpty() || !region.sizes().allFinite()) return region;
  const double margin = std::min(region.sizes().z(), max_range_m);
  Eigen::AlignedBox3d out = region;
  out.min().head<2>().array() -= margin;
  out.max().head<2>().array() += margin;
  return out;
}

RoundInputs prepare_round(const PlanRequest& req, const TeamCapabilities& view_team, const PlannerOptions& o,
                          bool record_targets) {
  RoundInputs in;
  const highlevel::TopologyGraph& graph = req.map->graph();
  in.robot_vertices = robot_vertices(graph, req.robots, view_team);
  in.reachable = reachable_ground(graph, req.robots, in.robot_vertices, view_team,
                                  stand_region(o.region, view_team.max_observation_range()));
  in.context = std::make_unique<MapContext>(*req.map, o, union_of(in.reachable), req.given_up);
  in.context->reachable_by_species = in.reachable;
  in.views = generate_task_views(*in.context, view_team, o, &in.stats, record_targets ? &in.targets : nullptr);
  return in;
}

StageClock::StageClock(const PlannerOptions& options)
    : cpu_(options.cpu_clock),
      start_ns_(budget_clock_ns(cpu_ ? BudgetClock::kThreadCpu : BudgetClock::kWall)),
      last_ns_(start_ns_) {}

double StageClock::lap() {
  const int64_t now = budget_clock_ns(cpu_ ? BudgetClock::kThreadCpu : BudgetClock::kWall);
  const double s = core::ns_to_s(now - last_ns_);
  last_ns_ = now;
  return s;
}

double StageClock::total() const {
  return core::ns_to_s(budget_clock_ns(cpu_ ? BudgetClock::kThreadCpu : BudgetClock::kWall) - start_ns_);
}

}  // namespace hexplore::planning
