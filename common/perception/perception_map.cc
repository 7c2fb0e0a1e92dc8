#include "common/perception/perception_map.h"

#include <algorithm>
#include <cmath>

namespace hexplore::perception {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr uint32_t kMaxVoxelCount = 1u << 15;

// Spreads the 16 bits of v to every third bit of a 48-bit word.
uint64_t spread3(uint64_t v) {
  v &= 0xFFFF;
  v = (v | (v << 16)) & 0x0000FF0000FFull;
  v = (v | (v << 8)) & 0x00F00F00F00Full;
  v = (v | (v << 4)) & 0x0C30C30C30C3ull;
  v = (v | (v << 2)) & 0x249249249249ull;
  return v;
}

// Morton (Z-order) code of a key: sorting by it keeps neighbours close in processing order.
uint64_t morton(const octomap::OcTreeKey& k) { return spread3(k[0]) | (spread3(k[1]) << 1) | (spread3(k[2]) << 2); }

}  // namespace

PerceptionMap::PerceptionMap(MapParams params)
    : params_((params.validate(), std::move(params))), window_(TerrainWindow::from(params_)), tree_(params_.resolution_m) {}

Eigen::Vector3d PerceptionMap::centre_of(const octomap::OcTreeKey& key) const {
  const double r = params_.resolution_m;
  return {(static_cast<int>(key[0]) - kOctreeKeyOffset + 0.5) * r, (static_cast<int>(key[1]) - kOctreeKeyOffset + 0.5) * r,
          (static_cast<int>(key[2]) - kOctreeKeyOffset + 0.5) * r};
}

Eigen::Vector3d PerceptionMap::centre_of(const core::GridCell& key) const {
  const double r = params_.resolution_m;
  return {(key.x + 0.5) * r, (key.y + 0.5) * r, (key.z + 0.5) * r};
}

core::GridCell PerceptionMap::key_of(const Eigen::Vector3d& p) const {
  const double r = params_.resolution_m;
  return {static_cast<int32_t>(std::floor(p.x() / r)), static_cast<int32_t>(std::floor(p.y() / r)),
          static_cast<int32_t>(std::floor(p.z() / r))};
}

IntegrationStats PerceptionMap::integrate(const ScanPoints& scan, const std::vector<OrientedBox>& teammates) {
  if (!scan.sensor_origin.allFinite()) {
    throw std::invalid_argument("PerceptionMap::integrate: sensor origin is not finite");
  }
  if (scan.count > 0 && scan.xyz == nullptr) {
    throw std::invalid_argument("PerceptionMap::integrate: " + std::to_string(scan.count) +
                                " points announced but no point buffer given");
  }
  IntegrationStats stats;
  stats.points_in = scan.count;
  group_points(scan, BodyFilter(teammates, params_.teammate_box_margin_m), stats);
  fold_into_leaves(stats);
  stats.voxels_touched = touched_.size();
  if (touched_.empty()) return stats;
  brick_index_.clear(touched_.size());
  bricks_.clear();
  NeighbourLookup lookup(tree_, bricks_, brick_index_);
  update_metrics(scan.sensor_origin, lookup);
  refresh_terrain_around_new(lookup);
  constexpr uint8_t kScratch = kFlagScratchGeometry | kFlagScratchRisk | kFlagScratchTouched;
  for (const Pending& g : geometry_set_) g.node->data().flags &= static_cast<uint8_t>(~kScratch);
  for (const Pending& r : risk_set_) r.node->data().flags &= static_cast<uint8_t>(~kScratch);
  stats.voxels_recomputed = geometry_set_.size() + risk_set_.size();
  return stats;
}

// 1. Group the points by voxel, accumulating moments relative to the voxel centre in double.
void PerceptionMap::group_points(const ScanPoints& scan, const BodyFilter& bodies, IntegrationStats& stats) {
  const double inv_res = 1.0 / params_.resolution_m;
  const double max_range_sq = scan.max_range_m > 0.0 ? std::pow(scan.max_range_m * (1.0 + 1e-6) + 1e-6, 2) : 0.0;
  groups_.clear(scan.count / 4 + 16);
  accumulators_.clear();
  uint64_t last_packed = FlatKeyMap<uint32_t>::kEmpty;
  uint32_t last_index = 0;
  for (size_t i = 0; i < scan.count; ++i) {
    const Eigen::Vector3d p(scan.xyz[3 * i], scan.xyz[3 * i + 1], scan.xyz[3 * i + 2]);
    if (!p.allFinite()) {
      ++stats.dropped_non_finite;
      continue;
    }
    if (max_range_sq > 0.0 && (p - scan.sensor_origin).squaredNorm() > max_range_sq) {
      ++stats.dropped_out_of_range;
      continue;
    }
    if (!bodies.empty() && bodies.contains(p)) {
      ++stats.dropped_teammate;
      continue;
    }
    int32_t cell[3];
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      const double c = std::floor(p[a] * inv_res) + kOctreeKeyOffset;
      inside = inside && c >= 0.0 && c < 65535.0;
      cell[a] = static_cast<int32_t>(c);
    }
    if (!inside) {
      ++stats.dropped_outside_map;
      continue;
    }
    const octomap::OcTreeKey key(static_cast<octomap::key_type>(cell[0]), static_cast<octomap::key_type>(cell[1]),
                                 static_cast<octomap::key_type>(cell[2]));
    const uint64_t packed = pack_key(key);
    if (packed != last_packed) {
      bool inserted = false;
      uint32_t& index = groups_.find_or_insert(packed, 0, inserted);
      if (inserted) {
        index = static_cast<uint32_t>(accumulators_.size());
        accumulators_.push_back(Accumulator{key, morton(key)});
      }
      last_packed = packed;
      last_index = index;
    }
    Accumulator& acc = accumulators_[last_index];
    const Eigen::Vector3d o = p - centre_of(key);
    ++acc.n;
    acc.s[0] += o.x();
    acc.s[1] += o.y();
    acc.s[2] += o.z();
    acc.q[0] += o.x() * o.x();
    acc.q[1] += o.x() * o.y();
    acc.q[2] += o.x() * o.z();
    acc.q[3] += o.y() * o.y();
    acc.q[4] += o.y() * o.z();
    acc.q[5] += o.z() * o.z();
    ++stats.points_integrated;
  }
}

// 2. Fold each voxel's scan moments into its Gaussian, creating new leaves. Voxels are taken
//    in Z-order: the metric updates below visit each voxel's neighbourhood, and LiDAR order
//    (ring by ring) would put neighbours thousands of voxels apart in memory and time.
void PerceptionMap::fold_into_leaves(IntegrationStats& stats) {
  std::sort(accumulators_.begin(), accumulators_.end(),
            [](const Accumulator& a, const Accumulator& b) { return a.order < b.order; });
  touched_.clear();
  for (const Accumulator& acc : accumulators_) {
    bool created = false;
    VoxelNode* node = tree_.find_or_create(acc.key, created);
    if (created) {
      ++voxel_count_;
      ++stats.voxels_created;
    }
    VoxelData& d = node->data();
    // A voxel that less than doubles shifts a neighbour's fused Gaussian (27 voxels, typically
    // nine occupied) by a few percent; skipping those neighbours keeps rescans cheap. They are
    // recomputed in full whenever a scan touches them.
    const bool propagates = created || acc.n >= d.count;
    uint32_t count = d.count + acc.n;
    for (int a = 0; a < 3; ++a) d.sum[a] += static_cast<float>(acc.s[a]);
    for (int a = 0; a < 6; ++a) d.sum_sq[a] += static_cast<float>(acc.q[a]);
    while (count > kMaxVoxelCount) {
      // Halving every moment keeps mean and covariance while float sums keep their precision
      // (a robot parked for hours keeps adding points to the same voxels).
      count /= 2;
      for (float& v : d.sum) v *= 0.5f;
      for (float& v : d.sum_sq) v *= 0.5f;
    }
    d.count = static_cast<uint16_t>(count);
    touched_.push_back({acc.key, node, acc.n, propagates, created});
  }
}

// 3. Normals and sparsity of the touched voxels and of the 26-neighbours of those that
//    changed enough to matter to them, then the observation metrics of the touched voxels
//    with their new normals. Every Gaussian is final after step 2, so each voxel's geometry
//    is computed as soon as it is reached: its neighbourhood is then still in cache.
void PerceptionMap::update_metrics(const Eigen::Vector3d& sensor_origin, NeighbourLookup& lookup) {
  geometry_set_.clear();
  for (const Touched& t : touched_) t.node->data().flags |= kFlagScratchTouched;
  // Flags and risk masks (step 4) of a voxel depend on its own normal and on its neighbours'
  // means and occupancy, all final by now: untouched voxels are refreshed right after their
  // geometry, touched ones after their observation update.
  auto geometry = [&](const octomap::OcTreeKey& key, VoxelNode* node) {
    VoxelData& d = node->data();
    d.flags |= kFlagScratchGeometry | kFlagScratchRisk;
    const bool touched = (d.flags & kFlagScratchTouched) != 0;
    update_geometry(key, d, lookup, centre_of(key), sensor_origin, touched, params_);
    if (!touched) refresh_state(key, d, lookup);
    geometry_set_.push_back({key, node});
  };
  for (const Touched& t : touched_) {
    if ((t.node->data().flags & kFlagScratchGeometry) == 0) geometry(t.key, t.node);
    update_observation(t.node->data(), centre_of(t.key), sensor_origin, t.points);
    refresh_state(t.key, t.node->data(), lookup);
    if (!t.propagates) continue;
    VoxelNode* block[27];
    lookup.gather27(t.key, block);
    for (int i = 0; i < 27; ++i) {
      VoxelNode* n = block[i];
      if (n == nullptr || (n->data().flags & kFlagScratchGeometry) != 0) continue;
      geometry(NeighbourLookup::offset(t.key, i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1), n);
    }
  }
}

// 4. Flags and risk masks of the voxels whose terrain sample may have changed beyond the
//    geometry set (refreshed above): around new voxels, the columns within the step window
//    (a new cell can change which run a neighbour column's surface is) and the cells below
//    within the clearance window. An existing voxel that propagates moves its mean by under
//    half a cell, which only its 26-neighbours' steps notice.
void PerceptionMap::refresh_terrain_around_new(NeighbourLookup& lookup) {
  risk_set_.clear();
  auto add_risk = [&](const octomap::OcTreeKey& k) {
    VoxelNode* n = lookup.at(k);
    if (n == nullptr || (n->data().flags & kFlagScratchRisk) != 0) return;
    n->data().flags |= kFlagScratchRisk;
    risk_set_.push_back({k, n});
  };
  for (const Touched& t : touched_) {
    if (!t.created) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dz = 2; dz <= window_.step_cells; ++dz) {
          add_risk(NeighbourLookup::offset(t.key, dx, dy, dz));
          add_risk(NeighbourLookup::offset(t.key, dx, dy, -dz));
        }
      }
    }
    for (int dz = -window_.clearance_cells; dz < -1; ++dz) add_risk(NeighbourLookup::offset(t.key, 0, 0, dz));
  }
  for (const Pending& r : risk_set_) refresh_state(r.key, r.node->data(), lookup);
}

void PerceptionMap::update_observation(VoxelData& d, const Eigen::Vector3d& centre, const Eigen::Vector3d& sensor,
                                       uint32_t points) const {
  // Without a normal the angle is undefined, so the observation cannot qualify; its points
  // still shape the Gaussian, and later observations count once a normal exists.
  if (!d.has_normal()) return;
  const Eigen::Vector3d view = sensor - voxel_mean(d, centre);
  const double distance = view.norm();
  if (distance < 1e-6) return;
  float n[3];
  d.normal(n);
  const double cosine = std::abs(view.dot(Eigen::Vector3d(n[0], n[1], n[2]))) / distance;
  const double angle_deg = std::acos(std::clamp(cosine, 0.0, 1.0)) * kRadToDeg;
  const auto angle_cdeg = static_cast<uint16_t>(std::lround(angle_deg * 100.0));
  const auto distance_cm = static_cast<uint16_t>(std::min<long>(0xFFFE, std::lround(distance * 100.0)));
  // Only observations inside both thresholds count (paper: gamma(v), l(v) are minima among them).
  if (angle_deg >= angle_threshold_deg(n) || distance >= params_.l_th_m) {
    // Until one qualifies, the minima of the failed ones say which threshold is in the way.
    if (!d.has_observation()) {
      d.obs_angle_cdeg = std::min(d.obs_angle_cdeg, angle_cdeg);
      d.obs_distance_cm = std::min(d.obs_distance_cm, distance_cm);
    }
    return;
  }
  if (!d.has_observation()) d.obs_angle_cdeg = d.obs_distance_cm = kNoObservation;  // forget the failed ones
  d.obs_points = static_cast<uint16_t>(std::min<uint32_t>(0xFFFF, d.obs_points + points));
  d.obs_angle_cdeg = std::min(d.obs_angle_cdeg, angle_cdeg);
  d.obs_distance_cm = std::min(d.obs_distance_cm, distance_cm);
}

double PerceptionMap::observation_density(const VoxelData& d) const {
  switch (params_.density) {
    case MapParams::Density::kQualifyingPoints: return d.obs_points * params_.density_per_point();
    case MapParams::Density::kAllPoints: return d.count * params_.density_per_point();
    case MapParams::Density::kNeighbourOccupancy: return 1.0 - d.empty_neighbours / 26.0;
    case MapParams::Density::kFusedSurface: return d.fused_density_q * 0.001;
  }
  return 0.0;
}

core::CoverageGap PerceptionMap::coverage_gap(const VoxelData& d) const {
  if (!d.has_normal()) return core::CoverageGap::kNoNormal;
  float n[3];
  d.normal(n);
  const double angle_th = angle_threshold_deg(n);
  if (!d.has_observation()) {
    // Failed observations only (their minima); no observation at all since the normal: angle.
    if (d.obs_angle_cdeg != kNoObservation && d.obs_angle_cdeg / 100.0 < angle_th) return core::CoverageGap::kDistance;
    return core::CoverageGap::kAngle;
  }
  // The threshold follows the current normal (ground or facade), which may have turned since.
  if (d.obs_angle_cdeg / 100.0 >= angle_th) return core::CoverageGap::kAngle;
  if (observation_density(d) <= params_.rho_th) return core::CoverageGap::kDensity;
  return core::CoverageGap::kNone;
}

double PerceptionMap::angle_threshold_deg(const float normal[3]) const {
  return slope_deg(normal) < params_.s_th_deg ? params_.gamma_th_ground_deg : params_.gamma_th_deg;
}

void PerceptionMap::refresh_state(const octomap::OcTreeKey& key, VoxelData& d, NeighbourLookup& lookup) {
  const Eigen::Vector3d centre = centre_of(key);
  float n[3];
  d.normal(n);
  const bool ground = d.has_normal() && slope_deg(n) < params_.s_th_deg;
  uint32_t mask = 0;
  if (ground) mask = low_risk_mask(sample_terrain(key, d, lookup, centre, window_, params_), params_);
  const core::CoverageGap gap = coverage_gap(d);
  const bool covered = gap == core::CoverageGap::kNone;
  const uint8_t flags = static_cast<uint8_t>((ground ? kFlagGround : 0) | (covered ? kFlagCovered : 0) |
                                             (mask != 0 ? kFlagTraversable : 0));
  const bool changed = (d.flags & kPublishedFlagsMask) != flags || d.low_risk_mask != mask ||
                       d.pub_gap != uint8_t(gap) || (d.flags & kFlagWasPublished) == 0 ||
                       published_state_moved(d, centre);
  d.flags = static_cast<uint8_t>((d.flags & ~kPublishedFlagsMask) | flags);
  d.low_risk_mask = mask;
  if (changed && (d.flags & kFlagChangePending) == 0) {
    d.flags |= kFlagChangePending;
    changed_.push_back(pack_key(key));
  }
}

bool PerceptionMap::published_state_moved(const VoxelData& d, const Eigen::Vector3d& centre) const {
  const double step = params_.resolution_m / 254.0;
  const Eigen::Vector3d published_mean(d.pub_mean_q[0] * step, d.pub_mean_q[1] * step, d.pub_mean_q[2] * step);
  const Eigen::Vector3d mean = voxel_mean(d, centre) - centre;
  if ((mean - published_mean).norm() > params_.mean_tolerance_m) return true;
  float n[3];
  d.normal(n);
  const Eigen::Vector3d normal(n[0], n[1], n[2]);
  const Eigen::Vector3d published_normal(d.pub_normal_q[0] / 127.0, d.pub_normal_q[1] / 127.0, d.pub_normal_q[2] / 127.0);
  if (normal.isZero() != published_normal.isZero()) return true;
  if (normal.isZero()) return false;
  const double cosine = normal.dot(published_normal) / (normal.norm() * published_normal.norm());
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * kRadToDeg > params_.normal_tolerance_deg;
}

VoxelView PerceptionMap::view_of(const octomap::OcTreeKey& key, const VoxelData& d) const {
  VoxelView v;
  v.key = to_voxel_key(key);
  v.point_count = d.count;
  const Eigen::Vector3d centre = centre_of(key);
  v.mean = voxel_mean(d, centre).cast<float>();
  if (d.count > 0) {
    const double inv = 1.0 / d.count;
    const Eigen::Vector3d m(d.sum[0] * inv, d.sum[1] * inv, d.sum[2] * inv);
    Eigen::Matrix3d q;
    q << d.sum_sq[0], d.sum_sq[1], d.sum_sq[2], d.sum_sq[1], d.sum_sq[3], d.sum_sq[4], d.sum_sq[2], d.sum_sq[4],
        d.sum_sq[5];
    v.covariance = (q * inv - m * m.transpose()).cast<float>();
  }
  float n[3];
  d.normal(n);
  if (d.has_normal()) {
    v.normal = Eigen::Vector3f(n[0], n[1], n[2]).normalized();
    v.slope_deg = slope_deg(n);
  }
  v.sparsity = d.empty_neighbours / 26.0;
  v.observed = d.has_observation();
  if (v.observed) {
    v.observation_angle_deg = d.obs_angle_cdeg / 100.0;
    v.observation_distance_m = d.obs_distance_cm / 100.0;
  }
  v.observation_density = observation_density(d);
  v.coverage_gap = coverage_gap(d);
  v.flags = d.flags & kPublishedFlagsMask;
  v.low_risk_species_mask = d.low_risk_mask;
  return v;
}

std::optional<VoxelView> PerceptionMap::find(const core::GridCell& key) const {
  octomap::OcTreeKey k;
  if (!to_octree_key(key, k)) return std::nullopt;
  const VoxelNode* node = tree_.search(k);
  if (node == nullptr || node->data().count == 0) return std::nullopt;
  return view_of(k, node->data());
}

std::vector<VoxelView> PerceptionMap::voxels() const {
  std::vector<VoxelView> out;
  out.reserve(voxel_count_);
  for (auto it = tree_.begin_leafs(), end = tree_.end_leafs(); it != end; ++it) {
    if (it.getDepth() != tree_.getTreeDepth() || it->data().count == 0) continue;
    out.push_back(view_of(it.getKey(), it->data()));
  }
  return out;
}

std::vector<VoxelView> PerceptionMap::take_changes() {
  std::vector<VoxelView> out;
  out.reserve(changed_.size());
  const double step = params_.resolution_m / 254.0;
  for (uint64_t packed : changed_) {
    const octomap::OcTreeKey key(static_cast<octomap::key_type>(packed & 0xFFFF),
                                 static_cast<octomap::key_type>((packed >> 16) & 0xFFFF),
                                 static_cast<octomap::key_type>((packed >> 32) & 0xFFFF));
    VoxelNode* node = tree_.search(key);
    if (node == nullptr) continue;
    VoxelData& d = node->data();
    out.push_back(view_of(key, d));
    d.pub_gap = uint8_t(out.back().coverage_gap) & 0x7;
    const Eigen::Vector3d centre = centre_of(key);
    const Eigen::Vector3d offset = voxel_mean(d, centre) - centre;
    for (int a = 0; a < 3; ++a) {
      d.pub_mean_q[a] = static_cast<int8_t>(std::clamp<long>(std::lround(offset[a] / step), -127, 127));
      d.pub_normal_q[a] = static_cast<int8_t>(std::lround(d.normal_q[a] / 32767.0 * 127.0));
    }
    d.flags = static_cast<uint8_t>((d.flags & ~kFlagChangePending) | kFlagWasPublished);
  }
  changed_.clear();
  return out;
}

size_t PerceptionMap::memory_bytes() const {
  return tree_.memoryUsage() + changed_.capacity() * sizeof(uint64_t);
}

}  // namespace hexplore::perception
