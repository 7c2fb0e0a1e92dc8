#include "common/planning/vrp_search.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "common/core/clock.h"
#include "common/core/rng.h"

namespace hexplore::planning {
namespace {

// An impassable leg or impossible service inside sums: large enough that no real route
// comes near it, small enough that prefix-sum differences stay exact to well below a second.
constexpr double kBig = 1e9;
constexpr double kEps = 1e-7;

double finite_or_big(double v) { return std::isfinite(v) ? v : kBig; }

// Positions [i, j] (inclusive) of one current route, possibly reversed; empty when i > j.
// A segment starting at 0 holds the depot and is never reversed.
struct Seg {
  int route = 0;
  int i = 0;
  int j = -1;
  bool rev = false;
};

class Search {
 public:
  Search(const VrpInstance& in, const VrpRoutes& start, const GlsOptions& o)
      : in_(in), o_(o), N_(in.customers), V_(in.vehicles()), C_(int(in.travel.size())) {
    class_used_.assign(size_t(C_), 0);
    for (int c : in.vehicle_class) class_used_[size_t(c)] = 1;
    routes_.resize(size_t(V_));
    route_of_.assign(size_t(N_), -1);
    pos_of_.assign(size_t(N_), -1);
    for (int v = 0; v < V_; ++v) {
      routes_[size_t(v)].seq.push_back(in.depot(v));
      for (int c : start[size_t(v)]) routes_[size_t(v)].seq.push_back(c);
      refresh(v);
    }
    for (int c = 0; c < N_; ++c) dropped_ += route_of_[size_t(c)] < 0 ? 1 : 0;
    recompute_objective();
    seen_.assign(size_t(N_), 0);
    active_.assign(size_t(N_), 0);
    build_neighbours();
  }

  GlsResult run() {
    GlsResult out;
    start_ns_ = budget_clock_ns(o_.clock);
    deadline_ns_ = o_.time_budget_s > 0 ? start_ns_ + int64_t(o_.time_budget_s * 1e9) : 0;
    out.start_cost = cost_now();
    best_ = snapshot();
    best_obj_ = objective_;
    current_is_best_ = true;

    std::vector<int> order;
    for (int c = 0; c < N_; ++c)
      if (route_of_[size_t(c)] >= 0) order.push_back(c);
    core::PlanRng rng(o_.seed);
    rng.shuffle(order);
    for (int c : order) activate(c);

    int64_t evaluations_at_optimum = -1;
    while (!out_of_budget()) {
      if (queue_.empty()) {
        ++out.local_optima;
        // Nothing to penalise, or no move could even be scored since the last local optimum
        // (e.g. one customer): the search cannot go anywhere else.
        if (evaluations_ == evaluations_at_optimum || !penalise()) break;
        evaluations_at_optimum = evaluations_;
        continue;
      }
      const int u = queue_.front();
      queue_.pop_front();
      active_[size_t(u)] = 0;
      if (route_of_[size_t(u)] < 0) continue;
      if (improve(u)) {
        ++out.moves;
        activate(u);
      }
    }
    if (current_is_best_ && objective_ < best_obj_ + tolerance()) best_ = snapshot();
    out.routes.resize(size_t(V_));
    for (int v = 0; v < V_; ++v) out.routes[size_t(v)].assign(best_[size_t(v)].begin() + 1, best_[size_t(v)].end());
    out.cost = vrp_cost(in_, out.routes);
    out.evaluations = evaluations_;
    out.elapsed_s = core::ns_to_s(budget_clock_ns(o_.clock) - start_ns_);
    return out;
  }

 private:
  struct Route {
    std::vector<int> seq;                    // depot first
    std::vector<std::vector<double>> fw, bw; // [class][t]: travel of seq[1..t] forward / backward
    std::vector<std::vector<double>> sv;     // [class][t]: service of seq[1..t]
    std::vector<double> pen;                 // [t]: penalty count of the arcs up to seq[t]
    double cost = 0.0;
  };

  double arc(int cls, int a, int b) const { return finite_or_big(in_.travel[size_t(cls)](a, b)); }
  double svc(int cls, int node) const {
    return node < N_ ? finite_or_big(in_.service[size_t(cls)][size_t(node)]) : 0.0;
  }
  int cls(int route) const { return in_.vehicle_class[size_t(route)]; }
  static uint64_t arc_key(int a, int b) {
    const auto lo = uint64_t(std::min(a, b)), hi = uint64_t(std::max(a, b));
    return (lo << 32) | hi;
  }
  double penalty(int a, int b) const {
    if (penalties_.empty()) return 0.0;
    const auto it = penalties_.find(arc_key(a, b));
    return it == penalties_.end() ? 0.0 : double(it->second);
  }

  void refresh(int r) {
    Route& rt = routes_[size_t(r)];
    const int m = int(rt.seq.size()) - 1;
    rt.fw.assign(size_t(C_), {});
    rt.bw.assign(size_t(C_), {});
    rt.sv.assign(size_t(C_), {});
    for (int c = 0; c < C_; ++c) {
      if (!class_used_[size_t(c)]) continue;
      auto& fw = rt.fw[size_t(c)];
      auto& bw = rt.bw[size_t(c)];
      auto& sv = rt.sv[size_t(c)];
      fw.assign(size_t(m) + 1, 0.0);
      bw.assign(size_t(m) + 1, 0.0);
      sv.assign(size_t(m) + 1, 0.0);
      for (int t = 1; t <= m; ++t) {
        sv[size_t(t)] = sv[size_t(t - 1)] + svc(c, rt.seq[size_t(t)]);
        if (t >= 2) {
          fw[size_t(t)] = fw[size_t(t - 1)] + arc(c, rt.seq[size_t(t - 1)], rt.seq[size_t(t)]);
          bw[size_t(t)] = bw[size_t(t - 1)] + arc(c, rt.seq[size_t(t)], rt.seq[size_t(t - 1)]);
        }
      }
    }
    refresh_penalties(r);
    const int k = cls(r);
    rt.cost = m >= 1 ? arc(k, rt.seq[0], rt.seq[1]) + rt.fw[size_t(k)][size_t(m)] + rt.sv[size_t(k)][size_t(m)] : 0.0;
    for (int t = 1; t <= m; ++t) {
      route_of_[size_t(rt.seq[size_t(t)])] = r;
      pos_of_[size_t(rt.seq[size_t(t)])] = t;
    }
  }

  void refresh_penalties(int r) {
    Route& rt = routes_[size_t(r)];
    rt.pen.assign(rt.seq.size(), 0.0);
    for (size_t t = 1; t < rt.seq.size(); ++t) rt.pen[t] = rt.pen[t - 1] + penalty(rt.seq[t - 1], rt.seq[t]);
  }

  // The search never drops or adds a customer, so dropped_ is fixed at construction.
  void recompute_objective() {
    double longest = 0.0;
    total_ = 0.0;
    for (const auto& rt : routes_) {
      longest = std::max(longest, rt.cost);
      total_ += rt.cost;
    }
    objective_ = total_ + in_.max_weight * longest + in_.drop_penalty * dropped_;
  }
  // Improvements smaller than this are rounding, not progress.
  double tolerance() const { return 1e-9 * (objective_ - in_.drop_penalty * dropped_) + 1e-9; }

  VrpCost cost_now() const {
    VrpRoutes r(static_cast<size_t>(V_));
    for (int v = 0; v < V_; ++v) r[size_t(v)].assign(routes_[size_t(v)].seq.begin() + 1, routes_[size_t(v)].seq.end());
    return vrp_cost(in_, r);
  }

  std::vector<std::vector<int>> snapshot() const {
    std::vector<std::vector<int>> s(static_cast<size_t>(V_));
    for (int v = 0; v < V_; ++v) s[size_t(v)] = routes_[size_t(v)].seq;
    return s;
  }

  void build_neighbours() {
    const int K = std::max(1, o_.neighbours);
    neighbours_.assign(size_t(C_), {});
    std::vector<std::pair<double, int>> cand;
    for (int c = 0; c < C_; ++c) {
      if (!class_used_[size_t(c)]) continue;
      auto& lists = neighbours_[size_t(c)];
      lists.assign(size_t(N_), {});
      for (int u = 0; u < N_; ++u) {
        if (!std::isfinite(in_.service[size_t(c)][size_t(u)])) continue;
        cand.clear();
        for (int v = 0; v < N_; ++v) {
          if (v == u || !std::isfinite(in_.service[size_t(c)][size_t(v)])) continue;
          const double d = in_.travel[size_t(c)](u, v);
          if (std::isfinite(d)) cand.push_back({d, v});
        }
        const size_t keep = std::min(cand.size(), size_t(K));
        std::partial_sort(cand.begin(), cand.begin() + long(keep), cand.end());
        for (size_t i = 0; i < keep; ++i) lists[size_t(u)].push_back(cand[i].second);
      }
    }
  }

  // --- segments -------------------------------------------------------------------------

  int first_node(const Seg& s) const { return routes_[size_t(s.route)].seq[size_t(s.rev ? s.j : s.i)]; }
  int last_node(const Seg& s) const { return routes_[size_t(s.route)].seq[size_t(s.rev ? s.i : s.j)]; }

  double internal(const Seg& s, int c) const {
    const Route& rt = routes_[size_t(s.route)];
    double travel;
    if (s.i == 0) travel = s.j >= 1 ? arc(c, rt.seq[0], rt.seq[1]) + rt.fw[size_t(c)][size_t(s.j)] - rt.fw[size_t(c)][1] : 0.0;
    else if (s.rev) travel = rt.bw[size_t(c)][size_t(s.j)] - rt.bw[size_t(c)][size_t(s.i)];
    else travel = rt.fw[size_t(c)][size_t(s.j)] - rt.fw[size_t(c)][size_t(s.i)];
    return travel + rt.sv[size_t(c)][size_t(s.j)] - (s.i >= 1 ? rt.sv[size_t(c)][size_t(s.i - 1)] : 0.0);
  }

  // Cost and penalty count of a route made of these segments, driven by class c.
  void compose(int c, const Seg* segs, int n, double& cost, double& pen) const {
    cost = 0.0;
    pen = 0.0;
    int prev = -1;
    for (int k = 0; k < n; ++k) {
      const Seg& s = segs[k];
      if (s.i > s.j) continue;
      const int f = first_node(s);
      if (prev >= 0) {
        cost += arc(c, prev, f);
        pen += penalty(prev, f);
      }
      cost += internal(s, c);
      const Route& rt = routes_[size_t(s.route)];
      pen += rt.pen[size_t(s.j)] - rt.pen[size_t(s.i)];
      prev = last_node(s);
    }
  }

  // Scores the move that rebuilds route a (and b, when b >= 0 and b != a) from segments;
  // applies it when it lowers the augmented objective. True when applied.
  bool attempt(int a, std::initializer_list<Seg> sa, int b, std::initializer_list<Seg> sb) {
    if (o_.max_evaluations > 0 && evaluations_ >= o_.max_evaluations) return false;
    ++evaluations_;
    double ca, pa, cb = 0.0, pb = 0.0;
    compose(cls(a), sa.begin(), int(sa.size()), ca, pa);
    const bool two = b >= 0 && b != a;
    if (two) compose(cls(b), sb.begin(), int(sb.size()), cb, pb);
    double total = total_ - routes_[size_t(a)].cost + ca;
    double longest = ca;
    double old_pen = routes_[size_t(a)].pen.back();
    if (two) {
      total += cb - routes_[size_t(b)].cost;
      longest = std::max(longest, cb);
      old_pen += routes_[size_t(b)].pen.back();
    }
    for (int r = 0; r < V_; ++r)
      if (r != a && !(two && r == b)) longest = std::max(longest, routes_[size_t(r)].cost);
    const double objective = total + in_.max_weight * longest + in_.drop_penalty * dropped_;
    const double delta = objective - objective_ + lambda_ * (pa + pb - old_pen);
    if (delta >= -tolerance()) return false;
    if (objective > objective_ + tolerance() && current_is_best_) {
      best_ = snapshot();  // leaving the best solution met so far
      best_obj_ = objective_;
      current_is_best_ = false;
    }
    // Endpoints of the changed arcs get another look (named before the routes change).
    int ends[16];
    int n_ends = 0;
    for (const Seg& s : sa)
      if (s.i <= s.j && n_ends + 2 <= 16) ends[n_ends++] = first_node(s), ends[n_ends++] = last_node(s);
    if (two)
      for (const Seg& s : sb)
        if (s.i <= s.j && n_ends + 2 <= 16) ends[n_ends++] = first_node(s), ends[n_ends++] = last_node(s);
    std::vector<int> na = materialise(sa), nb;
    if (two) nb = materialise(sb);
    routes_[size_t(a)].seq = std::move(na);
    if (two) routes_[size_t(b)].seq = std::move(nb);
    refresh(a);
    if (two) refresh(b);
    recompute_objective();
    if (objective_ < best_obj_ - tolerance()) {
      best_obj_ = objective_;
      current_is_best_ = true;
    } else if (objective_ > best_obj_ + tolerance()) {
      current_is_best_ = false;
    }
    for (int k = 0; k < n_ends; ++k) activate(ends[k]);
    return true;
  }

  std::vector<int> materialise(std::initializer_list<Seg> segs) const {
    std::vector<int> out;
    for (const Seg& s : segs) {
      if (s.i > s.j) continue;
      const auto& seq = routes_[size_t(s.route)].seq;
      if (s.rev)
        for (int t = s.j; t >= s.i; --t) out.push_back(seq[size_t(t)]);
      else
        out.insert(out.end(), seq.begin() + s.i, seq.begin() + s.j + 1);
    }
    return out;
  }

  void activate(int node) {
    if (node < 0 || node >= N_ || active_[size_t(node)]) return;
    active_[size_t(node)] = 1;
    queue_.push_back(node);
  }

  // --- moves ----------------------------------------------------------------------------

  // Moves the segment [p, p+len-1] of route A (reversed or not) to after position q of route B.
  bool or_opt(int A, int p, int len, bool rev, int B, int q) {
    const int mA = int(routes_[size_t(A)].seq.size()) - 1;
    const int e = p + len - 1;
    if (p < 1 || e > mA) return false;
    const Seg seg{A, p, e, rev};
    if (A != B) {
      const int mB = int(routes_[size_t(B)].seq.size()) - 1;
      return attempt(A, {Seg{A, 0, p - 1}, Seg{A, e + 1, mA}}, B, {Seg{B, 0, q}, seg, Seg{B, q + 1, mB}});
    }
    if (q >= p - 1 && q <= e) return false;
    if (q < p - 1) return attempt(A, {Seg{A, 0, q}, seg, Seg{A, q + 1, p - 1}, Seg{A, e + 1, mA}}, -1, {});
    return attempt(A, {Seg{A, 0, p - 1}, Seg{A, e + 1, q}, seg, Seg{A, q + 1, mA}}, -1, {});
  }

  bool exchange(int A, int p, int B, int q) {
    const int mA = int(routes_[size_t(A)].seq.size()) - 1;
    if (A != B) {
      const int mB = int(routes_[size_t(B)].seq.size()) - 1;
      return attempt(A, {Seg{A, 0, p - 1}, Seg{B, q, q}, Seg{A, p + 1, mA}}, B,
                     {Seg{B, 0, q - 1}, Seg{A, p, p}, Seg{B, q + 1, mB}});
    }
    const int i = std::min(p, q), j = std::max(p, q);
    if (i == j) return false;
    if (j == i + 1) return attempt(A, {Seg{A, 0, i - 1}, Seg{A, j, j}, Seg{A, i, i}, Seg{A, j + 1, mA}}, -1, {});
    return attempt(A, {Seg{A, 0, i - 1}, Seg{A, j, j}, Seg{A, i + 1, j - 1}, Seg{A, i, i}, Seg{A, j + 1, mA}}, -1, {});
  }

  // Same route: reverses the part between u and v so that they become neighbours.
  bool two_opt(int A, int p, int q) {
    const int m = int(routes_[size_t(A)].seq.size()) - 1;
    if (p < q) {
      if (q == p + 1) return false;
      return attempt(A, {Seg{A, 0, p}, Seg{A, p + 1, q, true}, Seg{A, q + 1, m}}, -1, {});
    }
    if (p == q + 1 || p == q) return false;
    return attempt(A, {Seg{A, 0, q}, Seg{A, q + 1, p, true}, Seg{A, p + 1, m}}, -1, {});
  }

  // Different routes: swaps their tails so that u is followed by v (or v by u).
  bool two_opt_star(int A, int p, int B, int q) {
    const int mA = int(routes_[size_t(A)].seq.size()) - 1, mB = int(routes_[size_t(B)].seq.size()) - 1;
    if (attempt(A, {Seg{A, 0, p}, Seg{B, q, mB}}, B, {Seg{B, 0, q - 1}, Seg{A, p + 1, mA}})) return true;
    return attempt(B, {Seg{B, 0, q}, Seg{A, p, mA}}, A, {Seg{A, 0, p - 1}, Seg{B, q + 1, mB}});
  }

  // First improving move around customer u; true when one was applied.
  bool improve(int u) {
    const int A = route_of_[size_t(u)];
    const int mA = int(routes_[size_t(A)].seq.size()) - 1;
    ++stamp_;
    seen_[size_t(u)] = stamp_;
    for (int c = 0; c < C_; ++c) {
      if (!class_used_[size_t(c)] || neighbours_[size_t(c)][size_t(u)].empty()) continue;
      for (int v : neighbours_[size_t(c)][size_t(u)]) {
        if (seen_[size_t(v)] == stamp_) continue;
        const int B = route_of_[size_t(v)];
        if (B < 0 || (cls(B) != c && cls(A) != c)) continue;
        seen_[size_t(v)] = stamp_;
        if (out_of_budget()) return false;
        const int p = pos_of_[size_t(u)], q = pos_of_[size_t(v)];
        // u (or a segment starting at u) after v, or before v.
        for (int len = 1; len <= 3 && p + len - 1 <= mA; ++len)
          for (bool rev : {false, true}) {
            if (rev && len == 1) continue;
            if (or_opt(A, p, len, rev, B, q) || or_opt(A, p, len, rev, B, q - 1)) return true;
          }
        if (exchange(A, p, B, q)) return true;
        if (A == B ? two_opt(A, p, q) : two_opt_star(A, p, B, q)) return true;
      }
    }
    // u at the front of any route (the depot is nobody's neighbour in the lists).
    for (int B = 0; B < V_; ++B) {
      if (out_of_budget()) return false;
      if (in_.eligible(B, u) && or_opt(A, pos_of_[size_t(u)], 1, false, B, 0)) return true;
    }
    return false;
  }

  // GLS at a local optimum: penalise the arcs of largest utility cost / (1 + penalty).
  bool penalise() {
    if (lambda_ == 0.0) {
      double travel = 0.0;
      int arcs = 0;
      for (int r = 0; r < V_; ++r) {
        const auto& seq = routes_[size_t(r)].seq;
        for (size_t t = 1; t < seq.size(); ++t) {
          const double c = arc(cls(r), seq[t - 1], seq[t]);
          if (c >= kBig / 2) continue;  // an impassable start placement says nothing of the scale
          travel += c;
          ++arcs;
        }
      }
      if (arcs == 0 || travel <= 0.0) return false;
      lambda_ = o_.lambda_coefficient * travel / arcs;
    }
    double best = -1.0;
    std::vector<std::pair<int, int>> chosen;
    for (int r = 0; r < V_; ++r) {
      const auto& seq = routes_[size_t(r)].seq;
      for (size_t t = 1; t < seq.size(); ++t) {
        const double c = std::min(arc(cls(r), seq[t - 1], seq[t]), kBig / 2);
        const double util = c / (1.0 + penalty(seq[t - 1], seq[t]));
        if (util > best + kEps) {
          best = util;
          chosen.assign(1, {seq[t - 1], seq[t]});
        } else if (util > best - kEps) {
          chosen.push_back({seq[t - 1], seq[t]});
        }
      }
    }
    if (chosen.empty()) return false;
    for (const auto& [a, b] : chosen) {
      ++penalties_[arc_key(a, b)];
      activate(a);
      activate(b);
    }
    for (int r = 0; r < V_; ++r) refresh_penalties(r);
    return true;
  }

  bool out_of_budget() {
    if (o_.max_evaluations > 0 && evaluations_ >= o_.max_evaluations) return true;
    if (deadline_ns_ != 0 && (++checks_ & 127) == 0 && budget_clock_ns(o_.clock) > deadline_ns_) expired_ = true;
    if (expired_) return true;
    // Neither budget: a plain local search, ending at the first local optimum.
    return o_.max_evaluations <= 0 && deadline_ns_ == 0 && lambda_ != 0.0;
  }

  const VrpInstance& in_;
  const GlsOptions& o_;
  const int N_, V_, C_;
  std::vector<char> class_used_;
  std::vector<Route> routes_;
  std::vector<int> route_of_, pos_of_;
  std::vector<std::vector<std::vector<int>>> neighbours_;  // [class][customer]
  std::unordered_map<uint64_t, int> penalties_;
  double lambda_ = 0.0;
  double total_ = 0.0;
  double objective_ = 0.0;
  int dropped_ = 0;
  std::vector<std::vector<int>> best_;
  double best_obj_ = 0.0;
  bool current_is_best_ = true;
  std::deque<int> queue_;
  std::vector<char> active_;
  std::vector<int> seen_;
  int stamp_ = 0;
  int64_t evaluations_ = 0;
  int64_t checks_ = 0;
  int64_t start_ns_ = 0, deadline_ns_ = 0;
  bool expired_ = false;
};

}  // namespace

GlsResult guided_local_search(const VrpInstance& in, const VrpRoutes& start, const GlsOptions& o) {
  if (int(start.size()) != in.vehicles())
    throw std::invalid_argument("guided_local_search: " + std::to_string(start.size()) + " routes for " +
                                std::to_string(in.vehicles()) + " vehicles");
  if (in.travel.size() != in.service.size())
    throw std::invalid_argument("guided_local_search: travel and service have different class counts");
  for (int c : in.vehicle_class)
    if (c < 0 || size_t(c) >= in.travel.size() || in.travel[size_t(c)].size() != in.customers + in.vehicles() ||
        int(in.service[size_t(c)].size()) != in.customers)
      throw std::invalid_argument("guided_local_search: vehicle class " + std::to_string(c) + " has no matrix of size " +
                                  std::to_string(in.customers + in.vehicles()));
  std::vector<char> seen(size_t(in.customers), 0);
  for (const auto& r : start)
    for (int n : r) {
      if (n < 0 || n >= in.customers) throw std::invalid_argument("guided_local_search: customer " + std::to_string(n) + " out of range");
      if (seen[size_t(n)]++) throw std::invalid_argument("guided_local_search: customer " + std::to_string(n) + " placed twice");
    }
  Search search(in, start, o);
  return search.run();
}

}  // namespace hexplore::planning
