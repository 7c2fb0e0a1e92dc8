#include "common/planning/vrp_instance.h"

#include <algorithm>
#include <cmath>

namespace hexplore::planning {

bool VrpInstance::eligible(int vehicle, int customer) const {
  const int c = vehicle_class[size_t(vehicle)];
  return std::isfinite(service[size_t(c)][size_t(customer)]) && std::isfinite(travel[size_t(c)](depot(vehicle), customer));
}

double vrp_route_cost(const VrpInstance& in, int vehicle, const std::vector<int>& route) {
  const int c = in.vehicle_class[size_t(vehicle)];
  double cost = 0.0;
  int prev = in.depot(vehicle);
  for (int n : route) {
    cost += in.travel[size_t(c)](prev, n) + in.service[size_t(c)][size_t(n)];
    prev = n;
  }
  return cost;
}

VrpCost vrp_cost(const VrpInstance& in, const VrpRoutes& routes) {
  VrpCost out;
  std::vector<char> placed(size_t(in.customers), 0);
  for (int v = 0; v < in.vehicles(); ++v) {
    const double c = vrp_route_cost(in, v, routes[size_t(v)]);
    if (!std::isfinite(c)) out.feasible = false;
    out.total += c;
    out.longest = std::max(out.longest, c);
    for (int n : routes[size_t(v)]) placed[size_t(n)] = 1;
  }
  for (char p : placed) out.dropped += p ? 0 : 1;
  out.objective = out.total + in.max_weight * out.longest + in.drop_penalty * out.dropped;
  return out;
}

VrpRoutes cheapest_insertion(const VrpInstance& in, VrpRoutes routes, const std::vector<int>& order) {
  const int V = in.vehicles();
  routes.resize(size_t(V));
  std::vector<char> placed(size_t(in.customers), 0);
  std::vector<double> cost(static_cast<size_t>(V));
  for (int v = 0; v < V; ++v) {
    for (int n : routes[size_t(v)]) placed[size_t(n)] = 1;
    cost[size_t(v)] = vrp_route_cost(in, v, routes[size_t(v)]);
  }
  for (int u : order) {
    if (u < 0 || u >= in.customers || placed[size_t(u)]) continue;
    int best_v = -1;
    size_t best_at = 0;
    double best_obj = kInfinity, best_add = 0.0;
    for (int v = 0; v < V; ++v) {
      if (!in.eligible(v, u)) continue;
      const int c = in.vehicle_class[size_t(v)];
      const auto& rt = routes[size_t(v)];
      const CostMatrix& t = in.travel[size_t(c)];
      double longest_other = 0.0;
      for (int w = 0; w < V; ++w)
        if (w != v) longest_other = std::max(longest_other, cost[size_t(w)]);
      const double s = in.service[size_t(c)][size_t(u)];
      for (size_t at = 0; at <= rt.size(); ++at) {
        const int prev = at == 0 ? in.depot(v) : rt[at - 1];
        double add = t(prev, u) + s;
        if (at < rt.size()) add += t(u, rt[at]) - t(prev, rt[at]);
        if (!std::isfinite(add)) continue;
        // Objective change: the route grows by `add`; the longest term may grow with it.
        const double after = cost[size_t(v)] + add;
        const double obj = add + in.max_weight * (std::max(longest_other, after) - std::max(longest_other, cost[size_t(v)]));
        if (obj < best_obj - 1e-9) best_obj = obj, best_v = v, best_at = at, best_add = add;
      }
    }
    if (best_v < 0) continue;
    auto& rt = routes[size_t(best_v)];
    rt.insert(rt.begin() + long(best_at), u);
    cost[size_t(best_v)] += best_add;
    placed[size_t(u)] = 1;
  }
  return routes;
}

}  // namespace hexplore::planning
