#include "common/planning/mromt_planner.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "common/planning/candidate_views.h"
#include "common/planning/graph_tour.h"
#include "common/planning/hungarian.h"
#include "common/planning/lloyd_clusters.h"
#include "common/planning/round_inputs.h"
#include "common/planning/view_costs.h"

namespace hexplore::planning {
namespace {

// Lazy greedy set cover by uncertainty: a candidate's priority is the number of still
// uncovered targets it sees (ties: larger summed visibility, then candidate order). Scores
// only fall as targets get covered, so a popped candidate whose score is still current is
// the best; accepting it covers its targets (co-visibility), and its view keeps only the
// targets it newly covers. Returns the accepted views in acceptance order.
std::vector<CandidateView> greedy_cover(const std::vector<CandidateView>& candidates) {
  std::unordered_map<uint64_t, int> index;
  std::vector<std::vector<int>> targets(candidates.size());
  for (size_t c = 0; c < candidates.size(); ++c)
    for (uint64_t t : candidates[c].view.targets) targets[c].push_back(index.try_emplace(t, int(index.size())).first->second);
  std::vector<char> covered(index.size(), 0);
  using Entry = std::tuple<int, double, int>;  // score, quality, -candidate
  std::priority_queue<Entry> queue;
  for (size_t c = 0; c < candidates.size(); ++c)
    queue.push({int(targets[c].size()), candidates[c].quality, -int(c)});
  std::vector<CandidateView> accepted;
  while (!queue.empty()) {
    const auto [score, quality, neg] = queue.top();
    queue.pop();
    const size_t c = size_t(-neg);
    int now = 0;
    for (int t : targets[c]) now += covered[size_t(t)] ? 0 : 1;
    if (now == 0) continue;
    if (now < score) {
      queue.push({now, quality, neg});
      continue;
    }
    CandidateView view = candidates[c];
    view.view.targets.clear();
    for (size_t i = 0; i < targets[c].size(); ++i)
      if (!covered[size_t(targets[c][i])]) {
        covered[size_t(targets[c][i])] = 1;
        view.view.targets.push_back(candidates[c].view.targets[i]);
      }
    accepted.push_back(std::move(view));
  }
  return accepted;
}

}  // namespace

PlanResult MromtPlanner::plan(const PlanRequest& req) {
  const PlannerContext& context = checked(req);
  const TeamCapabilities& team = context.team;
  const PlannerOptions& o = context.options;
  StageClock clock(o);

  const highlevel::TopologyGraph& graph = req.map->graph();
  const RoundInputs in = prepare_round(req, team, o);
  const std::vector<TaskView>& views = in.views;
  PlanResult out = start_result(req, in);

  // Candidate views and the priority queue: the views that cover every coverable target.
  const std::vector<CandidateView> candidates = candidate_views(*in.context, views, team, o, o.eta_r_m, in.reachable);
  int valid_task_views = 0;
  for (const auto& c : candidates) valid_task_views += c.task_view ? 1 : 0;
  out.dropped_clusters = int(views.size()) - valid_task_views;  // task views nobody may take
  std::vector<CandidateView> chosen = greedy_cover(candidates);
  out.open_views = int(chosen.size());
  out.times.views_s = clock.lap();

  // The batch of this round: the K views nearest (in travel time) to a robot that may take them.
  const size_t R = req.robots.size();
  const std::vector<std::optional<uint64_t>>& vertex = in.robot_vertices;
  std::vector<std::unordered_map<uint64_t, double>> from_robot(R);
  std::vector<double> speed(team.species.size());
  for (size_t k = 0; k < speed.size(); ++k) speed[k] = std::max(1e-6, team.species[k].speed_mps);
  for (size_t r = 0; r < R; ++r) {
    if (vertex[r]) from_robot[r] = graph.distances_from(*vertex[r], req.robots[r].species);
  }
  auto time_from = [&](size_t r, uint64_t ground) {
    const auto it = from_robot[r].find(ground);
    return it == from_robot[r].end() ? kInfinity : it->second / speed[size_t(req.robots[r].species)];
  };
  auto nearest_robot_s = [&](const CandidateView& c) {
    double best = kInfinity;
    for (size_t r = 0; r < R; ++r)
      if (c.species_mask & (1 << req.robots[r].species)) best = std::min(best, time_from(r, c.view.ground_key));
    return best;
  };
  const size_t cap = size_t(kMromtViewsPerRobot) * R;
  if (chosen.size() > cap) {
    std::vector<std::tuple<double, uint64_t, size_t>> by_distance;
    for (size_t i = 0; i < chosen.size(); ++i) by_distance.push_back({nearest_robot_s(chosen[i]), chosen[i].view.key, i});
    std::sort(by_distance.begin(), by_distance.end());
    std::vector<CandidateView> kept;
    for (size_t i = 0; i < cap; ++i) kept.push_back(std::move(chosen[std::get<2>(by_distance[i])]));
    chosen = std::move(kept);
  }
  // Key order (a total one: accepted views never share a target) for the clustering.
  std::sort(chosen.begin(), chosen.end(), [](const CandidateView& a, const CandidateView& b) {
    return std::make_tuple(a.view.key, a.view.observation_requirement, !a.task_view, a.view.targets.front()) <
           std::make_tuple(b.view.key, b.view.observation_requirement, !b.task_view, b.view.targets.front());
  });
  std::vector<TaskView> batch;
  std::vector<int> masks;
  for (const auto& c : chosen) {
    batch.push_back(c.view);
    masks.push_back(c.species_mask);
  }

  // Capability-aware Lloyd clustering, one cluster per robot to start.
  std::vector<LloydSeed> seeds;
  for (size_t r = 0; r < R; ++r)
    if (vertex[r]) seeds.push_back({req.robots[r].species, *vertex[r]});
  const std::vector<LloydCluster> clusters =
      capability_lloyd(graph, batch, masks, seeds, in.reachable, speed, LloydOptions{o.eta_r_m, 10});
  out.clusters = int(clusters.size());
  out.times.clustering_s = clock.lap();

  // Hungarian matching robot <-> cluster on travel time; a robot may take a cluster when it
  // may take every view of it. Clusters left over wait for a later round.
  std::vector<std::vector<double>> cost(R, std::vector<double>(clusters.size(), kInfinity));
  for (size_t r = 0; r < R; ++r) {
    const int k = req.robots[r].species;
    for (size_t c = 0; c < clusters.size(); ++c) {
      double nearest_member = kInfinity;
      bool all = true;
      for (int m : clusters[c].members) {
        const double t = time_from(r, batch[size_t(m)].ground_key);
        all = all && (masks[size_t(m)] & (1 << k)) && std::isfinite(t);
        nearest_member = std::min(nearest_member, t);
      }
      if (!all) continue;
      const double to_centre = time_from(r, clusters[c].centre_vertex);
      cost[r][c] = std::isfinite(to_centre) ? to_centre : nearest_member;
    }
  }
  const Assignment match = hungarian(cost);
  out.fitness = match.cost;  // the matching's total travel time, s
  out.times.assignment_s = clock.lap();

  // Each robot's cluster as an open TSP on its species' graph distance.
  out.robots.resize(R);
  for (size_t r = 0; r < R; ++r) {
    RobotPlan& plan = out.robots[r];
    plan.robot_id = req.robots[r].id;
    const int c = match.column_of_row[r];
    if (c < 0) continue;
    const LloydCluster& cl = clusters[size_t(c)];
    const int k = req.robots[r].species;
    std::vector<uint64_t> stops;
    for (int m : cl.members) stops.push_back(batch[size_t(m)].ground_key);
    const GraphTour tour = graph_tour(graph, *vertex[r], stops, k);
    plan.cluster_ids = {batch[size_t(cl.members.front())].key};
    plan.cluster_centers = {cl.centre};
    plan.route_length_m = tour.length_m;
    plan.cost_s = tour.length_m / speed[size_t(k)];
    for (int i : tour.order) plan.cost_s += observation_time_s(batch[size_t(cl.members[size_t(i)])], team.species[size_t(k)]);
    if (int(r) == req.self)
      for (int i : tour.order) plan.route.push_back(batch[size_t(cl.members[size_t(i)])]);
  }
  out.times.mnss_s = clock.lap();
  out.times.total_s = clock.total();
  return out;
}

}  // namespace hexplore::planning
