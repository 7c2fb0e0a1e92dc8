#pragma once
// The assignment fitness of the paper ("Fitness Function"):
//   J(h) = beta_c * sum_r cost_r + beta_m * max_r cost_r + beta_d * sum_r dist(route_r, ref_r),
// dist = sum_i e^{-beta_e * i} * (distance of the i-th city to the nearest reference segment
// among the first i + reference_window + 1 ones; every segment with window -1).
// Plain min-sum and min-max are the special weights below.

#include <vector>

#include <Eigen/Core>

#include "common/planning/mtsp/mtsp_problem.h"

namespace hexplore::planning {

struct FitnessWeights {
  double sum = 1.0;             // beta_c
  double max = 0.0;             // beta_m
  double reference = 0.0;       // beta_d
  double position_decay = 0.5;  // beta_e
  // The i-th city of a route is matched against the reference's segments 0 .. i + window:
  // following the reference costs nothing, running it backwards does. -1: every segment.
  int reference_window = -1;

  static FitnessWeights min_sum() { return {1.0, 0.0, 0.0, 0.5, -1}; }
  // Min-max with a tiny total-cost tie-break so that routes that do not set the maximum are
  // still kept short (a pure max objective has large plateaus).
  static FitnessWeights min_max() { return {1e-4, 1.0, 0.0, 0.5, -1}; }
};

// Minimum Euclidean distance from p to the segment [a, b] (the paper's L).
double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
// Minimum distance from p to a polyline (a single point counts as a degenerate segment).
double point_polyline_distance(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& polyline);

// Evaluates fitness of whole solutions and single routes. Precomputes each city's distance to
// each robot's reference polyline, so evaluation is O(route length).
class FitnessModel {
 public:
  // reference[r]: robot r's reference polyline (cluster centres of the reference solution),
  // empty = no reference term for r. Requires problem.positions when any reference is given.
  FitnessModel(const MtspProblem& problem, FitnessWeights weights,
               std::vector<std::vector<Eigen::Vector3d>> reference = {});

  const MtspProblem& problem() const { return *problem_; }
  const FitnessWeights& weights() const { return weights_; }
  bool has_reference() const { return has_reference_; }

  double route_cost(int robot, const Route& route) const { return planning::route_cost(*problem_, robot, route); }
  // Weighted reference distance of one route (0 without a reference).
  double reference_distance(int robot, const Route& route) const;
  // Contribution of one route that does not depend on the others.
  double route_terms(int robot, double cost, double ref) const { return weights_.sum * cost + weights_.reference * ref; }
  double combine(double sum_terms, double max_cost) const { return sum_terms + weights_.max * max_cost; }

  struct Breakdown {
    std::vector<double> costs;
    std::vector<double> reference;
    double sum_cost = 0.0;
    double max_cost = 0.0;
    double reference_total = 0.0;
    double fitness = 0.0;
    int infeasible = 0;  // infeasible legs or cities
  };
  Breakdown evaluate(const std::vector<Route>& routes) const;
  // Same value as evaluate().fitness without allocating (the GA's inner loop).
  double fitness(const std::vector<Route>& routes) const;

 private:
  const MtspProblem* problem_;
  FitnessWeights weights_;
  bool has_reference_ = false;
  // [robot][city][j]: distance of the city to the nearest of the reference's segments 0..j
  // (the last entry: to the whole polyline).
  std::vector<std::vector<std::vector<double>>> city_ref_distance_;
  std::vector<double> decay_;                           // e^{-beta_e * i}, i = 1..n
};

}  // namespace hexplore::planning
