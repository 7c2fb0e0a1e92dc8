// Perception-map integration of real simulated LiDAR frames: a robot of a built-in species
// drives through a built-in scene, 20 frames `spacing` apart (the species speed over the scan
// rate: SLUGCAT at 2 Hz is 0.2 m, at 10 Hz 0.04 m); prints CPU time per frame (one thread) of
// the ray casting and of the integration, points per frame and the resulting voxel partition
// (ground/facade, per-species low risk, CSE).
//
// Usage: perception_sim_scan_bench [scene=single-building] [species=SLUGCAT|MR1000] [spacing_m=0.3]

#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/perception/perception_map.h"
#include "common/sim/lidar.h"
#include "common/sim/ray_caster.h"
#include "common/sim/scenes.h"

namespace {

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hexplore;
  const std::string scene_name = argc > 1 ? argv[1] : "single-building";
  const std::string species_name = argc > 2 ? argv[2] : "SLUGCAT";
  const core::SpeciesConfig species = species_name == "MR1000" ? core::builtin_mr1000() : core::builtin_slugcat();
  const double spacing = argc > 3 ? std::atof(argv[3]) : 0.3;
  const sim::SceneInfo scene = sim::generate_scene(scene_name, 1);
  const sim::RayCaster caster(scene.mesh);
  perception::PerceptionMap map(perception::make_map_params(
      core::AlgorithmParams{}, {core::builtin_slugcat(), core::builtin_mr1000()}, species));
  std::vector<sim::LidarModel> lidars;
  for (size_t i = 0; i < species.lidars.size(); ++i) lidars.emplace_back(species.lidars[i], 7 + i);
  const Eigen::Vector3d start = scene.suggested_starts.empty() ? Eigen::Vector3d::Zero() : scene.suggested_starts[0];

  double total_ms = 0.0;
  double max_ms = 0.0;
  double cast_ms = 0.0;
  size_t points = 0;
  int frames = 0;
  for (int step = 0; step < 20; ++step) {
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.translation() = start + Eigen::Vector3d(spacing * step, 0, species.body_half_extents_m.z());
    for (sim::LidarModel& lidar : lidars) {
      lidar.aim_at(body.translation() + Eigen::Vector3d(10, 0, 0), body);
      const double r0 = thread_cpu_ms();
      const sim::LidarScan s = lidar.scan(caster, body);
      cast_ms += thread_cpu_ms() - r0;
      perception::ScanPoints in;
      in.sensor_origin = s.origin;
      in.xyz = reinterpret_cast<const float*>(s.points.data());
      in.count = s.points.size();
      const double c0 = thread_cpu_ms();
      const perception::IntegrationStats st = map.integrate(in, {});
      const double ms = thread_cpu_ms() - c0;
      total_ms += ms;
      max_ms = std::max(max_ms, ms);
      points += st.points_integrated;
      ++frames;
    }
  }
  size_t ground = 0, facade = 0, ground_cse = 0, facade_cse = 0, no_normal = 0;
  std::vector<size_t> low_risk(2, 0);
  for (const perception::VoxelView& v : map.voxels()) {
    (v.ground() ? ground : facade)++;
    if (v.covered()) (v.ground() ? ground_cse : facade_cse)++;
    if (v.normal.isZero()) ++no_normal;
    for (size_t k = 0; k < low_risk.size(); ++k) low_risk[k] += (v.low_risk_species_mask >> k) & 1u;
  }
  std::printf("perception on sim frames: scene %s, %s, %d frames %.2f m apart\n", scene_name.c_str(),
              species.name.c_str(), frames, spacing);
  std::printf("  per scan cycle (all %zu LiDARs): ray casting %.2f ms, integration %.2f ms thread cpu\n",
              lidars.size(), cast_ms / 20, total_ms / 20);
  std::printf("  thread cpu per frame mean / max %.2f / %.2f ms, %.0f points per frame, %.3g points/s\n",
              total_ms / frames, max_ms, static_cast<double>(points) / frames, points / (total_ms / 1000.0));
  std::printf("  voxels %zu: ground %zu (CSE %zu), facade %zu (CSE %zu, %zu without normal)\n", map.voxel_count(),
              ground, ground_cse, facade, facade_cse, no_normal);
  std::printf("  low risk: SLUGCAT %zu, MR1000 %zu\n", low_risk[0], low_risk[1]);
  return 0;
}
