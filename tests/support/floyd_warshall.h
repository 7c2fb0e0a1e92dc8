#pragma once
// Plain all-pairs Floyd–Warshall over a TopologyGraph for one species: the paper's method,
// kept as the reference the cached-Dijkstra answers are checked against (tests, benchmark).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/highlevel/topology_graph.h"

namespace hexplore::highlevel {

template <typename Real>
struct AllPairs {
  std::vector<uint64_t> keys;                // vertex keys, ascending; index = matrix row
  std::unordered_map<uint64_t, int> index;   // key -> row
  std::vector<Real> distance;                // n * n, +inf when unreachable
  std::vector<int> next;                     // n * n successor matrix for path recovery

  Real dist(uint64_t a, uint64_t b) const;
  std::vector<uint64_t> path(uint64_t a, uint64_t b) const;
};

// O(n^3) time, O(n^2) memory; vertices the species may not enter are left unconnected.
template <typename Real>
AllPairs<Real> floyd_warshall(const TopologyGraph& graph, int species_index);

extern template struct AllPairs<double>;
extern template struct AllPairs<float>;
extern template AllPairs<double> floyd_warshall<double>(const TopologyGraph&, int);
extern template AllPairs<float> floyd_warshall<float>(const TopologyGraph&, int);

}  // namespace hexplore::highlevel
