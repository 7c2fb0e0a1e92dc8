// Perception-map integration benchmark: time per 100,000-point scan (metric updates of the
// touched voxels included), points per second, and bytes per voxel, on one thread.
// Scans are cast analytically in a 30 m x 20 m x 3 m hall with a ramp and pillars, from a
// sensor that moves 0.25 m per scan, like a robot driving through it.
//
// Usage: perception_integration_bench [scans=30] [points_per_scan=100000]

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "common/perception/perception_map.h"

namespace {

using hexplore::perception::PerceptionMap;
using hexplore::perception::ScanPoints;

// First hit of the ray o + t d with the hall: floor, ceiling, walls, a 15 deg ramp along
// x in [4, 10] for y in [-9, -5], and square pillars every 6 m.
double cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  double best = 1e9;
  auto plane = [&](int axis, double value) {
    if (std::abs(d[axis]) < 1e-9) return;
    const double t = (value - o[axis]) / d[axis];
    if (t > 1e-6 && t < best) best = t;
  };
  plane(2, 0.0);
  plane(2, 3.0);
  plane(0, -15.0);
  plane(0, 15.0);
  plane(1, -10.0);
  plane(1, 10.0);
  {
    // Ramp plane z = (x - 4) tan 15 over its footprint.
    const double k = std::tan(15.0 * M_PI / 180.0);
    const double denom = d.z() - k * d.x();
    if (std::abs(denom) > 1e-9) {
      const double t = (k * (o.x() - 4.0) - o.z()) / denom;
      const Eigen::Vector3d p = o + t * d;
      if (t > 1e-6 && t < best && p.x() >= 4 && p.x() <= 10 && p.y() >= -9 && p.y() <= -5) best = t;
    }
  }
  for (double px = -12; px <= 12; px += 6) {
    for (double py = -6; py <= 6; py += 6) {
      // Axis-aligned 0.6 m pillar: slab test.
      double t0 = 1e-6;
      double t1 = best;
      const double lo[2] = {px - 0.3, py - 0.3};
      const double hi[2] = {px + 0.3, py + 0.3};
      bool hit = true;
      for (int a = 0; a < 2 && hit; ++a) {
        if (std::abs(d[a]) < 1e-12) {
          hit = o[a] >= lo[a] && o[a] <= hi[a];
          continue;
        }
        double ta = (lo[a] - o[a]) / d[a];
        double tb = (hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        hit = t0 <= t1;
      }
      if (hit && t0 < best) best = t0;
    }
  }
  return best;
}

std::vector<float> make_scan(const Eigen::Vector3d& origin, int points, std::mt19937& rng) {
  // A 360 deg LiDAR with 64 lines over -30..+30 deg elevation.
  const int lines = 64;
  const int columns = points / lines;
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<float> xyz;
  xyz.reserve(static_cast<size_t>(lines) * columns * 3);
  for (int l = 0; l < lines; ++l) {
    const double el = (-30.0 + 60.0 * l / (lines - 1)) * M_PI / 180.0;
    for (int c = 0; c < columns; ++c) {
      const double az = 2.0 * M_PI * c / columns;
      const Eigen::Vector3d d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
      const double t = cast(origin, d) + noise(rng);
      const Eigen::Vector3d p = origin + t * d;
      xyz.push_back(static_cast<float>(p.x()));
      xyz.push_back(static_cast<float>(p.y()));
      xyz.push_back(static_cast<float>(p.z()));
    }
  }
  return xyz;
}

// FNV-1a over every voxel's published attributes: equal digests mean a change to the
// integration code left the map it builds exactly as it was (keep it equal when optimising).
uint64_t map_digest(const PerceptionMap& map) {
  uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* p, size_t n) {
    for (size_t i = 0; i < n; ++i) h = (h ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
  };
  for (const hexplore::perception::VoxelView& v : map.voxels()) {
    const float f[] = {v.mean.x(), v.mean.y(), v.mean.z(), v.normal.x(), v.normal.y(), v.normal.z()};
    const double m[] = {v.sparsity, v.observation_angle_deg, v.observation_distance_m, v.observation_density};
    const uint32_t u[] = {static_cast<uint32_t>(v.key.x), static_cast<uint32_t>(v.key.y), static_cast<uint32_t>(v.key.z),
                          v.point_count, v.flags, v.low_risk_species_mask, static_cast<uint32_t>(v.coverage_gap)};
    mix(f, sizeof f);
    mix(m, sizeof m);
    mix(u, sizeof u);
  }
  return h;
}

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  const int scans = argc > 1 ? std::atoi(argv[1]) : 30;
  const int points = argc > 2 ? std::atoi(argv[2]) : 100000;
  hexplore::core::AlgorithmParams algo;
  const hexplore::perception::MapParams params = hexplore::perception::make_map_params(
      algo, {hexplore::core::builtin_slugcat(), hexplore::core::builtin_mr1000()}, hexplore::core::builtin_slugcat());

  std::mt19937 rng(7);
  std::vector<std::vector<float>> frames;
  std::vector<Eigen::Vector3d> origins;
  for (int i = 0; i < scans; ++i) {
    origins.emplace_back(-10.0 + 0.25 * i, 1.0, 0.6);
    frames.push_back(make_scan(origins.back(), points, rng));
  }

  const size_t heap_before = mallinfo2().uordblks;
  PerceptionMap map(params);
  std::vector<double> ms;
  std::vector<double> cpu_ms;
  size_t integrated = 0;
  size_t recomputed = 0;
  size_t touched = 0;
  size_t changes_published = 0;
  for (int i = 0; i < scans; ++i) {
    ScanPoints scan;
    scan.sensor_origin = origins[i];
    scan.xyz = frames[i].data();
    scan.count = frames[i].size() / 3;
    const double c0 = thread_cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    const hexplore::perception::IntegrationStats s = map.integrate(scan, {});
    const auto t1 = std::chrono::steady_clock::now();
    cpu_ms.push_back(thread_cpu_ms() - c0);
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    integrated += s.points_integrated;
    recomputed += s.voxels_recomputed;
    touched += s.voxels_touched;
    if (i % 5 == 4) changes_published += map.take_changes().size();  // as the service does every 0.5 s
  }
  changes_published += map.take_changes().size();
  const size_t heap_after = mallinfo2().uordblks;
  const size_t voxels_moving = map.voxel_count();
  const uint64_t digest_moving = map_digest(map);
  const size_t octree_bytes = map.memory_bytes();

  // A robot standing still: new scans from the last pose mostly add points to known voxels.
  std::vector<double> still_cpu;
  for (int i = 0; i < 10; ++i) {
    const std::vector<float> again = make_scan(origins.back(), points, rng);
    ScanPoints scan;
    scan.sensor_origin = origins.back();
    scan.xyz = again.data();
    scan.count = again.size() / 3;
    const double c0 = thread_cpu_ms();
    map.integrate(scan, {});
    still_cpu.push_back(thread_cpu_ms() - c0);
  }
  std::sort(still_cpu.begin(), still_cpu.end());

  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  double total = 0;
  for (double v : ms) total += v;
  std::printf("perception integration: %d scans of %d points, resolution %.2f m, %zu species\n", scans, points,
              params.resolution_m, params.species.size());
  std::vector<double> cpu_sorted = cpu_ms;
  std::sort(cpu_sorted.begin(), cpu_sorted.end());
  double cpu_total = 0;
  for (double v : cpu_ms) cpu_total += v;
  std::printf("  first scan (empty map)     %8.2f ms wall, %.2f ms cpu\n", ms.front(), cpu_ms.front());
  std::printf("  thread cpu per scan mean / median / max %6.2f / %6.2f / %6.2f ms (immune to other load)\n",
              cpu_total / scans, cpu_sorted[cpu_sorted.size() / 2], cpu_sorted.back());
  std::printf("  wall per scan mean / median / max %6.2f / %6.2f / %6.2f ms\n", total / scans, sorted[sorted.size() / 2],
              sorted.back());
  std::printf("  standing still: thread cpu per scan median %.2f ms\n", still_cpu[still_cpu.size() / 2]);
  std::printf("  points per second          %8.3g wall, %.3g cpu\n", integrated / (total / 1000.0),
              integrated / (cpu_total / 1000.0));
  std::printf("  voxels touched / recomputed per scan %zu / %zu\n", touched / scans, recomputed / scans);
  std::printf("  voxels in map              %8zu\n", voxels_moving);
  std::printf("  bytes per voxel (octomap accounting)  %6.1f\n", static_cast<double>(octree_bytes) / voxels_moving);
  std::printf("  bytes per voxel (heap incl. malloc and scan scratch) %6.1f\n",
              static_cast<double>(heap_after - heap_before) / voxels_moving);
  std::printf("  voxel changes published while driving %zu\n", changes_published);
  std::printf("  map digest after the drive / after standing still  %016llx / %016llx\n",
              static_cast<unsigned long long>(digest_moving), static_cast<unsigned long long>(map_digest(map)));
  return 0;
}
