#include "common/sim/scenes.h"

#include <cmath>
#include <filesystem>

#include "common/sim/scene_error.h"
#include "common/sim/scene_parts.h"

namespace hexplore::sim {

std::vector<std::string> scene_names() {
  return {"single-building", "small-building", "multi-building", "corridor-stairs", "office", "multi-storey",
          "campus"};
}

bool is_builtin_scene(const std::string& name) {
  for (const auto& n : scene_names())
    if (n == name) return true;
  return false;
}

SceneInfo generate_scene(const std::string& name, uint64_t seed) {
  if (name == "single-building") return detail::make_single_building(seed);
  if (name == "small-building") return detail::make_small_building(seed);
  if (name == "multi-building") return detail::make_multi_building(seed);
  if (name == "corridor-stairs") return detail::make_corridor_stairs(seed);
  if (name == "office") return detail::make_office(seed);
  if (name == "multi-storey") return detail::make_multi_storey(seed);
  if (name == "campus") return detail::make_campus(seed);
  std::string known;
  for (const auto& n : scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw SceneError(name, "unknown scene; built-in scenes are " + known + " (or give a mesh file path)");
}

SceneInfo load_scene(const std::string& name_or_path, uint64_t seed, const MeshImportOptions& options) {
  if (is_builtin_scene(name_or_path)) return generate_scene(name_or_path, seed);
  SceneInfo info;
  info.name = name_or_path;
  info.mesh = load_mesh(name_or_path, options);
  const Eigen::AlignedBox3f b = info.mesh.bounds();
  info.site = Eigen::AlignedBox3d(b.min().cast<double>(), b.max().cast<double>());
  return info;
}

std::string resolve_scene(const std::string& scene, const std::string& team_file) {
  namespace fs = std::filesystem;
  if (is_builtin_scene(scene) || team_file.empty() || fs::path(scene).is_absolute()) return scene;
  const fs::path beside = fs::path(team_file).parent_path() / scene;
  std::error_code ec;
  return fs::exists(beside, ec) ? beside.string() : scene;
}

namespace detail {

void rubble_pile(MeshBuilder& b, core::SimRng& rng, const Eigen::Vector2d& center, double radius, int blocks,
                 double max_height) {
  for (int i = 0; i < blocks; ++i) {
    const double r = radius * std::sqrt(rng.uniform()), a = rng.uniform(0, 2 * M_PI);
    // Taller near the centre, so the pile forms a mound.
    const double h = std::max(0.1, max_height * (1.0 - r / radius) * rng.uniform(0.5, 1.0));
    const Eigen::Vector3d half(rng.uniform(0.2, 0.6), rng.uniform(0.15, 0.5), h / 2);
    b.oriented_box({center.x() + r * std::cos(a), center.y() + r * std::sin(a), h / 2 - 0.05}, half,
                   rng.uniform(0, M_PI), rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3));
  }
}

void stone(MeshBuilder& b, core::SimRng& rng, const Eigen::Vector2d& center, double size) {
  const Eigen::Vector3d half(size * rng.uniform(0.4, 0.6), size * rng.uniform(0.3, 0.5), size * rng.uniform(0.25, 0.4));
  b.oriented_box({center.x(), center.y(), half.z() * 0.8}, half, rng.uniform(0, M_PI), rng.uniform(-0.2, 0.2),
                 rng.uniform(-0.2, 0.2));
}

void vehicle(MeshBuilder& b, const Eigen::Vector2d& center, double yaw, double base_z) {
  const Eigen::Vector2d fwd(std::cos(yaw), std::sin(yaw));
  b.oriented_box({center.x(), center.y(), base_z + 0.75}, {2.2, 0.9, 0.45}, yaw);  // body on its wheels
  const Eigen::Vector2d cab = center - 0.3 * fwd;
  b.oriented_box({cab.x(), cab.y(), base_z + 1.45}, {1.1, 0.8, 0.25}, yaw);        // cabin
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      const Eigen::Vector2d w = center + sx * 1.4 * fwd + sy * 0.8 * Eigen::Vector2d(-fwd.y(), fwd.x());
      b.oriented_box({w.x(), w.y(), base_z + 0.33}, {0.33, 0.12, 0.33}, yaw);
    }
}

void debris_field(MeshBuilder& b, core::SimRng& rng, const Rect& area, double cell, double min_h, double max_h,
                  double base_z) {
  const int nx = static_cast<int>(std::floor((area.x1 - area.x0) / cell + 1e-9));
  const int ny = static_cast<int>(std::floor((area.y1 - area.y0) / cell + 1e-9));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double h = rng.uniform(min_h, max_h);
      b.box({area.x0 + i * cell, area.y0 + j * cell, base_z}, {area.x0 + (i + 1) * cell, area.y0 + (j + 1) * cell, base_z + h});
    }
}

void floor_debris(MeshBuilder& b, core::SimRng& rng, const Rect& area, int blocks, double max_size, double floor_z) {
  for (int i = 0; i < blocks; ++i) {
    const Eigen::Vector3d half(rng.uniform(0.15, max_size / 2), rng.uniform(0.15, max_size / 2),
                               rng.uniform(0.08, max_size / 3));
    const double x = rng.uniform(area.x0 + half.x(), area.x1 - half.x());
    const double y = rng.uniform(area.y0 + half.y(), area.y1 - half.y());
    b.oriented_box({x, y, floor_z + half.z()}, half, rng.uniform(0, M_PI));
  }
}

}  // namespace detail
SceneInfo load_team_scene(const core::TeamConfig& team) {
  MeshImportOptions import;
  import.up_axis = parse_up_axis(team.scene_import.up_axis, team.source_file + ": scene_import.up_axis");
  import.scale = team.scene_import.scale;
  import.yaw_deg = team.scene_import.yaw_deg;
  import.translation_m = team.scene_import.translation_m;
  return load_scene(resolve_scene(team.scene, team.source_file), team.params.seed, import);
}

}  // namespace hexplore::sim
