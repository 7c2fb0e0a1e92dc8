#include "common/sim/local_maneuver.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

namespace hexplore::sim {
namespace {

struct Node {
  Footprint pose;
  int heading = 0;  // steps of 2 pi / headings from the start's yaw
  double cost = 0.0;
  int parent = -1;
};

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

}  // namespace

ProxyBox body_box_at(const TerrainProbe& probe, const Footprint& pose, double margin_m) {
  const Eigen::Isometry3d p = probe.body_pose(pose);
  ProxyBox b;
  b.center = p.translation();
  b.orientation = Eigen::Quaterniond(p.linear());
  b.half_extents = probe.species().body_half_extents_m + Eigen::Vector3d::Constant(margin_m);
  return b;
}

std::optional<std::vector<Footprint>> plan_maneuver(const TerrainProbe& probe, const Footprint& from,
                                                    const Eigen::Vector2d& far_goal, std::span<const ProxyBox> teammates,
                                                    const ManeuverOptions& options) {
  // A far waypoint is made for through a stand-in on the way: what wedges a body is where it
  // stands (on the edge of the ground plane, a wheeled body parallel to the rim cannot turn in
  // place, yet a few small turns and moves take it inwards), and the path takes it on from
  // there (before, a far goal was not planned for and the body reported BLOCKED).
  const double far = (far_goal - from.xy).norm();
  const Eigen::Vector2d goal =
      far > options.max_goal_m ? Eigen::Vector2d(from.xy + (far_goal - from.xy) * (options.max_goal_m / far)) : far_goal;
  auto clear_of_teammates = [&](const Footprint& pose) {
    const ProxyBox body = body_box_at(probe, pose, options.teammate_margin_m);
    for (const ProxyBox& mate : teammates)
      if (boxes_overlap(body, mate)) return false;
    return true;
  };
  const double step_rad = 2.0 * M_PI / options.headings;
  Eigen::AlignedBox2d window(from.xy.cwiseMin(goal), from.xy.cwiseMax(goal));
  window.min().array() -= options.window_m;
  window.max().array() += options.window_m;

  // Cells and headings relative to the start, so the start lies on the lattice.
  auto key = [&](const Eigen::Vector2d& xy, int heading) {
    const auto ix = static_cast<int64_t>(std::lround((xy.x() - from.xy.x()) / options.cell_m));
    const auto iy = static_cast<int64_t>(std::lround((xy.y() - from.xy.y()) / options.cell_m));
    const int k = ((heading % options.headings) + options.headings) % options.headings;
    return (static_cast<uint64_t>(ix & 0xFFFFF) << 40) | (static_cast<uint64_t>(iy & 0xFFFFF) << 20) |
           static_cast<uint64_t>(k);
  };
  auto estimate = [&](const Eigen::Vector2d& xy) { return (goal - xy).norm(); };

  std::vector<Node> nodes;
  std::unordered_map<uint64_t, double> best;
  using Entry = std::pair<double, int>;  // cost + estimate, node index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  nodes.push_back({from, 0, 0.0, -1});
  best[key(from.xy, 0)] = 0.0;
  open.push({estimate(from.xy), 0});

  auto add = [&](int parent, const Footprint& pose, int heading, double step_cost) {
    if (!clear_of_teammates(pose)) return;
    const double cost = nodes[size_t(parent)].cost + step_cost;
    const uint64_t k = key(pose.xy, heading);
    const auto it = best.find(k);
    if (it != best.end() && it->second <= cost + 1e-9) return;
    best[k] = cost;
    nodes.push_back({pose, heading, cost, parent});
    open.push({cost + estimate(pose.xy), static_cast<int>(nodes.size() - 1)});
  };

  for (int expansions = 0; !open.empty() && expansions < options.max_expansions;) {
    const int at = open.top().second;
    open.pop();
    const Node node = nodes[size_t(at)];  // a copy: add() grows the vector
    if (node.cost > best[key(node.pose.xy, node.heading)] + 1e-9) continue;  // a better way was found since
    if ((node.pose.xy - goal).norm() <= options.reach_m) {
      std::vector<Footprint> poses;
      for (int i = at; nodes[size_t(i)].parent >= 0; i = nodes[size_t(i)].parent) poses.push_back(nodes[size_t(i)].pose);
      return std::vector<Footprint>(poses.rbegin(), poses.rend());
    }
    ++expansions;
    const Footprint& pose = node.pose;
    const Eigen::Vector2d ahead(std::cos(pose.yaw), std::sin(pose.yaw));
    for (const double direction : {1.0, -1.0}) {
      const Eigen::Vector2d xy = pose.xy + direction * options.cell_m * ahead;
      if (!window.contains(xy)) continue;
      const auto next = probe.footprint(xy, pose.yaw, pose.heights);
      if (!next || probe.check(*next, &pose, direction > 0 ? Travel::kForward : Travel::kBackward) != TerrainVerdict::kOk)
        continue;
      add(at, *next, node.heading, options.cell_m * (direction > 0 ? 1.0 : options.reverse_cost));
    }
    for (const int turn : {1, -1}) {
      const int heading = node.heading + turn;
      const auto turned = probe.turn(pose, wrap(from.yaw + heading * step_rad));
      if (turned) add(at, *turned, heading, options.turn_cost_m);
    }
  }
  return std::nullopt;
}

}  // namespace hexplore::sim
