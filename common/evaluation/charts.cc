#include "common/evaluation/charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace hexplore::evaluation {
namespace {

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kBlack{20, 20, 20};
constexpr Rgb kGrid{225, 225, 225};
constexpr Rgb kTeam{20, 20, 20};
constexpr Rgb kObservable{120, 120, 120};

std::string format(const char* fmt, double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, fmt, v);
  return buffer;
}

// Maps data coordinates into a plot rectangle of the raster.
struct Frame {
  int left, top, right, bottom;
  double x_min, x_max, y_min, y_max;
  int px(double x) const { return left + static_cast<int>(std::lround((x - x_min) / (x_max - x_min) * (right - left))); }
  int py(double y) const { return bottom - static_cast<int>(std::lround((y - y_min) / (y_max - y_min) * (bottom - top))); }
};

void polyline(Raster& r, const Frame& f, const std::vector<double>& xs, const std::vector<double>& ys, Rgb c, int t) {
  for (size_t i = 1; i < xs.size(); ++i) r.line(f.px(xs[i - 1]), f.py(ys[i - 1]), f.px(xs[i]), f.py(ys[i]), c, t);
}

}  // namespace

Rgb robot_colour(size_t index) {
  static constexpr Rgb kPalette[] = {{228, 26, 28},  {55, 126, 184}, {77, 175, 74},  {152, 78, 163},
                                     {255, 127, 0},  {166, 86, 40},  {247, 129, 191}, {0, 170, 170}};
  return kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
}

Raster completeness_chart(const ExperimentRecord& record, int width, int height) {
  Raster r(width, height, kWhite);
  double t_max = 1.0;
  for (const auto& s : record.completeness) t_max = std::max(t_max, s.sim_time_s);
  const Frame f{70, 40, width - 200, height - 60, 0.0, t_max, 0.0, 100.0};
  for (int pct = 0; pct <= 100; pct += 20) {
    r.line(f.left, f.py(pct), f.right, f.py(pct), kGrid);
    r.text(f.left - 40, f.py(pct) - 3, format("%.0f%%", pct), kBlack);
  }
  for (int i = 0; i <= 5; ++i) {
    const double t = t_max * i / 5.0;
    r.line(f.px(t), f.top, f.px(t), f.bottom, kGrid);
    r.text(f.px(t) - 12, f.bottom + 10, format("%.0f", t), kBlack);
  }
  r.line(f.left, f.bottom, f.right, f.bottom, kBlack, 2);
  r.line(f.left, f.top, f.left, f.bottom, kBlack, 2);
  r.text(f.left + (f.right - f.left) / 2 - 60, height - 25, "SIM TIME (S)", kBlack);
  r.text(f.left, 12, "RECONSTRUCTION COMPLETENESS", kBlack, 2);

  std::vector<double> ts, team, observable;
  std::map<std::string, std::vector<double>> per_robot;
  for (const auto& s : record.completeness) {
    ts.push_back(s.sim_time_s);
    team.push_back(100.0 * s.team);
    observable.push_back(100.0 * s.team_observable);
    for (const auto& [robot, _] : record.robots) {
      const auto it = s.per_robot.find(robot);
      per_robot[robot].push_back(100.0 * (it == s.per_robot.end() ? 0.0 : it->second));
    }
  }
  polyline(r, f, ts, observable, kObservable, 2);
  polyline(r, f, ts, team, kTeam, 3);
  int legend_y = f.top;
  r.line(f.right + 15, legend_y + 3, f.right + 35, legend_y + 3, kTeam, 3);
  r.text(f.right + 42, legend_y, "TEAM", kBlack);
  legend_y += 18;
  r.line(f.right + 15, legend_y + 3, f.right + 35, legend_y + 3, kObservable, 2);
  r.text(f.right + 42, legend_y, "OBSERVABLE", kBlack);
  size_t index = 0;
  for (const auto& [robot, values] : per_robot) {
    legend_y += 18;
    const Rgb c = robot_colour(index++);
    polyline(r, f, ts, values, c, 2);
    r.line(f.right + 15, legend_y + 3, f.right + 35, legend_y + 3, c, 2);
    r.text(f.right + 42, legend_y, robot, kBlack);
  }
  return r;
}

Raster topdown_map(const ExperimentRecord& record, int width, int height) {
  Raster r(width, height, kWhite);
  double x_min = std::numeric_limits<double>::max(), y_min = x_min, z_min = x_min;
  double x_max = std::numeric_limits<double>::lowest(), y_max = x_max, z_max = x_max;
  auto grow = [&](double x, double y, double z) {
    x_min = std::min(x_min, x), x_max = std::max(x_max, x);
    y_min = std::min(y_min, y), y_max = std::max(y_max, y);
    z_min = std::min(z_min, z), z_max = std::max(z_max, z);
  };
  for (const auto& p : record.final_map_points_m) grow(p.x(), p.y(), p.z());
  for (const auto& [_, track] : record.robots)
    for (const auto& p : track.positions_m) grow(p.x(), p.y(), p.z());
  if (x_min > x_max) {
    r.text(20, 20, "NO MAP", kBlack, 2);
    return r;
  }
  // Equal scale on both axes, with a margin; y up in the picture.
  const double span = std::max({x_max - x_min, y_max - y_min, 1.0});
  const double margin = 40.0;
  const double scale = (std::min(width, height) - 2 * margin) / span;
  auto px = [&](double x) { return static_cast<int>(margin + (x - x_min) * scale); };
  auto py = [&](double y) { return static_cast<int>(height - margin - (y - y_min) * scale); };
  const double z_span = std::max(z_max - z_min, 1e-3);
  const int dot = std::max(1, static_cast<int>(scale * 0.15));
  // Draw low points first so that roofs and upper floors stay visible.
  std::vector<Eigen::Vector3f> points = record.final_map_points_m;
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.z() < b.z(); });
  for (const auto& p : points) {
    const auto grey = static_cast<uint8_t>(215 - 150 * (p.z() - z_min) / z_span);
    r.fill_rect(px(p.x()), py(p.y()), px(p.x()) + dot - 1, py(p.y()) + dot - 1, {grey, grey, grey});
  }
  size_t index = 0;
  int legend_y = 10;
  for (const auto& [robot, track] : record.robots) {
    const Rgb c = robot_colour(index++);
    for (size_t i = 1; i < track.positions_m.size(); ++i)
      r.line(px(track.positions_m[i - 1].x()), py(track.positions_m[i - 1].y()), px(track.positions_m[i].x()),
             py(track.positions_m[i].y()), c, 3);
    if (!track.positions_m.empty()) {
      const auto& start = track.positions_m.front();
      r.fill_rect(px(start.x()) - 4, py(start.y()) - 4, px(start.x()) + 4, py(start.y()) + 4, c);
    }
    r.fill_rect(10, legend_y, 24, legend_y + 8, c);
    r.text(30, legend_y + 1, robot + " (" + track.species + ")", kBlack);
    legend_y += 16;
  }
  // Open coverage targets of the first robot that reported (every planner sees the same
  // fused map), coloured by why they are open.
  const std::pair<const char*, Rgb> states[] = {{"has_view", {230, 140, 0}},  {"given_up", {150, 0, 150}},
                                                {"no_viewpoint", {0, 150, 150}}, {"occluded", {0, 90, 200}},
                                                {"unreachable", {120, 120, 0}}, {"unassignable", {200, 0, 0}}};
  const std::vector<OpenTargetRow> open = record.latest_open_targets();
  if (!open.empty()) {
    const std::string& reporter = open.front().robot;
    for (const auto& t : open) {
      if (t.robot != reporter) continue;
      for (const auto& [name, colour] : states)
        if (t.state == name) r.fill_rect(px(t.center.x()) - 2, py(t.center.y()) - 2, px(t.center.x()) + 2,
                                         py(t.center.y()) + 2, colour);
    }
    int y = height - 20 - 14 * int(std::size(states));
    r.text(width - 200, y - 14, "OPEN TARGETS (" + reporter + ")", kBlack);
    for (const auto& [name, colour] : states) {
      r.fill_rect(width - 200, y, width - 192, y + 8, colour);
      r.text(width - 186, y + 1, name, kBlack);
      y += 14;
    }
  }
  r.text(10, height - 20, format("SCALE: %.1f M PER 100 PX", 100.0 / scale), kBlack);
  return r;
}

}  // namespace hexplore::evaluation
