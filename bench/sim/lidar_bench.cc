// Rays per second of one full frame of each built-in LiDAR on the multi-building scene.
// Scans run on the calling thread (Embree queries never spawn threads), so the figures are
// for one core. Usage: sim_bench [frames per sensor, default 20]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "common/core/team_config.h"
#include "common/sim/lidar.h"
#include "common/sim/ray_caster.h"
#include "common/sim/robot_motion.h"
#include "common/sim/scenes.h"

int main(int argc, char** argv) {
  using namespace hexplore;
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
  const auto scene = sim::generate_scene("multi-building", 1);
  const auto t0 = std::chrono::steady_clock::now();
  const sim::RayCaster caster(scene.mesh);
  const double build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("scene multi-building: %zu triangles, BVH build %.1f ms\n", caster.triangle_count(), build_ms);
  std::printf("%-10s %-12s %-22s %9s %9s %10s %12s\n", "species", "lidar", "where", "rays", "points", "median ms",
              "Mrays/s");
  struct Spot {
    const char* name;
    Eigen::Vector3d ground;
  };
  const Spot spots[] = {{"street (19,2)", {19, 2, 0}}, {"centre (19,19)", {19, 19, 0}}, {"inside B3 (8,26)", {8, 26, 0}}};
  for (const auto& species : {core::builtin_slugcat(), core::builtin_mr1000()}) {
    for (size_t li = 0; li < species.lidars.size(); ++li) {
      for (const auto& spot : spots) {
        const sim::RobotMotion body(caster, species, spot.ground, 0.3);
        sim::LidarModel lidar(species.lidars[li], 1 + li);
        lidar.aim_at({10, 30, 6}, body.body_pose());  // the gimbal looks at B3's facade
        std::vector<double> ms;
        size_t points = 0;
        for (int f = 0; f < frames; ++f) {
          const auto a = std::chrono::steady_clock::now();
          const auto scan = lidar.scan(caster, body.body_pose());
          ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - a).count());
          points = scan.points.size();
        }
        std::sort(ms.begin(), ms.end());
        const double median = ms[ms.size() / 2];
        std::printf("%-10s %-12s %-22s %9zu %9zu %10.2f %12.2f\n", species.name.c_str(), species.lidars[li].name.c_str(),
                    spot.name, lidar.ray_count(), points, median, lidar.ray_count() / median / 1e3);
      }
    }
  }
  return 0;
}
