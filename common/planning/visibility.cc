#include "common/planning/visibility.h"

#include <algorithm>
#include <cmath>

#include "common/planning/frontier.h"

namespace hexplore::planning {

OcclusionGrid::OcclusionGrid(const highlevel::HighLevelMap& map, double cell_m) : cell_m_(cell_m) {
  const double reach = kPlateRadiusCells * cell_m_;
  for (const auto& [key, sv] : map.supervoxels()) {
    if (!sv.facade() || sv.normal.norm() < 1e-9) continue;
    const auto index = static_cast<uint32_t>(plates_.size());
    plates_.push_back({sv.center, sv.normal.normalized()});
    // The disk's own bounding box: a wall's plate is flat across its normal, so it reaches into
    // one layer of cells there, not three.
    const Eigen::Vector3d& n = plates_.back().normal;
    const Eigen::Vector3d half = reach * (Eigen::Vector3d::Ones() - n.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
    const core::GridCell lo = core::cell_of(sv.center - half, cell_m_);
    const core::GridCell hi = core::cell_of(sv.center + half, cell_m_);
    for (int32_t x = lo.x; x <= hi.x; ++x)
      for (int32_t y = lo.y; y <= hi.y; ++y)
        for (int32_t z = lo.z; z <= hi.z; ++z) cells_[core::seed_key({x, y, z})].push_back(index);
  }
}

bool OcclusionGrid::clear(const Eigen::Vector3d& from, const highlevel::Supervoxel& target_sv) const {
  const Eigen::Vector3d& target = target_sv.center;
  const Eigen::Vector3d target_normal =
      target_sv.normal.norm() > 1e-9 ? Eigen::Vector3d(target_sv.normal.normalized()) : Eigen::Vector3d::Zero();
  const Eigen::Vector3d d = target - from;
  const double len = d.norm();
  if (len <= kTargetMarginM) return true;
  const Eigen::Vector3d u = d / len;
  const double stop = len - kTargetMarginM;
  const double reach2 = std::pow(kPlateRadiusCells * cell_m_, 2);
  auto crosses = [&](const Plate& p) {
    if (p.normal.dot(target_normal) > kOwnSurfaceCos && (p.center - target).norm() < cell_m_) return false;
    const double facing = p.normal.dot(u);
    if (std::abs(facing) < 1e-9) return false;  // the ray runs along the plate
    const double t = p.normal.dot(p.center - from) / facing;
    return t > 0.0 && t < stop && (from + u * t - p.center).squaredNorm() <= reach2;
  };
  // Visit the cells along the ray at a third of a cell: a ray cannot skip a cell it crosses by
  // more than that, and a plate is listed in every cell it reaches into.
  const double step = cell_m_ / 3.0;
  uint64_t last = ~uint64_t{0};
  for (double t = 0.0; t < stop + step; t += step) {
    const uint64_t key = core::seed_key(core::cell_of(from + u * std::min(t, stop), cell_m_));
    if (key == last) continue;
    last = key;
    const auto it = cells_.find(key);
    if (it == cells_.end()) continue;
    for (const uint32_t i : it->second)
      if (crosses(plates_[i])) return false;
  }
  return true;
}

ViewGeometry view_geometry(const Eigen::Vector3d& sensor, const Eigen::Vector3d& view_normal,
                           const Eigen::Vector3d& target, const Eigen::Vector3d& target_normal) {
  ViewGeometry g;
  const Eigen::Vector3d m = target - sensor;
  g.distance_m = m.norm();
  if (g.distance_m <= 1e-9) return g;
  const Eigen::Vector3d u = m / g.distance_m;
  // Facade normals face the side their sensors saw (perception orients them; a supervoxel
  // holds one facing), so a view behind the surface sees its back: incidence over 90 deg.
  const double tn = target_normal.norm();
  const double c = tn > 1e-9 ? -u.dot(target_normal) / tn : 1.0;
  g.incidence_rad = std::acos(std::clamp(c, -1.0, 1.0));
  const double vn = view_normal.norm();
  const double s = vn > 1e-9 ? u.dot(view_normal) / vn : u.z();
  g.elevation_rad = std::asin(std::clamp(s, -1.0, 1.0));
  return g;
}

bool angles_ok(const ViewGeometry& g, const PlannerOptions& o, double margin_deg) {
  // The target is a supervoxel, not a point: its far edge is seen at up to atan(extent / d)
  // more than its centre, and every voxel must be within gamma_th for it to be complete.
  const double spread = g.distance_m > 1e-9 ? std::atan2(o.target_half_extent_m, g.distance_m) : M_PI_2;
  const double margin = margin_deg;
  return g.incidence_rad + spread < (o.gamma_th_deg - margin) * kDegToRad &&
         g.elevation_rad >= (o.theta_l_deg + margin) * kDegToRad && g.elevation_rad <= (o.theta_u_deg - margin) * kDegToRad;
}

double ground_target_score(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& ground,
                           const highlevel::Supervoxel& target, const PlannerOptions& o) {
  if (ground.key != target.key && at_frontier(map, target, o.region)) return 0.0;
  const double d = (ground.center - target.center).norm();
  return d > o.ground_cover_radius_m ? 0.0 : 1.0 / (o.beta_l * d + 1e-3);
}

double ground_view_score(const highlevel::HighLevelMap& map, const highlevel::Supervoxel& ground,
                         const highlevel::Supervoxel& target, double range_m, const OcclusionGrid& occlusion,
                         const PlannerOptions& o, int64_t& rays) {
  if (!target.facade()) return ground_target_score(map, ground, target, o);
  const Eigen::Vector3d sensor = ground.center + ground.normal.normalized() * o.sensor_height_m;
  const ViewGeometry geo = view_geometry(sensor, ground.normal, target.center, target.normal);
  if (geo.distance_m >= range_m || !angles_ok(geo, o, o.shared_view_margin_deg)) return 0.0;
  ++rays;
  return occlusion.clear(sensor, target) ? visibility_score(geo, o) : 0.0;
}

}  // namespace hexplore::planning
