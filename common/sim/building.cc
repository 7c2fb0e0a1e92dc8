#include "common/sim/building.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/sim/scene_error.h"

namespace hexplore::sim {

void add_wall(MeshBuilder& b, const Eigen::Vector2d& a, const Eigen::Vector2d& end, double thickness, double base_z,
              double height, std::vector<Opening> openings) {
  const bool along_x = std::abs(end.y() - a.y()) < 1e-9;
  const double start = along_x ? std::min(a.x(), end.x()) : std::min(a.y(), end.y());
  const double length = along_x ? std::abs(end.x() - a.x()) : std::abs(end.y() - a.y());
  const double across = along_x ? a.y() : a.x();
  auto piece = [&](double s0, double s1, double z0, double z1) {
    if (s1 - s0 < 1e-6 || z1 - z0 < 1e-6) return;
    if (along_x)
      b.box({start + s0, across - thickness / 2, base_z + z0}, {start + s1, across + thickness / 2, base_z + z1});
    else
      b.box({across - thickness / 2, start + s0, base_z + z0}, {across + thickness / 2, start + s1, base_z + z1});
  };
  std::sort(openings.begin(), openings.end(), [](const Opening& l, const Opening& r) { return l.from < r.from; });
  double cursor = 0.0;
  for (const auto& o : openings) {
    const double from = std::clamp(o.from, cursor, length), to = std::clamp(o.to, from, length);
    piece(cursor, from, 0.0, height);                      // solid wall before the opening
    piece(from, to, 0.0, std::max(0.0, o.bottom));         // sill / nothing for doors
    piece(from, to, std::min(height, o.top), height);      // lintel
    cursor = to;
  }
  piece(cursor, length, 0.0, height);
}

void add_slab(MeshBuilder& b, const Rect& outline, double z_bottom, double z_top, const std::vector<Rect>& holes) {
  std::vector<double> xs = {outline.x0, outline.x1}, ys = {outline.y0, outline.y1};
  for (const auto& h : holes) {
    xs.push_back(std::clamp(h.x0, outline.x0, outline.x1));
    xs.push_back(std::clamp(h.x1, outline.x0, outline.x1));
    ys.push_back(std::clamp(h.y0, outline.y0, outline.y1));
    ys.push_back(std::clamp(h.y1, outline.y0, outline.y1));
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  for (size_t j = 0; j + 1 < ys.size(); ++j) {
    // Merge solid cells of one row into runs to keep the triangle count down.
    size_t i = 0;
    while (i + 1 < xs.size()) {
      auto solid = [&](size_t k) {
        const double cx = 0.5 * (xs[k] + xs[k + 1]), cy = 0.5 * (ys[j] + ys[j + 1]);
        for (const auto& h : holes)
          if (h.contains(cx, cy)) return false;
        return true;
      };
      if (!solid(i)) {
        ++i;
        continue;
      }
      size_t k = i;
      while (k + 2 < xs.size() && solid(k + 1)) ++k;
      b.box({xs[i], ys[j], z_bottom}, {xs[k + 1], ys[j + 1], z_top});
      i = k + 1;
    }
  }
}

void add_parapet(MeshBuilder& b, const Rect& h, double base_z, double height, double t, const std::vector<Side>& open) {
  auto is_open = [&](Side side) { return std::find(open.begin(), open.end(), side) != open.end(); };
  // South and north rails also fill the corners where a west or east rail stands; west and
  // east rails fit between them.
  const double x0 = is_open(Side::kWest) ? h.x0 : h.x0 - t, x1 = is_open(Side::kEast) ? h.x1 : h.x1 + t;
  if (!is_open(Side::kSouth)) b.box({x0, h.y0 - t, base_z}, {x1, h.y0, base_z + height});
  if (!is_open(Side::kNorth)) b.box({x0, h.y1, base_z}, {x1, h.y1 + t, base_z + height});
  if (!is_open(Side::kWest)) b.box({h.x0 - t, h.y0, base_z}, {h.x0, h.y1, base_z + height});
  if (!is_open(Side::kEast)) b.box({h.x1, h.y0, base_z}, {h.x1 + t, h.y1, base_z + height});
}

namespace {

// Windows evenly spaced along a wall of `length`, skipping those that would cut a door.
std::vector<Opening> windows_for(const BuildingSpec& s, double length, const std::vector<Opening>& doors) {
  std::vector<Opening> out;
  const int count = static_cast<int>(std::floor(length / s.window_spacing_m));
  for (int i = 0; i < count; ++i) {
    const double centre = (i + 0.5) * length / count;
    Opening w{centre - s.window_width_m / 2, centre + s.window_width_m / 2, s.window_sill_m,
              s.window_sill_m + s.window_height_m};
    if (w.from < 0.4 || w.to > length - 0.4) continue;
    bool clash = false;
    for (const auto& d : doors) clash = clash || (w.from < d.to + 0.3 && w.to > d.from - 0.3);
    if (!clash) out.push_back(w);
  }
  return out;
}

}  // namespace

void add_building(MeshBuilder& b, const BuildingSpec& s) {
  for (const auto& d : s.doors)
    if (d.width_m < kMinDoorWidthM || d.height_m < kMinDoorHeightM)
      throw SceneError("building", "door of " + std::to_string(d.width_m) + " x " + std::to_string(d.height_m) +
                                       " m is smaller than the robots need (" + std::to_string(kMinDoorWidthM) + " x " +
                                       std::to_string(kMinDoorHeightM) + " m)");
  const Rect& f = s.footprint;
  const double t = s.wall_m;
  struct WallLine {
    Side side;
    Eigen::Vector2d a, e;
    double start;  // footprint coordinate where the wall begins (door offsets are relative to the corner)
  };
  const WallLine walls[4] = {
      {Side::kSouth, {f.x0, f.y0 + t / 2}, {f.x1, f.y0 + t / 2}, f.x0},
      {Side::kNorth, {f.x0, f.y1 - t / 2}, {f.x1, f.y1 - t / 2}, f.x0},
      {Side::kWest, {f.x0 + t / 2, f.y0 + t}, {f.x0 + t / 2, f.y1 - t}, f.y0 + t},
      {Side::kEast, {f.x1 - t / 2, f.y0 + t}, {f.x1 - t / 2, f.y1 - t}, f.y0 + t},
  };
  const double corner[4] = {f.x0, f.x0, f.y0, f.y0};
  for (int w = 0; w < 4; ++w) {
    const auto& line = walls[w];
    const double length = (line.e - line.a).norm();
    std::vector<Opening> doors;
    for (const auto& d : s.doors)
      if (d.side == line.side) {
        const double from = corner[w] + d.offset_m - line.start;
        doors.push_back({from, from + d.width_m, 0.0, d.height_m});
      }
    for (int floor = 0; floor < s.floors; ++floor) {
      std::vector<Opening> openings = windows_for(s, length, floor == 0 ? doors : std::vector<Opening>{});
      if (floor == 0) openings.insert(openings.end(), doors.begin(), doors.end());
      add_wall(b, line.a, line.e, t, s.base_z_m + floor * s.floor_height_m, s.floor_height_m, openings);
    }
  }
  const Rect inner{f.x0 + t, f.y0 + t, f.x1 - t, f.y1 - t};
  for (int level = 1; level <= s.floors; ++level) {
    if (level == s.floors && !s.roof) break;
    const std::vector<Rect> holes =
        (level < s.floors && level - 1 < static_cast<int>(s.slab_holes.size())) ? s.slab_holes[level - 1]
                                                                               : std::vector<Rect>{};
    const double top = s.base_z_m + level * s.floor_height_m;
    add_slab(b, inner, top - s.slab_m, top, holes);
  }
}

}  // namespace hexplore::sim
