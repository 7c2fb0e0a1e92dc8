#include "common/highlevel/clearance.h"

#include <algorithm>
#include <cmath>

#include "common/core/team_config.h"

namespace hexplore::highlevel {

std::vector<double> body_radii(const core::TeamConfig& team) {
  std::vector<double> out;
  for (const auto& s : team.species) out.push_back(s.body_half_extents_m.head<2>().norm());
  return out;
}

std::vector<double> body_half_widths(const core::TeamConfig& team) {
  std::vector<double> out;
  for (const auto& s : team.species) out.push_back(s.body_half_extents_m.y());
  return out;
}

ClearanceOptions clearance_options(const core::TeamConfig& team) {
  ClearanceOptions o;
  o.body_radius_m = body_radii(team);
  o.body_half_width_m = body_half_widths(team);
  o.facade_half_extent_m = 0.5 * team.params.eta_s_m;
  return o;
}

ClearanceIndex::ClearanceIndex(ClearanceOptions options, double cell_m) : options_(std::move(options)), cell_m_(cell_m) {}

uint64_t ClearanceIndex::cell_key(const Eigen::Vector3d& p) const {
  const auto x = static_cast<int32_t>(std::floor(p.x() / cell_m_));
  const auto y = static_cast<int32_t>(std::floor(p.y() / cell_m_));
  return (static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32) | static_cast<uint32_t>(y);
}

void ClearanceIndex::insert(const Supervoxel& sv) {
  cells_[cell_key(sv.center)].push_back({sv.key, sv.center, sv.normal, sv.facade()});
}

void ClearanceIndex::erase(const Supervoxel& sv) {
  const auto it = cells_.find(cell_key(sv.center));
  if (it == cells_.end()) return;
  auto& v = it->second;
  v.erase(std::remove_if(v.begin(), v.end(), [&](const Entry& e) { return e.key == sv.key; }), v.end());
  if (v.empty()) cells_.erase(it);
}

template <typename F>
void ClearanceIndex::for_each_near(const Eigen::Vector3d& p, double radius, F&& f) const {
  const int reach = static_cast<int>(std::ceil(radius / cell_m_));
  const auto cx = static_cast<int32_t>(std::floor(p.x() / cell_m_));
  const auto cy = static_cast<int32_t>(std::floor(p.y() / cell_m_));
  for (int dx = -reach; dx <= reach; ++dx)
    for (int dy = -reach; dy <= reach; ++dy) {
      const uint64_t k = (static_cast<uint64_t>(static_cast<uint32_t>(cx + dx)) << 32) | static_cast<uint32_t>(cy + dy);
      const auto it = cells_.find(k);
      if (it == cells_.end()) continue;
      for (const Entry& e : it->second) f(e);
    }
}

bool ClearanceIndex::in_band(const Entry& facade, const Eigen::Vector3d& p) const {
  const double dz = facade.center.z() - p.z();
  return facade.facade && dz >= -options_.below_m && dz <= options_.above_m;
}

Eigen::Vector2d ClearanceIndex::nearest_point(const Entry& facade, const Eigen::Vector2d& p) const {
  const Eigen::Vector2d c = facade.center.head<2>();
  const Eigen::Vector2d d = p - c;
  const double half = options_.facade_half_extent_m;
  const Eigen::Vector2d n = facade.normal.head<2>();
  if (n.norm() > 0.5) {
    // Wall-like (normal mostly horizontal): a strip along the surface through the centre.
    const Eigen::Vector2d along = Eigen::Vector2d(-n.y(), n.x()).normalized();
    return c + std::clamp(d.dot(along), -half, half) * along;
  }
  // Top of something (normal mostly vertical): a disc.
  const double r = d.norm();
  return r <= half ? p : Eigen::Vector2d(c + d * (half / r));
}

double ClearanceIndex::clearance(const Eigen::Vector3d& p, double search_m) const {
  double best = search_m;
  for_each_near(p, search_m + options_.facade_half_extent_m, [&](const Entry& e) {
    if (in_band(e, p)) best = std::min(best, (p.head<2>() - nearest_point(e, p.head<2>())).norm());
  });
  return best;
}

Eigen::Vector3d ClearanceIndex::clear_position(const Eigen::Vector3d& p, double radius) const {
  const double before = clearance(p, radius);
  if (before >= radius) return p;
  // Each facade closer than the radius pushes the point away by its shortfall; pushes from
  // both sides of a corridor cancel, so the point settles between them.
  Eigen::Vector3d q = p;
  for (int iteration = 0; iteration < 4; ++iteration) {
    Eigen::Vector2d push = Eigen::Vector2d::Zero();
    for_each_near(q, radius + options_.facade_half_extent_m, [&](const Entry& e) {
      if (!in_band(e, p)) return;
      const Eigen::Vector2d from = nearest_point(e, q.head<2>());
      Eigen::Vector2d away = q.head<2>() - from;
      const double d = away.norm();
      if (d >= radius) return;
      if (d > 1e-6) away /= d;
      else if ((q.head<2>() - e.center.head<2>()).norm() > 1e-6) away = (q.head<2>() - e.center.head<2>()).normalized();
      else return;
      push += (radius - d) * away;
    });
    if (push.norm() < 1e-3) break;
    q.head<2>() += push;
    const Eigen::Vector2d shift = q.head<2>() - p.head<2>();
    if (shift.norm() > options_.max_shift_m) q.head<2>() = p.head<2>() + shift * (options_.max_shift_m / shift.norm());
  }
  return clearance(q, radius) > before + 1e-3 ? q : p;
}

std::vector<uint64_t> ClearanceIndex::ground_near(const Eigen::Vector3d& p, double radius) const {
  std::vector<uint64_t> out;
  for_each_near(p, radius, [&](const Entry& e) {
    if (!e.facade && (e.center.head<2>() - p.head<2>()).norm() <= radius) out.push_back(e.key);
  });
  return out;
}

}  // namespace hexplore::highlevel
