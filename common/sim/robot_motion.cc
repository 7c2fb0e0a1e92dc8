#include "common/sim/robot_motion.h"

#include <cmath>
#include <sstream>

#include "common/sim/local_maneuver.h"
#include "common/sim/scene_error.h"

namespace hexplore::sim {
namespace {

constexpr double kMaxSubstepM = 0.05;   // small enough that a climbable slope never reads as a step
constexpr double kWaypointReachedM = 1e-3;
// Leading waypoints closer than this are passed by: a path that starts at the robot, or at
// the nearest point of a path it strayed from a little (the safety layer re-sends the
// remaining path every cycle), is followed by steering for the point after, as a path
// follower does, not by turning in place towards a point a few centimetres aside.
constexpr double kPassByM = 0.35;
// How far back a body may retrace its own poses to find room to turn: 40 moves of up to
// kMaxSubstepM, or turns.
constexpr size_t kTrailPoses = 40;
// A manoeuvre ends within ManeuverOptions::reach_m of its waypoint, which then counts as
// reached; a waypoint this close to one a manoeuvre was searched for is the same goal.
constexpr double kManeuverReachM = 0.1;
constexpr double kSameGoalM = 0.05;

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

// Whether `body` overlaps a teammate's body (own box, by `self`, excluded).
bool touches_a_teammate(const ProxyBox& body, std::span<const ProxyBox> teammates, uint32_t self) {
  for (const ProxyBox& mate : teammates)
    if (mate.id != self && boxes_overlap(body, mate)) return true;
  return false;
}

}  // namespace

const char* to_string(MotionState s) {
  switch (s) {
    case MotionState::kIdle: return "idle";
    case MotionState::kMoving: return "moving";
    case MotionState::kStopped: return "stopped";
    case MotionState::kBlocked: return "blocked";
    case MotionState::kEmergencyStop: return "emergency stop";
  }
  return "unknown";
}

RobotMotion::RobotMotion(const RayCaster& caster, const core::SpeciesConfig& species, const Eigen::Vector3d& start,
                         double yaw_rad, uint32_t id)
    : probe_(caster, species), id_(id) {
  auto where = [&] {
    std::ostringstream s;
    s << species.name << " start (" << start.x() << ", " << start.y() << ", " << start.z() << ")";
    return s.str();
  };
  const auto f = probe_.footprint(start.head<2>(), yaw_rad, start.z());
  if (!f) throw SceneError(where(), "no ground under the robot's footprint");
  const TerrainVerdict v = probe_.check(*f, nullptr);
  if (v == TerrainVerdict::kSlope || v == TerrainVerdict::kClearance || v == TerrainVerdict::kStep)
    throw SceneError(where(), std::string("the robot cannot stand there: ") + to_string(v));
  footprint_ = *f;
}

Eigen::Vector3d RobotMotion::ground_position() const {
  return {footprint_.xy.x(), footprint_.xy.y(), footprint_.ground_z};
}

ProxyBox RobotMotion::body_box() const {
  ProxyBox b = body_box_at(probe_, footprint_);
  b.id = id_;
  return b;
}

void RobotMotion::follow(std::vector<Eigen::Vector3d> waypoints, double speed_mps) {
  if (state_ == MotionState::kEmergencyStop) return;
  path_ = std::move(waypoints);
  next_ = 0;
  // A manoeuvre under way is finished first (it is short, and the safety layer re-sends the
  // path every cycle); a path to nowhere ends it.
  if (path_.empty()) maneuver_.clear();
  pass_by_near_waypoints();
  speed_mps_ = speed_mps > 0 ? std::min(speed_mps, species().speed_mps) : species().speed_mps;
  block_reason_ = TerrainVerdict::kOk;
  reversing_ = false;
  state_ = path_.empty() ? MotionState::kIdle : MotionState::kMoving;
}

void RobotMotion::stop() {
  if (state_ == MotionState::kEmergencyStop) return;
  path_.clear();
  maneuver_.clear();
  next_ = 0;
  state_ = MotionState::kStopped;
}

void RobotMotion::emergency_stop() {
  path_.clear();
  maneuver_.clear();
  next_ = 0;
  state_ = MotionState::kEmergencyStop;
}

void RobotMotion::release() {
  if (state_ == MotionState::kEmergencyStop) state_ = MotionState::kIdle;
}

void RobotMotion::remember(const Footprint& f) {
  trail_.push_back(f);
  if (trail_.size() > kTrailPoses) trail_.pop_front();
}

void RobotMotion::block(TerrainVerdict why) {
  block_reason_ = why;
  reversing_ = false;
  state_ = MotionState::kBlocked;
  path_.clear();
  maneuver_.clear();
  next_ = 0;
}

void RobotMotion::pass_by_near_waypoints() {
  while (next_ + 1 < path_.size() && (path_[next_].head<2>() - footprint_.xy).norm() < kPassByM) ++next_;
}

void RobotMotion::next_waypoint() {
  ++next_;
  reversing_ = false;
  maneuver_goal_.reset();
}

bool RobotMotion::start_maneuver(std::span<const ProxyBox> teammates) {
  const Eigen::Vector2d goal = path_[next_].head<2>();
  // Once per waypoint: where no manoeuvre reaches it, searching again every cycle would only
  // cost time (the safety layer re-sends the same path).
  if (maneuver_goal_ && (*maneuver_goal_ - goal).norm() < kSameGoalM) return false;
  maneuver_goal_ = goal;
  std::vector<ProxyBox> others;
  for (const ProxyBox& mate : teammates)
    if (mate.id != id_) others.push_back(mate);
  const auto poses = plan_maneuver(probe_, footprint_, goal, others);
  if (!poses || poses->empty()) return false;
  maneuver_.assign(poses->begin(), poses->end());
  reversing_ = false;
  ++maneuvers_;
  return true;
}

double RobotMotion::drive_maneuver(double budget, std::span<const ProxyBox> teammates) {
  const Footprint& to = maneuver_.front();
  // Teammates move meanwhile: one now in the way ends the manoeuvre (blocked: the planner and
  // the safety layer take it from there).
  if (touches_a_teammate(body_box_at(probe_, to), teammates, id_)) {
    block(TerrainVerdict::kObstacle);
    return budget;
  }
  const Eigen::Vector2d delta = to.xy - footprint_.xy;
  const double dist = delta.norm();
  const double move = std::min({budget, dist, kMaxSubstepM});
  const Eigen::Vector3d a = ground_position();
  remember(footprint_);
  if (move >= dist - 1e-9) {  // a turn (no distance), or the rest of a move
    footprint_ = to;
    maneuver_.pop_front();
  } else if (const auto part = probe_.footprint(footprint_.xy + move * delta / dist, to.yaw, footprint_.heights)) {
    footprint_ = *part;  // within a move checked whole when it was planned
  } else {
    block(TerrainVerdict::kNoGround);
    return budget;
  }
  odometry_m_ += (ground_position() - a).norm();
  if (maneuver_.empty() && next_ < path_.size()) {
    // At the waypoint it was for (or the path changed meanwhile): on along the path from here.
    if ((path_[next_].head<2>() - footprint_.xy).norm() <= kManeuverReachM) next_waypoint();
    pass_by_near_waypoints();
  }
  return move;
}

void RobotMotion::step(double dt_s, std::span<const ProxyBox> teammates) {
  const Eigen::Vector3d before = body_pose().translation();
  double budget = state_ == MotionState::kMoving ? speed_mps_ * dt_s : 0.0;
  while (state_ == MotionState::kMoving && budget > 1e-9) {
    if (!maneuver_.empty()) {
      budget -= drive_maneuver(budget, teammates);
      continue;
    }
    if (next_ >= path_.size()) {
      state_ = MotionState::kIdle;
      break;
    }
    const Eigen::Vector2d delta = path_[next_].head<2>() - footprint_.xy;
    const double dist = delta.norm();
    if (dist < kWaypointReachedM) {
      next_waypoint();
      continue;
    }
    // Face the waypoint (turning in place), or, when the body cannot turn that far where it
    // stands, put its back to the waypoint and reverse there; kept until the waypoint.
    const double heading = std::atan2(delta.y(), delta.x());
    const double yaw = reversing_ ? wrap(heading + M_PI) : heading;
    if (std::abs(wrap(yaw - footprint_.yaw)) > 1e-6) {
      TerrainVerdict why = TerrainVerdict::kOk;
      auto turned = probe_.turn(footprint_, yaw, &why);
      if (!turned && !reversing_) {
        turned = probe_.turn(footprint_, wrap(heading + M_PI));
        reversing_ = turned.has_value();
      }
      if (!turned && !trail_.empty() &&
          !touches_a_teammate(body_box_at(probe_, trail_.back(), ManeuverOptions{}.teammate_margin_m), teammates, id_)) {
        // No room to turn here: back up one pose the way we came (each was reached by a
        // checked move or turn, so undoing it is free of the scene, not of a teammate that
        // came up behind since: the safety layer approved the path ahead, not this, and a
        // SLUGCAT backing up so touched an MR1000 waiting behind it, multi-building seed 2 at
        // 1,028 s, services/sim/README.md) and try again from there.
        const Footprint back = trail_.back();
        trail_.pop_back();
        const double step = (back.xy - footprint_.xy).norm();
        const Eigen::Vector3d a = ground_position();
        footprint_ = back;
        odometry_m_ += (ground_position() - a).norm();
        budget -= step;
        continue;
      }
      if (!turned) {
        if (start_maneuver(teammates)) continue;
        return block(why);
      }
      if (std::abs(wrap(turned->yaw - footprint_.yaw)) > 1e-3) remember(footprint_);
      footprint_ = *turned;
    }
    const double move = std::min({budget, dist, kMaxSubstepM});
    const Eigen::Vector2d xy = footprint_.xy + move * delta / dist;
    const auto next = probe_.footprint(xy, footprint_.yaw, footprint_.heights);
    if (!next) return block(TerrainVerdict::kNoGround);
    const TerrainVerdict v = probe_.check(*next, &footprint_, reversing_ ? Travel::kBackward : Travel::kForward);
    if (v != TerrainVerdict::kOk) {
      if (start_maneuver(teammates)) continue;
      return block(v);
    }
    const Eigen::Vector3d a = ground_position();
    remember(footprint_);
    footprint_ = *next;
    odometry_m_ += (ground_position() - a).norm();
    budget -= move;
  }
  if (state_ == MotionState::kMoving && next_ < path_.size() &&
      (path_[next_].head<2>() - footprint_.xy).norm() < kWaypointReachedM)
    next_waypoint();
  if (state_ == MotionState::kMoving && next_ >= path_.size()) state_ = MotionState::kIdle;
  velocity_ = dt_s > 0 ? Eigen::Vector3d((body_pose().translation() - before) / dt_s) : Eigen::Vector3d::Zero();

  // Contacts: a collision is counted when a teammate's body starts touching ours.
  const ProxyBox mine = body_box();
  std::set<uint32_t> now;
  for (const auto& other : teammates)
    if (other.id != id_ && boxes_overlap(mine, other)) now.insert(other.id);
  for (auto id : now)
    if (!touching_.count(id)) ++collisions_;
  touching_ = std::move(now);
}

double trajectory_length(std::span<const Eigen::Vector3d> points) {
  double sum = 0.0;
  for (size_t i = 1; i < points.size(); ++i) sum += (points[i] - points[i - 1]).norm();
  return sum;
}

}  // namespace hexplore::sim
