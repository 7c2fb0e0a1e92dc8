#include "common/sim/terrain_probe.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hexplore::sim {
namespace {

// Sample points sit slightly inside the body outline so a robot can pass a door whose
// width only just exceeds its own.
constexpr double kInset = 0.95;
constexpr double kSearchBelowM = 1.0;
// Support is searched from this far above a step's reach, so float noise on a riser edge does
// not hide the tread, while an overhang just above the step height stays above the search.
constexpr double kAboveStepM = 0.03;
// Rotation per checked pose of a turn in place: a body corner 0.6 m out moves about 5 cm,
// like a substep of a move.
constexpr double kMaxTurnStepRad = 5.0 * M_PI / 180.0;

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

}  // namespace

const char* to_string(TerrainVerdict v) {
  switch (v) {
    case TerrainVerdict::kOk: return "ok";
    case TerrainVerdict::kNoGround: return "no ground";
    case TerrainVerdict::kStep: return "step too high";
    case TerrainVerdict::kSlope: return "slope too steep";
    case TerrainVerdict::kClearance: return "too little clearance";
    case TerrainVerdict::kObstacle: return "obstacle ahead";
  }
  return "unknown";
}

TerrainProbe::TerrainProbe(const RayCaster& caster, const core::SpeciesConfig& species)
    : caster_(caster), species_(species) {}

std::optional<double> TerrainProbe::support_height(const Eigen::Vector2d& xy, double z_ref) const {
  const double above = species_.max_step_m + kAboveStepM;
  const double top = z_ref + above;
  const float t = caster_.cast(Eigen::Vector3f(static_cast<float>(xy.x()), static_cast<float>(xy.y()), static_cast<float>(top)),
                               -Eigen::Vector3f::UnitZ(), 0.0f, static_cast<float>(above + kSearchBelowM));
  if (t == RayCaster::kMiss) return std::nullopt;
  return top - t;
}

Eigen::Vector2d TerrainProbe::sample_point(const Eigen::Vector2d& xy, double yaw, int k) const {
  const int ix = k / 3 - 1, iy = k % 3 - 1;
  const Eigen::Vector2d fwd(std::cos(yaw), std::sin(yaw)), left(-fwd.y(), fwd.x());
  return xy + ix * kInset * species_.body_half_extents_m.x() * fwd + iy * kInset * species_.body_half_extents_m.y() * left;
}

std::optional<Footprint> TerrainProbe::footprint(const Eigen::Vector2d& xy, double yaw,
                                                 const std::array<double, 9>& z_refs) const {
  Footprint f;
  f.xy = xy;
  f.yaw = yaw;
  double sum = 0.0;
  for (int k = 0; k < 9; ++k) {
    const auto h = support_height(sample_point(xy, yaw, k), z_refs[k]);
    if (!h) return std::nullopt;
    f.heights[k] = *h;
    sum += *h;
  }
  f.ground_z = sum / 9.0;
  const auto& h = f.heights;
  const double front = (h[6] + h[7] + h[8]) / 3, back = (h[0] + h[1] + h[2]) / 3;
  const double left = (h[2] + h[5] + h[8]) / 3, right = (h[0] + h[3] + h[6]) / 3;
  f.pitch = std::atan2(front - back, 2 * kInset * species_.body_half_extents_m.x());
  f.roll = std::atan2(left - right, 2 * kInset * species_.body_half_extents_m.y());
  return f;
}

std::optional<Footprint> TerrainProbe::footprint(const Eigen::Vector2d& xy, double yaw, double z_ref) const {
  std::array<double, 9> refs;
  refs.fill(z_ref);
  return footprint(xy, yaw, refs);
}

TerrainVerdict TerrainProbe::check(const Footprint& to, const Footprint* from, Travel travel) const {
  // Slope over the body's length and width. Nine samples alias on stairs (a sample on a
  // nosing, the next on a tread), so half a step of height difference is tolerated: a
  // tracked body bridges the nosings and feels the staircase's mean slope.
  const double tan_slope = std::tan(species_.max_slope_deg * M_PI / 180.0);
  const double length = 2 * kInset * species_.body_half_extents_m.x(), width = 2 * kInset * species_.body_half_extents_m.y();
  const double tolerance = 0.5 * species_.max_step_m;
  if (std::abs(std::tan(to.pitch)) * length > length * tan_slope + tolerance ||
      std::abs(std::tan(to.roll)) * width > width * tan_slope + tolerance)
    return TerrainVerdict::kSlope;
  if (from)
    for (int k = 0; k < 9; ++k)
      if (std::abs(to.heights[k] - from->heights[k]) > species_.max_step_m) return TerrainVerdict::kStep;
  // Clearance: the body's height must be free above every sample point. Something low on a
  // sample's ground (a block taller than a step: the support search started inside it) is a
  // step; something higher up is an overhang the body does not fit under.
  const float up_from = 0.05f;
  const float clearance = static_cast<float>(species_.min_clearance_m);
  for (int k = 0; k < 9; ++k) {
    const Eigen::Vector2d p = sample_point(to.xy, to.yaw, k);
    const Eigen::Vector3f o(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(to.heights[k]));
    if (clearance <= up_from) continue;
    const float t = caster_.cast(o, Eigen::Vector3f::UnitZ(), up_from, clearance);
    if (t != RayCaster::kMiss) return t < 0.5f * clearance ? TerrainVerdict::kStep : TerrainVerdict::kClearance;
  }
  // Obstacles in the way: rays along the pitched heading (backward when reversing, both ways
  // when turning) at two heights within the body, from its centre line and both sides,
  // reaching just past its end.
  const Eigen::Vector3d dir(std::cos(to.pitch) * std::cos(to.yaw), std::cos(to.pitch) * std::sin(to.yaw),
                            std::sin(to.pitch));
  const Eigen::Vector2d left(-std::sin(to.yaw), std::cos(to.yaw));
  const double low = species_.max_step_m + 0.5 * (species_.min_clearance_m - species_.max_step_m);
  const double high = std::max(low, species_.min_clearance_m - 0.03);
  // Moving, the rays look a little ahead of the body; turning, they sweep its outline.
  const float reach = static_cast<float>(species_.body_half_extents_m.x() + (travel == Travel::kTurn ? 0.02 : 0.1));
  std::vector<Eigen::Vector3f> dirs;
  if (travel != Travel::kBackward) dirs.push_back(dir.cast<float>());
  if (travel != Travel::kForward) dirs.push_back(-dir.cast<float>());
  for (const auto& d : dirs)
    for (double h : {low, high})
      for (int side = -1; side <= 1; ++side) {
        const Eigen::Vector2d p = to.xy + side * kInset * species_.body_half_extents_m.y() * left;
        const Eigen::Vector3f o(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(to.ground_z + h));
        if (caster_.occluded(o, d, 0.0f, reach)) return TerrainVerdict::kObstacle;
      }
  return TerrainVerdict::kOk;
}

std::optional<Footprint> TerrainProbe::turn(const Footprint& from, double yaw, TerrainVerdict* why) const {
  const double shorter = wrap(yaw - from.yaw);
  if (std::abs(shorter) < 1e-12) return from;
  const double longer = shorter > 0 ? shorter - 2 * M_PI : shorter + 2 * M_PI;
  std::optional<TerrainVerdict> first;
  for (const double sweep : {shorter, longer}) {
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / kMaxTurnStepRad)));
    Footprint f = from;
    TerrainVerdict v = TerrainVerdict::kOk;
    for (int s = 1; s <= steps && v == TerrainVerdict::kOk; ++s) {
      const double a = s == steps ? wrap(yaw) : wrap(from.yaw + sweep * s / steps);
      const auto next = footprint(from.xy, a, f.heights);
      v = next ? check(*next, &f, Travel::kTurn) : TerrainVerdict::kNoGround;
      if (v == TerrainVerdict::kOk) f = *next;
    }
    if (v == TerrainVerdict::kOk) return f;
    if (!first) first = v;
  }
  if (why) *why = *first;
  return std::nullopt;
}

Eigen::Isometry3d TerrainProbe::body_pose(const Footprint& f) const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(f.yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(-f.pitch, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(f.roll, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  pose.linear() = r;
  pose.translation() = Eigen::Vector3d(f.xy.x(), f.xy.y(), f.ground_z) + r * Eigen::Vector3d(0, 0, species_.body_half_extents_m.z());
  return pose;
}

}  // namespace hexplore::sim
