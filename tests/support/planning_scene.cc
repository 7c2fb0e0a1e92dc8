#include "tests/support/planning_scene.h"

#include <set>

#include "common/core/rng.h"

namespace hexplore::planning {

highlevel::MapUpdate synthetic_scene(const SyntheticSceneOptions& o) {
  using highlevel::Supervoxel;
  using highlevel::SurfaceClass;
  highlevel::MapUpdate up;
  up.full_snapshot = true;
  up.version = 1;
  core::PlanRng rng(o.seed);
  const double c = o.cell_m;
  // Wall cells (no ground there unless a door) and their outward normals.
  std::set<std::pair<int, int>> wall, door;
  for (const auto& b : o.buildings) {
    for (int x = b.x0; x <= b.x1; ++x)
      for (int y = b.y0; y <= b.y1; ++y)
        if (x == b.x0 || x == b.x1 || y == b.y0 || y == b.y1) wall.insert({x, y});
    door.insert({(b.x0 + b.x1) / 2, b.y0});  // one door in the south wall, one in the north
    door.insert({(b.x0 + b.x1) / 2 + 1, b.y1});
  }
  auto ground_at = [&](int x, int y) { return !wall.count({x, y}) || door.count({x, y}); };
  auto in = [](const std::vector<Eigen::Vector4i>& rects, int x, int y) {
    for (const auto& r : rects)
      if (x >= r[0] && x <= r[2] && y >= r[1] && y <= r[3]) return true;
    return false;
  };
  for (int x = 0; x < o.width_cells; ++x)
    for (int y = 0; y < o.depth_cells; ++y) {
      if (!ground_at(x, y)) continue;
      Supervoxel sv;
      sv.center = {(x + 0.5) * c, (y + 0.5) * c, 0.1};
      sv.normal = Eigen::Vector3d::UnitZ();
      sv.surface = SurfaceClass::kGround;
      sv.key = highlevel::supervoxel_key(core::cell_of(sv.center, c), sv.surface);
      sv.traversal_requirement = in(o.masonry, x, y) ? 3 : in(o.rubble, x, y) ? 2 : 1;
      sv.covered = rng.uniform() < o.covered_fraction;
      sv.voxel_count = 40;
      up.upserts.push_back(sv);
    }
  for (const auto& b : o.buildings)
    for (int x = b.x0; x <= b.x1; ++x)
      for (int y = b.y0; y <= b.y1; ++y) {
        if (!wall.count({x, y})) continue;
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        if (x == b.x0) n.x() -= 1;
        if (x == b.x1) n.x() += 1;
        if (y == b.y0) n.y() -= 1;
        if (y == b.y1) n.y() += 1;
        n.normalize();
        // Each wall cell has an outer face and an inner one (one facing per supervoxel), each on
        // the side it faces: a wall 0.2 cells thick.
        for (int z = door.count({x, y}) ? 2 : 0; z < b.floors_m; ++z)
          for (const Eigen::Vector3d& face : {n, Eigen::Vector3d(-n)}) {
            Supervoxel sv;
            sv.center = Eigen::Vector3d((x + 0.5) * c, (y + 0.5) * c, (z + 0.5) * c) + 0.1 * c * face;
            sv.normal = face;
            sv.surface = SurfaceClass::kFacade;
            sv.key = highlevel::supervoxel_key(core::cell_of(sv.center, c), sv.surface,
                                               highlevel::facing_of(face.cast<float>()));
            sv.covered = rng.uniform() < o.covered_fraction;
            sv.voxel_count = 30;
            up.upserts.push_back(sv);
          }
      }
  for (int x = 0; x < o.width_cells; ++x)
    for (int y = 0; y < o.depth_cells; ++y) {
      if (!ground_at(x, y)) continue;
      const auto key = [&](int gx, int gy) {
        return highlevel::supervoxel_key(core::cell_of(Eigen::Vector3d((gx + 0.5) * c, (gy + 0.5) * c, 0.1), c),
                                         SurfaceClass::kGround);
      };
      const int d[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
      for (const auto& dd : d) {
        const int nx = x + dd[0], ny = y + dd[1];
        if (nx < 0 || ny < 0 || nx >= o.width_cells || ny >= o.depth_cells || !ground_at(nx, ny)) continue;
        // Diagonals must not cut a wall corner.
        if (dd[0] != 0 && dd[1] != 0 && (!ground_at(x + dd[0], y) || !ground_at(x, y + dd[1]))) continue;
        up.edge_upserts.push_back(highlevel::EdgeKey::of(key(x, y), key(nx, ny)));
      }
    }
  return up;
}

void hide_open_facades(highlevel::MapUpdate& up, double share) {
  core::PlanRng rng(99);
  for (auto& sv : up.upserts)
    if (sv.facade() && !sv.covered && rng.uniform() < share) sv.covered = true;
}

}  // namespace hexplore::planning
