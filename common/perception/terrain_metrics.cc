#include "common/perception/terrain_metrics.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace hexplore::perception {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// Mean z in the world frame of voxel `d` whose centre height is `centre_z`.
double mean_z(const VoxelData& d, double centre_z) { return centre_z + d.sum[2] / static_cast<double>(d.count); }

// Which side of the plane through the voxel's own points the sensor is on (a unit vector along
// that plane's normal), or zero when those points make no plane: too few, on a line, or bent
// (an edge runs through the voxel). A plane of points is seen only from its open side.
Eigen::Vector3d own_points_side(const VoxelData& d, const Eigen::Vector3d& centre, const Eigen::Vector3d& sensor,
                                double resolution) {
  if (d.count < 4) return Eigen::Vector3d::Zero();
  const double n = d.count;
  const Eigen::Vector3d mean(d.sum[0] / n, d.sum[1] / n, d.sum[2] / n);
  Eigen::Matrix3d cov;
  cov << d.sum_sq[0], d.sum_sq[1], d.sum_sq[2], d.sum_sq[1], d.sum_sq[3], d.sum_sq[4], d.sum_sq[2], d.sum_sq[4], d.sum_sq[5];
  cov = cov / n - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(cov);
  const double flat = eig.eigenvalues()(0), narrow = eig.eigenvalues()(1);
  // A plane at the LiDAR's range noise has flat/narrow of a few hundredths; an L of two faces
  // inside one voxel about a half.
  if (narrow < 0.01 * resolution * resolution || flat > 0.25 * narrow) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d normal = eig.eigenvectors().col(0);
  return normal.dot(sensor - (centre + mean)) >= 0.0 ? normal : Eigen::Vector3d(-normal);
}

}  // namespace

TerrainWindow TerrainWindow::from(const MapParams& params) {
  double max_step = 0.0;
  double max_clearance = 0.0;
  for (const SpeciesLimits& s : params.species) {
    max_step = std::max(max_step, s.max_step_m);
    max_clearance = std::max(max_clearance, s.min_clearance_m);
  }
  TerrainWindow w;
  // One cell more than the largest tolerated step, so a step just above the limit is seen.
  w.step_cells = static_cast<int>(std::ceil(max_step / params.resolution_m)) + 1;
  w.clearance_cells = static_cast<int>(std::ceil(max_clearance / params.resolution_m)) + 1;
  return w;
}

double slope_deg(const float normal[3]) {
  return std::acos(std::clamp(static_cast<double>(normal[2]), -1.0, 1.0)) * kRadToDeg;
}

Eigen::Vector3d voxel_mean(const VoxelData& d, const Eigen::Vector3d& centre) {
  if (d.count == 0) return centre;
  const double inv = 1.0 / static_cast<double>(d.count);
  return centre + Eigen::Vector3d(d.sum[0] * inv, d.sum[1] * inv, d.sum[2] * inv);
}

void update_geometry(const octomap::OcTreeKey& key, VoxelData& d, NeighbourLookup& lookup,
                     const Eigen::Vector3d& centre, const Eigen::Vector3d& sensor, bool orient_to_sensor,
                     const MapParams& params) {
  // Moments of the whole neighbourhood relative to this voxel's centre: each neighbour's
  // moments are shifted by its centre offset o: S1' = S1 + n o, S2' = S2 + S1 o^T + o S1^T + n o o^T.
  const double res = params.resolution_m;
  VoxelNode* block[27];
  lookup.gather27(key, block);
  // The neighbours live in scattered heap nodes; ask for all of them at once so their cache
  // misses overlap instead of stalling the accumulation one by one.
  for (const VoxelNode* b : block) {
    if (b != nullptr) __builtin_prefetch(&b->data().count);
  }
  double n = 0.0;
  double s1[3] = {0, 0, 0};
  double s2[6] = {0, 0, 0, 0, 0, 0};  // xx xy xz yy yz zz
  int empty = 0;
  for (int i = 0; i < 27; ++i) {
    const VoxelData* nd = i == 13 ? &d : (block[i] != nullptr ? &block[i]->data() : nullptr);
    if (nd == nullptr) {
      ++empty;
      continue;
    }
    static constexpr int8_t kOffset[27][3] = {
        {-1, -1, -1}, {0, -1, -1}, {1, -1, -1}, {-1, 0, -1}, {0, 0, -1}, {1, 0, -1}, {-1, 1, -1}, {0, 1, -1}, {1, 1, -1},
        {-1, -1, 0},  {0, -1, 0},  {1, -1, 0},  {-1, 0, 0},  {0, 0, 0},  {1, 0, 0},  {-1, 1, 0},  {0, 1, 0},  {1, 1, 0},
        {-1, -1, 1},  {0, -1, 1},  {1, -1, 1},  {-1, 0, 1},  {0, 0, 1},  {1, 0, 1},  {-1, 1, 1},  {0, 1, 1},  {1, 1, 1}};
    const double o[3] = {kOffset[i][0] * res, kOffset[i][1] * res, kOffset[i][2] * res};
    const double c = nd->count;
    const double a[3] = {nd->sum[0], nd->sum[1], nd->sum[2]};
    n += c;
    for (int k = 0; k < 3; ++k) s1[k] += a[k] + c * o[k];
    s2[0] += nd->sum_sq[0] + 2 * a[0] * o[0] + c * o[0] * o[0];
    s2[1] += nd->sum_sq[1] + a[0] * o[1] + o[0] * a[1] + c * o[0] * o[1];
    s2[2] += nd->sum_sq[2] + a[0] * o[2] + o[0] * a[2] + c * o[0] * o[2];
    s2[3] += nd->sum_sq[3] + 2 * a[1] * o[1] + c * o[1] * o[1];
    s2[4] += nd->sum_sq[4] + a[1] * o[2] + o[1] * a[2] + c * o[1] * o[2];
    s2[5] += nd->sum_sq[5] + 2 * a[2] * o[2] + c * o[2] * o[2];
  }
  d.empty_neighbours = static_cast<uint8_t>(empty);
  if (n < params.min_points_for_normal) return;

  const Eigen::Vector3d mean(s1[0] / n, s1[1] / n, s1[2] / n);
  Eigen::Matrix3d cov_d;
  cov_d << s2[0], s2[1], s2[2], s2[1], s2[3], s2[4], s2[2], s2[4], s2[5];
  cov_d = cov_d / n - mean * mean.transpose();
  // The moments are offsets within half a metre, so the decomposition is safe in float (and
  // about twice as fast as in double).
  const Eigen::Matrix3f cov = cov_d.cast<float>();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> eig;
  eig.computeDirect(cov);
  // Points on a line (one far LiDAR ring) leave the normal undetermined within a plane.
  const double line_limit = 0.01 * res * res;
  if (eig.eigenvalues()(1) < line_limit) return;
  // The surface's area in the neighbourhood from its spread in the plane: points spread evenly
  // over an a x b patch have variances a^2/12 and b^2/12, so area = 12 sqrt(l1 l2). Counting per
  // fitted area instead of per voxel face is what keeps a wall that runs along a voxel boundary
  // (its points split between two layers) or past a voxel's corner from looking sparse forever.
  const double area_m2 = 12.0 * std::sqrt(double(eig.eigenvalues()(1)) * double(eig.eigenvalues()(2)));
  const double per_cm2 = n / std::max(area_m2 * 1.0e4, 1.0);
  d.fused_density_q = static_cast<uint16_t>(std::min(65535.0, std::round(per_cm2 * 1000.0)));
  Eigen::Vector3d normal = eig.eigenvectors().col(0).cast<double>().normalized();

  // The sensor saw this side of the surface. But the plane is fitted to a 0.45 m neighbourhood,
  // and where the surface is not flat at that scale the sensor may see it from beyond the
  // plane: the treads of a staircase seen from its top landing face the sensor while the
  // flight's mean plane passes above it, and orienting towards the sensor would turn the
  // flight down (a ceiling: facade) behind a robot that just climbed it. A ground robot sees
  // a shallow surface from above only on its top side, so a shallow plane seen from above
  // faces up; steeper ones, and any seen from below (ceilings), face the sensor.
  //
  // A grazing ray says little about which side of a steep plane is open: at a building's corner
  // the fitted plane bisects the edge, and a sensor that sees one face from far along it is
  // behind that plane, so turning towards it points the edge's normal into the building; the
  // supervoxel it joins then faces inwards and gets views inside the wall that never complete
  // it. So a steep plane changes sides only for a ray within gamma_th of it (one that could
  // observe it), and a new one seen at a grazing angle takes the side the sensor sees of the
  // voxel's own points when they are planar (one face of the corner), else the sensor's.
  const Eigen::Vector3d view = sensor - (centre + mean);
  const bool shallow = std::abs(normal.z()) >= std::cos(params.s_th_deg * M_PI / 180.0);
  const bool frontal = std::abs(normal.dot(view)) >= std::cos(params.gamma_th_deg * M_PI / 180.0) * view.norm();
  if (!d.has_normal() || (orient_to_sensor && (shallow || frontal))) {
    Eigen::Vector3d open_side = view;
    if (!shallow && !frontal) {
      const Eigen::Vector3d own = own_points_side(d, centre, sensor, res);
      if (!own.isZero()) open_side = own;
    }
    if (shallow && view.z() > 0.0 ? normal.z() < 0.0 : normal.dot(open_side) < 0.0) normal = -normal;
  } else {
    float prev[3];
    d.normal(prev);
    if (normal.dot(Eigen::Vector3d(prev[0], prev[1], prev[2])) < 0.0) normal = -normal;
  }
  d.set_normal(normal.x(), normal.y(), normal.z());
}

TerrainSample sample_terrain(const octomap::OcTreeKey& key, const VoxelData& d, NeighbourLookup& lookup,
                             const Eigen::Vector3d& centre, const TerrainWindow& window, const MapParams& params) {
  TerrainSample t;
  float normal[3];
  d.normal(normal);
  t.slope_deg = slope_deg(normal);
  t.sparsity = d.empty_neighbours / 26.0;
  const double res = params.resolution_m;
  const double h = mean_z(d, centre.z());

  // Surface height of each neighbouring column: the occupied cell nearest to this voxel's
  // level, then up its contiguous run (a wall's run reaches the window top: a large step; an
  // overhang above a floor is a separate run and does not count).
  VoxelNode* block[27];
  lookup.gather27(key, block);
  // Cell (dx, dy, dz) of the neighbourhood, from the gathered block when |dz| <= 1.
  auto cell = [&](int dx, int dy, int dz) -> VoxelNode* {
    if (dz >= -1 && dz <= 1) return block[(dz + 1) * 9 + (dy + 1) * 3 + (dx + 1)];
    return lookup.at(key, dx, dy, dz);
  };
  double heights[9];
  double xs[9];
  double ys[9];
  int m = 0;
  heights[m] = h;
  xs[m] = 0.0;
  ys[m] = 0.0;
  ++m;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      int found = 0;
      bool any = false;
      for (int r = 0; r <= window.step_cells && !any; ++r) {
        if (cell(dx, dy, r) != nullptr) {
          found = r;
          any = true;
        } else if (r > 0 && cell(dx, dy, -r) != nullptr) {
          found = -r;
          any = true;
        }
      }
      if (!any) continue;  // unknown column: sparsity accounts for it
      int top = found;
      while (top < window.step_cells && cell(dx, dy, top + 1) != nullptr) ++top;
      const VoxelNode* node = cell(dx, dy, top);
      const double hz = mean_z(node->data(), centre.z() + top * res);
      t.step_m = std::max(t.step_m, std::abs(hz - h));
      heights[m] = hz;
      xs[m] = dx * res;
      ys[m] = dy * res;
      ++m;
    }
  }
  if (m >= 4) {
    // Least-squares plane z = a + b x + c y through the column heights.
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Vector3d atb = Eigen::Vector3d::Zero();
    for (int i = 0; i < m; ++i) {
      const Eigen::Vector3d row(1.0, xs[i], ys[i]);
      ata += row * row.transpose();
      atb += row * heights[i];
    }
    const Eigen::Vector3d coef = ata.ldlt().solve(atb);
    double sq = 0.0;
    for (int i = 0; i < m; ++i) {
      const double r = heights[i] - (coef(0) + coef(1) * xs[i] + coef(2) * ys[i]);
      sq += r * r;
    }
    t.roughness_m = std::sqrt(sq / m);
  }

  // This column's own run: cells directly above this one, without a gap, are the surface
  // rising within the column (a riser from this tread to the next, a ramp split over two
  // cells, a wall's foot), a step like a neighbour column's run, not something overhead.
  int run = 0;
  while (run < window.step_cells && cell(0, 0, run + 1) != nullptr) ++run;
  const double surface = run == 0 ? h : mean_z(cell(0, 0, run)->data(), centre.z() + run * res);
  t.step_m = std::max(t.step_m, surface - h);
  // Overhead obstacles: the first voxel above the run, after a gap, measured from its top.
  for (int dz = run + 2; dz <= window.clearance_cells; ++dz) {
    const VoxelNode* node = cell(0, 0, dz);
    if (node == nullptr) continue;
    t.clearance_m = mean_z(node->data(), centre.z() + dz * res) - surface;
    break;
  }
  return t;
}

uint32_t low_risk_mask(const TerrainSample& t, const MapParams& params) {
  uint32_t mask = 0;
  for (size_t k = 0; k < params.species.size(); ++k) {
    const SpeciesLimits& s = params.species[k];
    const bool low_risk = t.slope_deg <= slope_allowance_deg(s) && t.sparsity <= s.max_sparsity &&
                          t.step_m <= s.max_step_m && t.roughness_m <= s.max_roughness_m &&
                          t.clearance_m >= s.min_clearance_m;
    if (low_risk) mask |= uint32_t{1} << k;
  }
  return mask;
}

}  // namespace hexplore::perception
