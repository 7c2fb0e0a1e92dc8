#pragma once
// A heterogeneous multi-depot multiple travelling salesman problem (HMDMTSP, paper
// "Problem Formulation"): cities that are public or private to one species, robots of a
// species starting at their own depot, per-species travel and execution costs (+inf where a
// capability does not match), open paths or closed routes. Independent of any map.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hexplore::planning {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr int kPublic = -1;  // city label: any species may serve it

// Dense square cost matrix stored as float (travel times and TSPLIB integer distances are
// exact or near-exact in float; sums are taken in double). Memory: 4 n^2 bytes.
class CostMatrix {
 public:
  CostMatrix() = default;
  explicit CostMatrix(int n, double fill = 0.0) : n_(n), data_(size_t(n) * size_t(n), static_cast<float>(fill)) {}
  int size() const { return n_; }
  double operator()(int i, int j) const { return data_[size_t(i) * size_t(n_) + size_t(j)]; }
  void set(int i, int j, double v) { data_[size_t(i) * size_t(n_) + size_t(j)] = static_cast<float>(v); }

 private:
  int n_ = 0;
  std::vector<float> data_;
};

enum class RouteKind { kOpen, kClosed };  // open: ends at the last city; closed: back to the depot

struct MtspRobot {
  int species = 0;
};

// Node numbering: cities are 0..num_cities-1; robot r's depot (start) is node num_cities + r.
struct MtspProblem {
  int num_cities = 0;
  int num_species = 1;
  std::vector<int> city_species;       // per city: kPublic or a species index; empty = all public
  std::vector<MtspRobot> robots;
  RouteKind kind = RouteKind::kOpen;
  // travel[s](i, j): transition cost for species s between nodes (w of the paper). One matrix
  // shared by every species, or one per species. +inf = not traversable for that species.
  std::vector<CostMatrix> travel;
  // execution[s][c]: cost of serving city c with species s (delta of the paper); empty = 0.
  std::vector<std::vector<double>> execution;
  // Node positions (cities then depots), for the reference-route distance; may be empty.
  std::vector<Eigen::Vector3d> positions;
  // Smallest number of cities per robot (0 lets a robot stay idle; the classic mTSP uses 1).
  int min_cities_per_robot = 0;

  int num_nodes() const { return num_cities + static_cast<int>(robots.size()); }
  int depot(int robot) const { return num_cities + robot; }
  int label(int city) const { return city_species.empty() ? kPublic : city_species[size_t(city)]; }
  double travel_cost(int species, int from, int to) const {
    return travel[travel.size() == 1 ? 0 : size_t(species)](from, to);
  }
  double execution_cost(int species, int city) const {
    if (execution.empty()) return 0.0;
    return execution[execution.size() == 1 ? 0 : size_t(species)][size_t(city)];
  }
  // The robot may serve the city: label matches, execution finite and reachable from its depot.
  bool eligible(int robot, int city) const;
};

// Throws std::invalid_argument naming the inconsistent field (sizes, labels, species indices,
// a city that no robot can serve).
void validate(const MtspProblem& problem);

// One robot's ordered cities.
using Route = std::vector<int>;

// Cost of one route for robot r (travel from its depot, execution of every city, and the way
// back for closed routes). Legs or cities that are infeasible add `infeasible_penalty` each
// instead of +inf so that a search can still rank infeasible candidates.
inline constexpr double kInfeasiblePenalty = 1e9;
double route_cost(const MtspProblem& problem, int robot, const Route& route, int* infeasible = nullptr);

}  // namespace hexplore::planning
