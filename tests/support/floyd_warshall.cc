#include "tests/support/floyd_warshall.h"

#include <limits>

namespace hexplore::highlevel {

template <typename Real>
Real AllPairs<Real>::dist(uint64_t a, uint64_t b) const {
  auto ia = index.find(a);
  auto ib = index.find(b);
  if (ia == index.end() || ib == index.end()) return std::numeric_limits<Real>::infinity();
  return distance[static_cast<size_t>(ia->second) * keys.size() + ib->second];
}

template <typename Real>
std::vector<uint64_t> AllPairs<Real>::path(uint64_t a, uint64_t b) const {
  std::vector<uint64_t> out;
  auto ia = index.find(a);
  auto ib = index.find(b);
  if (ia == index.end() || ib == index.end()) return out;
  const size_t n = keys.size();
  int at = ia->second;
  const int to = ib->second;
  if (distance[static_cast<size_t>(at) * n + to] == std::numeric_limits<Real>::infinity()) return out;
  out.push_back(keys[at]);
  while (at != to) {
    at = next[static_cast<size_t>(at) * n + to];
    out.push_back(keys[at]);
  }
  return out;
}

template <typename Real>
AllPairs<Real> floyd_warshall(const TopologyGraph& graph, int species_index) {
  AllPairs<Real> ap;
  for (uint64_t key : graph.vertex_keys())
    if (graph.passable(key, species_index)) ap.keys.push_back(key);
  const size_t n = ap.keys.size();
  for (size_t i = 0; i < n; ++i) ap.index[ap.keys[i]] = static_cast<int>(i);
  const Real inf = std::numeric_limits<Real>::infinity();
  ap.distance.assign(n * n, inf);
  ap.next.assign(n * n, -1);
  for (size_t i = 0; i < n; ++i) {
    ap.distance[i * n + i] = 0;
    ap.next[i * n + i] = static_cast<int>(i);
    for (const auto& [other, len] : graph.neighbours(ap.keys[i])) {
      auto j = ap.index.find(other);
      if (j == ap.index.end()) continue;
      ap.distance[i * n + j->second] = static_cast<Real>(len);
      ap.next[i * n + j->second] = j->second;
    }
  }
  for (size_t k = 0; k < n; ++k) {
    const Real* dk = &ap.distance[k * n];
    for (size_t i = 0; i < n; ++i) {
      const Real dik = ap.distance[i * n + k];
      if (dik == inf) continue;
      Real* di = &ap.distance[i * n];
      int* ni = &ap.next[i * n];
      const int nik = ni[k];
      for (size_t j = 0; j < n; ++j) {
        const Real cand = dik + dk[j];
        if (cand < di[j]) {
          di[j] = cand;
          ni[j] = nik;
        }
      }
    }
  }
  return ap;
}

template struct AllPairs<double>;
template struct AllPairs<float>;
template AllPairs<double> floyd_warshall<double>(const TopologyGraph&, int);
template AllPairs<float> floyd_warshall<float>(const TopologyGraph&, int);

}  // namespace hexplore::highlevel
