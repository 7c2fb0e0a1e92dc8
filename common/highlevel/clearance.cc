#include "common/highlevel/clearance.h"

#include <algorithm>
#include <cmath>

#include "common/core/team_config.h"
#include "common/highlevel/slopes.h"

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
  o.ground_spacing_m = team.params.eta_s_m;
  for (const auto& species : team.species) {
    o.body_height_m.push_back(2.0 * species.body_half_extents_m.z());
    o.species_level.push_back(species.traversal_level);
  }
  return o;
}

double ClearanceOptions::overhead_m(int requirement) const {
  constexpr double kMarginM = 0.2;
  double tallest = -1.0;
  for (size_t k = 0; k < body_height_m.size() && k < species_level.size(); ++k)
    if (species_level[k] >= requirement) tallest = std::max(tallest, body_height_m[k]);
  if (tallest < 0.0)  // no species may stand there (or none known): every body
    for (double h : body_height_m) tallest = std::max(tallest, h);
  return tallest < 0.0 ? above_m : tallest + kMarginM;
}

ClearanceIndex::ClearanceIndex(ClearanceOptions options, double cell_m) : options_(std::move(options)), cell_m_(cell_m) {}

uint64_t ClearanceIndex::cell_key(const Eigen::Vector3d& p) const {
  const auto x = static_cast<int32_t>(std::floor(p.x() / cell_m_));
  const auto y = static_cast<int32_t>(std::floor(p.y() / cell_m_));
  return (static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32) | static_cast<uint32_t>(y);
}

ClearanceIndex::Entry ClearanceIndex::entry_of(const Supervoxel& sv) {
  return Entry{sv.key, sv.center, sv.normal, sv.facade(), sv.traversal_requirement, sliver_of_ground(sv)};
}

ClearanceIndex::Entry ClearanceIndex::ground_at(const Eigen::Vector3d& p) {
  Entry e;
  e.center = p;
  return e;
}

void ClearanceIndex::insert(const Supervoxel& sv) {
  cells_[cell_key(sv.center)].push_back(entry_of(sv));
  invalidate_rims_near(sv.center);
}

void ClearanceIndex::erase(const Supervoxel& sv) {
  const auto it = cells_.find(cell_key(sv.center));
  if (it == cells_.end()) return;
  auto& v = it->second;
  v.erase(std::remove_if(v.begin(), v.end(), [&](const Entry& e) { return e.key == sv.key; }), v.end());
  if (v.empty()) cells_.erase(it);
  rim_cache_.erase(sv.key);
  invalidate_rims_near(sv.center);
}

double ClearanceIndex::rim_reach_m() const {
  const double step = options_.ground_spacing_m;
  return std::max(std::hypot(1.75, 0.75) * step, step + options_.facade_half_extent_m) + 1e-6;
}

void ClearanceIndex::invalidate_rims_near(const Eigen::Vector3d& p) {
  if (rim_cache_.empty()) return;
  const double reach = rim_reach_m();
  for_each_near(p, reach, [&](const Entry& e) {
    if (!e.facade && (e.center.head<2>() - p.head<2>()).norm() <= reach) rim_cache_.erase(e.key);
  });
}

uint8_t ClearanceIndex::cached_open_sides(const Entry& g) const {
  const auto it = rim_cache_.find(g.key);
  if (it != rim_cache_.end()) return it->second;
  const uint8_t open = open_sides(g);
  rim_cache_.emplace(g.key, open);
  return open;
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

bool ClearanceIndex::in_the_way(const Entry& facade, const Entry& ground) const {
  const double dz = facade.center.z() - ground.center.z();
  if (!facade.facade || dz < -options_.below_m || dz > options_.above_m) return false;
  // A surface facing down above every body that may stand here leaves room under it: the slab
  // beside B1's flight, 0.7 m over its upper treads, kept the 0.4 m tall tracked robots off the
  // flight (stop 58; the MR1000 may not use it). A ceiling's edge seen from below faces partly
  // sideways, hence the loose test.
  if (facade.normal.z() < -0.3 && dz > options_.overhead_m(ground.requirement)) return false;
  return !step_of_slope(ground.center, ground.normal, facade.center, facade.normal);
}

Eigen::Vector2d ClearanceIndex::nearest_point(const Patch& patch, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - patch.center;
  if (!patch.along.isZero()) return patch.center + std::clamp(d.dot(patch.along), -patch.half, patch.half) * patch.along;
  const double r = d.norm();
  return r <= patch.half ? p : Eigen::Vector2d(patch.center + d * (patch.half / r));
}

ClearanceIndex::Patch ClearanceIndex::facade_patch(const Entry& facade) const {
  Patch patch;
  patch.center = facade.center.head<2>();
  patch.half = options_.facade_half_extent_m;
  const Eigen::Vector2d n = facade.normal.head<2>();
  // Wall-like (normal mostly horizontal): a strip along the surface through the centre; the
  // top of something (normal mostly vertical): a disc.
  if (n.norm() > 0.5) patch.along = Eigen::Vector2d(-n.y(), n.x()).normalized();
  return patch;
}

namespace {
const Eigen::Vector2d kSides[kRimSideCount] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
}  // namespace

Eigen::Vector2d rim_side_direction(int side) { return kSides[side]; }

ClearanceIndex::SideClosure ClearanceIndex::side_closure(const Entry& g) const {
  // Sides +x, -x, +y, -y: whether ground lies beyond (a neighbour supervoxel at this level about
  // one spacing out that way; centres are voxel means, so neither exactly one spacing out nor
  // in line), and whether a wall stands there.
  const double step = options_.ground_spacing_m;
  const Eigen::Vector2d c = g.center.head<2>();
  SideClosure closure;
  for_each_near(g.center, 1.75 * step, [&](const Entry& e) {
    if (e.key == g.key) return;
    const Eigen::Vector2d off = e.center.head<2>() - c;
    const bool facade = in_the_way(e, g);
    if (!facade && (e.facade || e.sliver || std::abs(e.center.z() - g.center.z()) > options_.ground_band_m)) return;
    const Patch wall = facade ? facade_patch(e) : Patch{};
    for (int i = 0; i < kRimSideCount; ++i) {
      const uint8_t bit = uint8_t(1u << i);
      if (facade) {
        if (closure.by_wall & bit) continue;
        const Eigen::Vector2d rim_centre = c + 0.5 * step * kSides[i];
        if ((nearest_point(wall, rim_centre) - rim_centre).norm() <= 0.5 * step) closure.by_wall |= bit;
      } else {
        if (closure.by_ground & bit) continue;
        const Eigen::Vector2d along(-kSides[i].y(), kSides[i].x());
        const double out = off.dot(kSides[i]);
        if (out > 0.25 * step && out <= 1.75 * step && std::abs(off.dot(along)) <= 0.75 * step) closure.by_ground |= bit;
      }
    }
  });
  return closure;
}

uint8_t ClearanceIndex::open_sides(const Entry& g) const {
  // A wall already keeps bodies off its side; a rim there would double it.
  const SideClosure closure = side_closure(g);
  return uint8_t(~(closure.by_ground | closure.by_wall) & ((1u << kRimSideCount) - 1));
}

ClearanceIndex::RimSides ClearanceIndex::rim_sides(const Supervoxel& ground) const {
  const SideClosure closure = side_closure(entry_of(ground));
  const uint8_t all = (1u << kRimSideCount) - 1;
  return {uint8_t(~(closure.by_ground | closure.by_wall) & all), uint8_t(closure.by_wall & ~closure.by_ground)};
}

void ClearanceIndex::add_rims(const Entry& g, std::vector<Patch>& out) const {
  const double step = options_.ground_spacing_m;
  const uint8_t open = cached_open_sides(g);
  for (int i = 0; i < kRimSideCount; ++i) {
    if ((open & (1u << i)) == 0) continue;
    Patch rim;
    rim.center = g.center.head<2>() + 0.5 * step * kSides[i];
    rim.along = Eigen::Vector2d(-kSides[i].y(), kSides[i].x());
    rim.half = 0.5 * step;
    out.push_back(rim);
  }
}

std::vector<ClearanceIndex::Patch> ClearanceIndex::patches_near(const Entry& ground, double radius) const {
  const Eigen::Vector3d& p = ground.center;
  std::vector<Patch> out;
  const double reach = radius + std::max(options_.facade_half_extent_m, options_.ground_spacing_m);
  for_each_near(p, reach, [&](const Entry& e) {
    if (e.facade) {
      if (in_the_way(e, ground)) out.push_back(facade_patch(e));
    } else if (std::abs(e.center.z() - p.z()) <= options_.ground_band_m) {
      add_rims(e, out);
    }
  });
  return out;
}

double ClearanceIndex::distance(const std::vector<Patch>& patches, const Eigen::Vector2d& p, double cap) {
  double best = cap;
  for (const Patch& patch : patches) best = std::min(best, (p - nearest_point(patch, p)).norm());
  return best;
}

double ClearanceIndex::clearance(const Eigen::Vector3d& p, double search_m) const {
  return distance(patches_near(ground_at(p), search_m), p.head<2>(), search_m);
}

Eigen::Vector3d ClearanceIndex::clear_position(const Eigen::Vector3d& p, double radius) const {
  return pushed_clear(patches_near(ground_at(p), radius + options_.max_shift_m), p, radius);
}

ClearanceIndex::Measure ClearanceIndex::measure(const Supervoxel& ground, double search_m,
                                                const std::vector<double>& radii) const {
  const Eigen::Vector3d& p = ground.center;
  double reach = search_m;
  for (double r : radii) reach = std::max(reach, r + options_.max_shift_m);
  const std::vector<Patch> patches = patches_near(entry_of(ground), reach);  // the expensive part, once
  Measure m;
  m.clearance = distance(patches, p.head<2>(), search_m);
  for (double r : radii) m.waypoints.push_back(pushed_clear(patches, p, r));
  return m;
}

double ClearanceIndex::largest_radius() const {
  const auto& radii = options_.body_radius_m;
  return radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
}

double ClearanceIndex::search_m() const { return largest_radius() + 0.25; }

double ClearanceIndex::influence_m() const {
  // A supervoxel that changes at p turns the rims of ground up to hypot(1.75, 0.75) spacings
  // away on or off (add_rims' neighbour test); a rim reaches hypot(0.5, 0.5) spacings from its
  // ground's centre; a body measured there feels it from its radius plus the waypoint's shift.
  const double step = options_.ground_spacing_m;
  return std::hypot(1.75, 0.75) * step + std::hypot(0.5, 0.5) * step +
         std::max(largest_radius() + options_.max_shift_m, search_m());
}

Eigen::Vector3d ClearanceIndex::pushed_clear(const std::vector<Patch>& patches, const Eigen::Vector3d& p,
                                             double radius) const {
  const double before = distance(patches, p.head<2>(), radius);
  if (before >= radius) return p;
  // Each patch closer than the radius pushes the point away by its shortfall; pushes from
  // both sides of a corridor cancel, so the point settles between them.
  Eigen::Vector3d q = p;
  for (int iteration = 0; iteration < 4; ++iteration) {
    Eigen::Vector2d push = Eigen::Vector2d::Zero();
    for (const Patch& patch : patches) {
      const Eigen::Vector2d from = nearest_point(patch, q.head<2>());
      Eigen::Vector2d away = q.head<2>() - from;
      const double d = away.norm();
      if (d >= radius) continue;
      if (d > 1e-6) away /= d;
      else if ((q.head<2>() - patch.center).norm() > 1e-6) away = (q.head<2>() - patch.center).normalized();
      else continue;
      push += (radius - d) * away;
    }
    if (push.norm() < 1e-3) break;
    q.head<2>() += push;
    const Eigen::Vector2d shift = q.head<2>() - p.head<2>();
    if (shift.norm() > options_.max_shift_m) q.head<2>() = p.head<2>() + shift * (options_.max_shift_m / shift.norm());
  }
  return distance(patches, q.head<2>(), radius) > before + 1e-3 ? q : p;
}

std::vector<uint64_t> ClearanceIndex::ground_near(const Eigen::Vector3d& p, double radius) const {
  std::vector<uint64_t> out;
  for_each_near(p, radius, [&](const Entry& e) {
    if (!e.facade && (e.center.head<2>() - p.head<2>()).norm() <= radius) out.push_back(e.key);
  });
  return out;
}

}  // namespace hexplore::highlevel
