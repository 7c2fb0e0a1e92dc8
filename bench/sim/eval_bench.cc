// Ground-truth evaluation cost on a built-in scene with the default team (or the scene's
// suggested starts): surface samples, reachable ground per species, observable fraction.
// Usage: sim_eval_bench [scene, default single-building] [seed, default 1]
#include <chrono>
#include <cstdio>
#include <string>

#include "common/core/team_config.h"
#include "common/sim/ground_truth.h"
#include "common/sim/observability.h"
#include "common/sim/ray_caster.h"
#include "common/sim/scenes.h"

int main(int argc, char** argv) {
  using namespace hexplore;
  using clock = std::chrono::steady_clock;
  auto ms_since = [](clock::time_point t) { return std::chrono::duration<double, std::milli>(clock::now() - t).count(); };
  const std::string name = argc > 1 ? argv[1] : "single-building";
  const uint64_t seed = argc > 2 ? std::stoull(argv[2]) : 1;
  const auto scene = sim::generate_scene(name, seed);
  const sim::RayCaster caster(scene.mesh);
  auto t = clock::now();
  const auto samples = sim::sample_surface(scene.mesh, 0.1, seed, &scene.site);
  std::printf("%s: %zu surface samples (0.1 m) in %.0f ms\n", name.c_str(), samples.points.size(), ms_since(t));

  core::TeamConfig team;
  team.species = {core::builtin_slugcat(), core::builtin_mr1000()};
  for (size_t i = 0; i < scene.suggested_starts.size() && i < 4; ++i) {
    core::RobotConfig r;
    r.id = "r" + std::to_string(i);
    r.species = team.species[i % 2].name;
    r.start_position_m = scene.suggested_starts[i];
    team.robots.push_back(r);
  }
  for (const auto& species : team.species) {
    std::vector<Eigen::Vector3d> starts;
    for (const auto& r : team.robots)
      if (r.species == species.name) starts.push_back(r.start_position_m);
    t = clock::now();
    const auto reach = sim::reachable_ground(caster, species, starts, scene.site);
    size_t upper = 0;
    for (const auto& p : reach) upper += p.z() > 2.5;
    std::printf("  %-8s reachable cells %6zu (%4zu above 2.5 m) in %.0f ms\n", species.name.c_str(), reach.size(), upper,
                ms_since(t));
  }
  t = clock::now();
  const auto mask = sim::observable_mask(caster, samples, team, scene.site);
  size_t seen = 0;
  for (auto m : mask) seen += m;
  std::printf("  observable samples %zu of %zu (%.1f %%) in %.0f ms\n", seen, mask.size(),
              100.0 * static_cast<double>(seen) / static_cast<double>(mask.size()), ms_since(t));
  return 0;
}
