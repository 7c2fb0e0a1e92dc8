// Figures for the high-level map (issue 5 / paper "Computation Runtime" and
// "Communication-Data Volume"):
//  1. segmentation + topology update per 1 s window while a robot explores a synthetic
//     multi-building campus (ground, walls, two upper floors per building);
//  2. distance queries: cached single-source Dijkstra vs plain Floyd–Warshall at 1k/5k/20k
//     vertices (Floyd–Warshall measured where it fits, extrapolated as n^3 beyond);
//  3. bytes per window of incremental sharing vs the full high-level map vs the raw map.
// Usage: highlevel_bench [--quick]

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "common/highlevel/contribution_log.h"
#include "common/highlevel/map_fusion.h"
#include "common/highlevel/map_proto.h"
#include "common/highlevel/segmenter.h"

#include "tests/highlevel/synthetic_map.h"
#include "tests/support/floyd_warshall.h"
#include "tests/support/voxel_sample_wire.h"

namespace hl = hexplore::highlevel;
using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of this thread: the figure that does not depend on other processes sharing cores.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

struct Summary {
  double mean = 0, p95 = 0, max = 0;
};
Summary summarize(std::vector<double> v) {
  Summary s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  for (double x : v) s.mean += x;
  s.mean /= v.size();
  s.p95 = v[std::min(v.size() - 1, static_cast<size_t>(0.95 * v.size()))];
  s.max = v.back();
  return s;
}

void bench_windows(bool quick) {
  hl::testing::CampusSpec spec;
  spec.size_m = 48.0;
  spec.buildings = 2;
  spec.building_m = 10.0;
  spec.storeys = 3;
  const auto all = hl::testing::campus_voxels(spec);
  const double res = spec.resolution_m;

  // The robot drives a lawn-mower route at 0.5 m/s; each 1 s window its 10 m sensor adds the
  // voxels it sees first, marks voxels within 6 m covered and refines the means of a tenth of
  // the voxels in range (the mapping service's VoxelDelta).
  std::vector<Eigen::Vector2d> route;
  for (double y = 4.0; y < spec.size_m; y += 12.0) {
    for (double x = 2.0; x < spec.size_m - 2.0; x += 0.5) route.emplace_back(x, y);
    for (double x = spec.size_m - 2.0; x > 2.0; x -= 0.5) route.emplace_back(x, y + 6.0);
  }
  if (quick) route.resize(route.size() / 4);

  hl::SupervoxelSegmenter seg({}, {1, 2});
  hl::ContributionLog log("r1");
  hl::MapFusion fusion({1, 2});
  std::vector<uint8_t> state(all.size(), 0);  // 0 unseen, 1 seen, 2 covered
  std::vector<hl::VoxelSample> current = all;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> seg_ms, topo_ms, total_ms, cpu_total_ms;
  size_t inc_bytes = 0, full_hl_bytes = 0, raw_delta_bytes = 0, raw_full_bytes = 0, windows = 0;
  size_t seen = 0;
  std::vector<double> delta_sizes;
  for (const auto& pos : route) {
    std::vector<hl::VoxelSample> delta;
    for (size_t i = 0; i < all.size(); ++i) {
      const auto& v = all[i];
      const double dx = (v.key.x + 0.5) * res - pos.x();
      const double dy = (v.key.y + 0.5) * res - pos.y();
      const double d2 = dx * dx + dy * dy;
      if (d2 > 100.0) continue;
      bool changed = false;
      if (state[i] == 0) {
        state[i] = 1;
        ++seen;
        changed = true;
      }
      if (state[i] == 1 && d2 < 36.0) {
        state[i] = 2;
        current[i].flags |= hl::kVoxelCovered;
        changed = true;
      }
      if (!changed && unit(rng) < 0.1) {
        current[i].mean.z() += static_cast<float>(0.002 * (unit(rng) - 0.5));
        changed = true;
      }
      if (changed) delta.push_back(current[i]);
    }
    const double c0 = cpu_ms();
    auto t0 = Clock::now();
    const auto change = seg.update(delta);
    const double t_seg = ms_since(t0);
    auto t1 = Clock::now();
    log.record(seg, change);
    const auto inc = log.take_increment();
    fusion.apply("r1", inc.update);
    const double t_topo = ms_since(t1);
    seg_ms.push_back(t_seg);
    topo_ms.push_back(t_topo);
    total_ms.push_back(t_seg + t_topo);
    cpu_total_ms.push_back(cpu_ms() - c0);
    delta_sizes.push_back(delta.size());

    inc_bytes += hl::to_increment(inc, log.contribution()).ByteSizeLong();
    full_hl_bytes += hl::to_snapshot(log.snapshot(), log.contribution()).ByteSizeLong();
    hexplore::v1::VoxelDelta raw;
    raw.set_resolution_m(res);
    for (const auto& v : delta) hl::to_proto(v, raw.add_voxels());
    raw_delta_bytes += raw.ByteSizeLong();
    // The whole raw map as the voxels seen so far (estimated from one voxel's encoded size).
    raw_full_bytes += seen * (raw.voxels_size() > 0 ? raw.ByteSizeLong() / raw.voxels_size() : 30);
    ++windows;
  }
  size_t ground = 0, facade = 0;
  for (const auto& [k, sv] : seg.supervoxels()) (sv.ground() ? ground : facade)++;
  const auto& g = fusion.map().graph();
  std::printf("== segmentation + topology per 1 s window (campus %.0f x %.0f m, %d x %d buildings x %d storeys)\n",
              spec.size_m, spec.size_m, spec.buildings, spec.buildings, spec.storeys);
  std::printf("voxels %zu, supervoxels %zu (ground %zu, facade %zu), graph vertices %zu, edges %zu, windows %zu\n",
              seg.voxel_count(), seg.supervoxels().size(), ground, facade, g.vertex_count(), g.edge_count(), windows);
  const auto s = summarize(seg_ms), t = summarize(topo_ms), a = summarize(total_ms);
  std::printf("segmentation ms/window: mean %.2f p95 %.2f max %.2f\n", s.mean, s.p95, s.max);
  std::printf("topology+fusion ms/window: mean %.2f p95 %.2f max %.2f\n", t.mean, t.p95, t.max);
  std::printf("total ms/window: mean %.2f p95 %.2f max %.2f (target <= 30)\n", a.mean, a.p95, a.max);
  const auto c = summarize(cpu_total_ms), d = summarize(delta_sizes);
  std::printf("total CPU ms/window: mean %.2f p95 %.2f max %.2f; voxels per delta: mean %.0f max %.0f\n", c.mean, c.p95,
              c.max, d.mean, d.max);

  auto t0 = Clock::now();
  hl::SupervoxelSegmenter full({}, {1, 2});
  full.update(all);
  std::printf("one-shot segmentation of the whole map: %.1f ms\n", ms_since(t0));

  std::printf("== sharing volume per window (mean over %zu windows)\n", windows);
  const double inc = static_cast<double>(inc_bytes) / windows;
  const double hlf = static_cast<double>(full_hl_bytes) / windows;
  const double rd = static_cast<double>(raw_delta_bytes) / windows;
  const double rf = static_cast<double>(raw_full_bytes) / windows;
  std::printf("incremental high-level map: %.0f B/s\n", inc);
  std::printf("full high-level map every window: %.0f B/s (incremental saves %.2f%%)\n", hlf, 100.0 * (1.0 - inc / hlf));
  std::printf("raw perception deltas: %.0f B/s (saves %.2f%%)\n", rd, 100.0 * (1.0 - inc / rd));
  std::printf("raw perception map every window: %.0f B/s (saves %.2f%%)\n", rf, 100.0 * (1.0 - inc / rf));
}

// Lattice of ground supervoxels (8-neighbour, jittered, some rough vertices) like the map's.
hl::TopologyGraph lattice(int n, uint32_t seed) {
  const int side = static_cast<int>(std::ceil(std::sqrt(n)));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::uniform_int_distribution<int> rough(0, 9);
  hl::TopologyGraph g({1, 2});
  std::vector<Eigen::Vector3d> pos(static_cast<size_t>(side) * side);
  int count = 0;
  for (int y = 0; y < side && count < n; ++y)
    for (int x = 0; x < side && count < n; ++x, ++count) {
      pos[y * side + x] = Eigen::Vector3d(x + jitter(rng), y + jitter(rng), 0.1 * jitter(rng));
      g.upsert_vertex(y * side + x + 1, pos[y * side + x], rough(rng) == 0 ? 2 : 1);
    }
  for (int i = 0; i < count; ++i) {
    const int x = i % side, y = i / side;
    for (auto [dx, dy] : {std::pair{1, 0}, {0, 1}, {1, 1}, {-1, 1}}) {
      const int nx = x + dx, ny = y + dy;
      const int j = ny * side + nx;
      if (nx < 0 || nx >= side || j >= count) continue;
      g.upsert_edge(i + 1, j + 1, (pos[i] - pos[j]).norm());
    }
  }
  return g;
}

void bench_distances(bool quick) {
  std::printf("== distance queries: cached Dijkstra vs Floyd-Warshall (species 0; thread CPU time)\n");
  std::printf("%8s %14s %14s %16s %16s %14s %16s\n", "vertices", "dijkstra_ms", "warm_query_ns", "mem/source_KiB",
              "mem_200src_MiB", "fw_ms", "fw_mem_MiB(f32)");
  double fw_ref_ms = 0;
  int fw_ref_n = 0;
  for (int n : {1000, 5000, 20000}) {
    auto g = lattice(n, 3);
    const auto keys = g.vertex_keys();
    std::mt19937 rng(n);
    std::uniform_int_distribution<size_t> pick(0, keys.size() - 1);
    // Cold searches: distinct sources.
    const int sources = quick ? 20 : 100;
    double c0 = cpu_ms();
    double sink = 0;
    for (int i = 0; i < sources; ++i) sink += std::min(1e9, g.dist(keys[pick(rng)], keys[pick(rng)], 0));
    const double cold = (cpu_ms() - c0) / sources;
    // Warm queries: pairs among 200 sources once their searches are cached.
    std::vector<uint64_t> pool;
    for (int i = 0; i < 200; ++i) pool.push_back(keys[pick(rng)]);
    for (uint64_t s : pool) sink += std::min(1e9, g.dist(s, pool[0], 0));
    const int queries = 1000000;
    std::uniform_int_distribution<size_t> pp(0, pool.size() - 1);
    c0 = cpu_ms();
    for (int i = 0; i < queries; ++i) sink += std::min(1e9, g.dist(pool[pp(rng)], keys[pick(rng)], 0));
    const double warm_ns = (cpu_ms() - c0) * 1e6 / queries;
    const double per_source_kib = n * (sizeof(double) + sizeof(int)) / 1024.0;
    const double pool_mib = static_cast<double>(g.cache_bytes()) / (1024.0 * 1024.0);
    // Floyd–Warshall (float distances + int successors): measured at 1k, n^3 beyond.
    double fw_ms = 0;
    std::string fw_note;
    if (n <= 1000) {
      const double f0 = cpu_ms();
      const auto ap = hl::floyd_warshall<float>(g, 0);
      fw_ms = cpu_ms() - f0;
      sink += std::min(1e9f, ap.dist(keys[0], keys[1]));
      fw_ref_ms = fw_ms;
      fw_ref_n = n;
      fw_note = "measured";
    } else {
      fw_ms = fw_ref_ms * std::pow(static_cast<double>(n) / fw_ref_n, 3.0);
      fw_note = "n^3 extrapolated";
    }
    const double fw_mib = static_cast<double>(n) * n * (sizeof(float) + sizeof(int)) / (1024.0 * 1024.0);
    std::printf("%8d %14.3f %14.1f %16.1f %16.1f %14.0f %16.0f  (FW %s; sink %.0f)\n", n, cold, warm_ns, per_source_kib,
                pool_mib, fw_ms, fw_mib, fw_note.c_str(), std::fmod(sink, 10.0));
  }
  std::printf("(FW memory is per species and doubles with double distances; Dijkstra memory is per cached source)\n");
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  bench_windows(quick);
  bench_distances(quick);
  return 0;
}
