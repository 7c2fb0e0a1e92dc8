#include "common/planning/mtsp/mtsp_fitness.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hexplore::planning {

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 <= 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

double point_polyline_distance(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& polyline) {
  if (polyline.empty()) return 0.0;
  if (polyline.size() == 1) return (p - polyline.front()).norm();
  double best = kInfinity;
  for (size_t j = 0; j + 1 < polyline.size(); ++j)
    best = std::min(best, point_segment_distance(p, polyline[j], polyline[j + 1]));
  return best;
}

FitnessModel::FitnessModel(const MtspProblem& problem, FitnessWeights weights,
                           std::vector<std::vector<Eigen::Vector3d>> reference)
    : problem_(&problem), weights_(weights) {
  const size_t robots = problem.robots.size();
  city_ref_distance_.assign(robots, {});
  for (size_t r = 0; r < robots && r < reference.size(); ++r) {
    if (reference[r].empty()) continue;
    if (problem.positions.size() != size_t(problem.num_nodes()))
      throw std::invalid_argument("FitnessModel: a reference route needs problem.positions for every node");
    has_reference_ = true;
    const auto& line = reference[r];
    auto& d = city_ref_distance_[r];
    d.resize(size_t(problem.num_cities));
    for (int c = 0; c < problem.num_cities; ++c) {
      const Eigen::Vector3d& p = problem.positions[size_t(c)];
      auto& prefix = d[size_t(c)];
      if (line.size() == 1) {
        prefix = {(p - line.front()).norm()};
        continue;
      }
      prefix.resize(line.size() - 1);
      double best = kInfinity;
      for (size_t j = 0; j + 1 < line.size(); ++j) prefix[j] = best = std::min(best, point_segment_distance(p, line[j], line[j + 1]));
    }
  }
  has_reference_ = has_reference_ && weights_.reference != 0.0;
  decay_.resize(size_t(problem.num_cities) + 1);
  for (size_t i = 0; i < decay_.size(); ++i) decay_[i] = std::exp(-weights_.position_decay * double(i + 1));
}

double FitnessModel::reference_distance(int robot, const Route& route) const {
  if (!has_reference_) return 0.0;
  const auto& d = city_ref_distance_[size_t(robot)];
  if (d.empty()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < route.size(); ++i) {
    const auto& prefix = d[size_t(route[i])];
    const size_t last = weights_.reference_window < 0 ? prefix.size() - 1
                                                       : std::min(prefix.size() - 1, i + size_t(weights_.reference_window));
    sum += decay_[i] * prefix[last];
  }
  return sum;
}

FitnessModel::Breakdown FitnessModel::evaluate(const std::vector<Route>& routes) const {
  Breakdown b;
  b.costs.resize(routes.size());
  b.reference.resize(routes.size());
  double terms = 0.0;
  for (size_t r = 0; r < routes.size(); ++r) {
    int bad = 0;
    b.costs[r] = planning::route_cost(*problem_, int(r), routes[r], &bad);
    b.infeasible += bad;
    b.reference[r] = reference_distance(int(r), routes[r]);
    b.sum_cost += b.costs[r];
    b.max_cost = std::max(b.max_cost, b.costs[r]);
    b.reference_total += b.reference[r];
    terms += route_terms(int(r), b.costs[r], b.reference[r]);
  }
  b.fitness = combine(terms, b.max_cost);
  return b;
}

double FitnessModel::fitness(const std::vector<Route>& routes) const {
  double terms = 0.0, mx = 0.0;
  for (size_t r = 0; r < routes.size(); ++r) {
    const double c = planning::route_cost(*problem_, int(r), routes[r]);
    terms += route_terms(int(r), c, reference_distance(int(r), routes[r]));
    mx = std::max(mx, c);
  }
  return combine(terms, mx);
}

}  // namespace hexplore::planning
