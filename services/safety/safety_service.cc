#include "services/safety/safety_service.h"

#include <chrono>

#include "common/core/clock.h"
#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/radio/pose_schedule.h"
#include "common/radio/vec3_proto.h"
#include "common/safety/decision_trace.h"
#include "common/safety/fragment_proto.h"
#include "common/service/mission_state.h"
#include "common/service/options.h"
#include "common/service/status_values.h"
#include "common/transport/topics.h"

namespace hexplore::safety_service {
namespace {

namespace topics = transport::topics;

using radio::vec;

// Where a driver's pose, `age_s` old, puts the teammate now (along its velocity).
Eigen::Vector3d position_now(const v1::RobotPose& pose, double age_s) {
  return radio::extrapolate_pose(vec(pose.pose().position_m()), vec(pose.velocity_mps()), age_s,
                                 radio::PoseScheduleOptions{}.max_extrapolation_s);
}

// A teammate heard only through its driver's pose (its safety service is silent): moving along
// its velocity from where the pose puts it now, or standing still.
safety::Fragment fragment_from_pose(const std::string& id, const v1::RobotPose& pose, const Eigen::Vector3d& half_extents,
                            double age_s, double eta_p_m) {
  safety::Fragment f;
  f.robot_id = id;
  f.position_m = position_now(pose, age_s);
  Eigen::Vector3d v = vec(pose.velocity_mps());
  v.z() = 0.0;
  const double speed = v.norm();
  f.stationary = speed < 0.05;
  if (!f.stationary) {
    f.speed_mps = speed;
    f.waypoints_m.push_back(f.position_m + v / speed * eta_p_m);
  }
  Eigen::Vector3d half = vec(pose.body_half_extents_m());
  if (half.minCoeff() <= 0.0) half = half_extents;
  safety::body_box_any_yaw(f.position_m, half, f.box_min_m, f.box_max_m);
  return f;
}

// A fragment moved to where the teammate was measured: the box goes with it, and the trail
// keeps the predicted place too (hold-off keeps clear of both and everything between).
void move_to_measured(safety::Fragment& f, const Eigen::Vector3d& measured) {
  if (f.trail_m.empty()) f.trail_m.push_back(f.position_m);
  f.trail_m.push_back(measured);
  const Eigen::Vector3d moved = measured - f.position_m;
  f.position_m = measured;
  f.box_min_m += moved;
  f.box_max_m += moved;
}

}  // namespace

void SafetyService::setup(service::ServiceContext& context) {
  context_ = &context;
  robot_id_ = context.robot_id();
  const core::SpeciesConfig* species = context.species();
  if (species == nullptr) throw core::ConfigError(context.team().source_file, "robots." + robot_id_ + ".species",
                                                  "safety: robot has no known species");
  default_speed_mps_ = species->speed_mps;

  safety::SafetyOptions options;
  options.eta_p_m = context.team().params.eta_p_m;
  resolver_ = std::make_unique<safety::ConflictResolver>(robot_id_, species->body_half_extents_m, options);
  safety::SharingOptions sharing;
  sharing.heartbeat_s = context.team().params.eta_c_s;
  sharing.eta_p_m = options.eta_p_m;
  sharing_ = safety::FragmentSchedule(sharing);
  // Fragments arrive once per eta_c while nothing changes: one lost heartbeat, plus latency,
  // must not make a teammate look silent.
  obstacles_ = core::Liveness(std::max(context.team().params.liveness.obstacle_s, 2.0 * sharing.heartbeat_s + 0.5));

  const service::Options opts(context.arguments());
  sim_clock_ = opts.choice("decision-clock", sim_clock_ ? "sim" : "wall", {"sim", "wall"}) == "sim";
  mission_ = service::MissionState(opts.flag("wait-for-start", false));
  trace_ = service::open_trace_file(opts, "safety-" + robot_id_ + ".jsonl");

  auto& m = context.metrics();
  const metrics::Labels labels{{"robot", robot_id_}};
  conflicts_ = m.counter_family("hexplore_safety_conflicts_total", "Path conflicts with teammates detected")->add(labels);
  yields_ = m.counter_family("hexplore_safety_yields_total", "Times this robot yielded to a teammate")->add(labels);
  detours_ = m.counter_family("hexplore_safety_detours_total", "Detours around stationary teammates begun")->add(labels);
  deadlock_breaks_ =
      m.counter_family("hexplore_safety_deadlock_breaks_total", "Yields ended by the mutual-wait or timeout rules")
          ->add(labels);
  emergency_stops_ =
      m.counter_family("hexplore_safety_emergency_stops_total", "Emergency stops received from the station")->add(labels);
  yielding_ = m.gauge_family("hexplore_safety_yielding", "1 while this robot waits for a teammate")->add(labels);

  // Inputs: own driver (pose, team/pose) and planning (path); every teammate's driver and
  // safety (team/pose, team/path); the station (team/mission).
  context.connect(robot_id_, core::ServiceKind::kSim);
  context.connect(robot_id_, core::ServiceKind::kPlanning);
  for (const auto& robot : context.team().robots) {
    if (robot.id == robot_id_) continue;
    context.connect(robot.id, core::ServiceKind::kSim);
    context.connect(robot.id, core::ServiceKind::kSafety);
  }

  auto& sub = context.subscriber();
  sub.on<v1::RobotPose>(topics::pose(robot_id_), [this](const transport::Received<v1::RobotPose>& r) {
    on_pose(r.message, r.header.sim_time_ns());
  });
  sub.on<v1::ExecutablePath>(topics::path(robot_id_),
                             [this](const transport::Received<v1::ExecutablePath>& r) { on_path(r.message); });
  sub.on<v1::RobotPose>(std::string(topics::kTeamPose), [this](const transport::Received<v1::RobotPose>& r) {
    const std::string& id = r.header.robot_id();
    if (id == robot_id_ || id.empty()) return;
    Peer& peer = peers_[id];
    peer.pose = r.message;
    peer.pose_ns = context_->now_ns();
    peer.pose_sim_ns = r.header.sim_time_ns();
  });
  sub.on<v1::PathFragment>(std::string(topics::kTeamPath), [this](const transport::Received<v1::PathFragment>& r) {
    const std::string& id = r.header.robot_id();
    if (id == robot_id_ || id.empty()) return;
    Peer& peer = peers_[id];
    peer.fragment = safety::from_proto(r.message, id);
    if (!r.message.has_body_box_m()) {
      // The radio leaves the box out: it is the sender's species body around its position.
      safety::body_box_any_yaw(peer.fragment->position_m, half_extents_of(id), peer.fragment->box_min_m, peer.fragment->box_max_m);
    }
    peer.fragment_ns = context_->now_ns();
    peer.fragment_sim_ns = r.header.sim_time_ns();
  });
  context.on_mission([this](const v1::MissionCommand& command) { on_mission(command); });

  const auto period = std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::duration<double>(resolver_->options().cycle_s));
  context.loop().add_timer(period, [this] {
    // On the sim clock, decisions follow the poses (see on_pose) while sim time is known.
    if (!sim_clock_ || sim_time_ns_ == 0) cycle();
  });
  context.set_state(v1::SERVICE_STATE_RUNNING, mission_.active() ? "waiting for pose" : mission_.reason());
}

void SafetyService::on_shutdown(service::ServiceContext&) {
  // Leave the robot standing, not driving the last approved path unattended.
  halt("safety service stopped");
}

double SafetyService::now_s() const {
  // Sim time when the driver provides it (so timeouts scale with a faster-than-real-time sim).
  return sim_time_ns_ > 0 ? core::ns_to_s(sim_time_ns_) : core::ns_to_s(context_->now_ns());
}

void SafetyService::on_pose(const v1::RobotPose& pose, int64_t sim_time_ns) {
  position_ = vec(pose.pose().position_m());
  if (sim_time_ns > 0) sim_time_ns_ = sim_time_ns;
  if (sim_clock_ && sim_time_ns > 0) {
    const int64_t period_ns = core::s_to_ns(resolver_->options().cycle_s);
    if (last_decision_sim_ns_ < 0 || sim_time_ns - last_decision_sim_ns_ >= period_ns || sim_time_ns < last_decision_sim_ns_) {
      last_decision_sim_ns_ = sim_time_ns;
      cycle();
    }
  }
}

void SafetyService::on_path(const v1::ExecutablePath& path) {
  desired_.clear();
  for (const auto& w : path.waypoints_m()) desired_.push_back(vec(w));
  path_speed_mps_ = path.speed_mps() > 0.0 ? path.speed_mps() : default_speed_mps_;
  look_at_.reset();
  if (path.has_goal() && path.goal().has_look_at_m()) look_at_ = vec(path.goal().look_at_m());
}

void SafetyService::on_mission(const v1::MissionCommand& command) {
  const bool was_active = mission_.active();
  const auto state = mission_.apply(command, robot_id_);
  if (!state) return;
  switch (*state) {
    case service::MissionState::State::kEmergency:
      emergency_stops_->increment();
      core::LogLine(core::LogLevel::kWarn, "safety") << robot_id_ << ": " << mission_.reason();
      halt(mission_.reason());  // at once, not at the next cycle
      break;
    case service::MissionState::State::kStopped:
      halt(mission_.reason());
      break;
    case service::MissionState::State::kActive:
      if (!was_active) core::LogLine(core::LogLevel::kInfo, "safety") << robot_id_ << ": mission start";
      break;
  }
}

void SafetyService::halt(const std::string& reason) {
  resolver_->reset();
  safety::Decision stop;
  stop.kind = safety::DecisionKind::kStop;
  stop.reason = reason;
  last_ = stop;
  publish(safety::to_motion_command(stop));
  if (position_) share_fragment();
}

double SafetyService::age_s(int64_t received_ns, int64_t sent_sim_ns) const {
  // Sim time when both sides have it (a fast sim ages messages faster than the wall clock).
  if (sim_time_ns_ > 0 && sent_sim_ns > 0) return core::ns_to_s(sim_time_ns_ - sent_sim_ns);
  return core::ns_to_s(context_->now_ns() - received_ns);
}

bool SafetyService::stale(int64_t received_ns, int64_t sent_sim_ns) const {
  return !obstacles_.fresh(age_s(received_ns, sent_sim_ns));
}

Eigen::Vector3d SafetyService::half_extents_of(const std::string& id) const {
  const core::RobotConfig* robot = context_->team().find_robot(id);
  const core::SpeciesConfig* species = robot ? context_->team().find_species(robot->species) : nullptr;
  return species ? species->body_half_extents_m : Eigen::Vector3d(0.5, 0.5, 0.5);
}

bool SafetyService::pose_is_newer(const Peer& peer) const {
  // Sim stamps when both messages carry one (they order sends, not arrivals); else arrival.
  if (peer.pose_sim_ns > 0 && peer.fragment_sim_ns > 0) return peer.pose_sim_ns > peer.fragment_sim_ns;
  return peer.pose_ns > peer.fragment_ns;
}

std::vector<safety::Fragment> SafetyService::peers() const {
  std::vector<safety::Fragment> out;
  for (const auto& [id, peer] : peers_) {
    if (peer.fragment && !stale(peer.fragment_ns, peer.fragment_sim_ns)) {
      // Where the teammate is by now, driving the path it shared.
      safety::Fragment f = safety::advance_fragment(*peer.fragment, age_s(peer.fragment_ns, peer.fragment_sim_ns),
                                    resolver_->options().eta_p_m);
      if (peer.pose && pose_is_newer(peer)) {
        // Its driver has spoken since: the body is where the pose puts it (a stop decided a
        // moment ago still rolls on until the driver hears it; a fragment predicts, a pose
        // measures). Between the two it may be anywhere, so the trail joins them.
        move_to_measured(f, position_now(*peer.pose, age_s(peer.pose_ns, peer.pose_sim_ns)));
      }
      out.push_back(std::move(f));
    } else if (peer.pose) {
      safety::Fragment f = fragment_from_pose(id, *peer.pose, half_extents_of(id), age_s(peer.pose_ns, peer.pose_sim_ns),
                                      resolver_->options().eta_p_m);
      if (stale(peer.pose_ns, peer.pose_sim_ns)) {
        // Silent (radio or services gone): its body is still where it was last seen, and it
        // is no longer known to move. A stopped box to drive around, never forgotten.
        f.stationary = true;
        f.speed_mps = 0.0;
        f.waypoints_m.clear();
      }
      out.push_back(std::move(f));
    }
  }
  return out;
}

void SafetyService::cycle() {
  if (!position_) {
    context_->set_state(v1::SERVICE_STATE_DEGRADED, "waiting for pose on " + topics::pose(robot_id_));
    return;
  }
  if (!mission_.active()) {
    // Repeat the stop: a driver that missed the first one still halts within a cycle.
    publish(safety::to_motion_command(last_));
    share_fragment();
    context_->set_state(v1::SERVICE_STATE_RUNNING, mission_.reason());
    return;
  }
  const std::vector<safety::Fragment> teammates = peers();
  const safety::Decision decision = resolver_->decide(*position_, desired_, path_speed_mps_, teammates, now_s());
  if (trace_.is_open() && safety::worth_tracing(decision, last_, *position_, teammates))
    trace_ << safety::decision_trace_json(now_s(), *position_, decision, teammates) << std::flush;
  if (decision.yielding_to != last_.yielding_to) {
    // Waiting starts and ends are rare and worth seeing in the log; every decision is not.
    if (decision.yielding_to.empty()) {
      core::LogLine(core::LogLevel::kInfo, "safety") << robot_id_ << ": no longer waiting for " << last_.yielding_to;
    } else {
      core::LogLine(core::LogLevel::kInfo, "safety") << robot_id_ << ": " << decision.reason;
    }
  }
  last_ = decision;
  v1::MotionCommand command = safety::to_motion_command(decision);
  if (decision.kind == safety::DecisionKind::kFollow && look_at_) {
    auto* follow = command.mutable_follow();
    follow->mutable_look_at_m()->set_x(look_at_->x());
    follow->mutable_look_at_m()->set_y(look_at_->y());
    follow->mutable_look_at_m()->set_z(look_at_->z());
    follow->set_has_look_at(true);
  }
  publish(command);
  share_fragment();

  const safety::ResolverCounters& c = resolver_->counters();
  conflicts_->increment(static_cast<double>(c.conflicts_detected - reported_.conflicts_detected));
  yields_->increment(static_cast<double>(c.yields - reported_.yields));
  detours_->increment(static_cast<double>(c.detours - reported_.detours));
  deadlock_breaks_->increment(static_cast<double>(c.deadlock_breaks - reported_.deadlock_breaks));
  reported_ = c;
  yielding_->set(decision.yielding_to.empty() ? 0.0 : 1.0);
  std::string detail = decision.kind == safety::DecisionKind::kFollow ? "following" : "stopped";
  if (!decision.reason.empty()) detail += ": " + decision.reason;
  context_->set_state(v1::SERVICE_STATE_RUNNING, detail);
}

void SafetyService::publish(const v1::MotionCommand& command) {
  context_->publisher().publish(topics::motion(robot_id_), command, sim_time_ns_);
}

void SafetyService::share_fragment() {
  if (!position_) return;
  // Outside an active mission the robot stands still whatever the resolver last decided.
  safety::Fragment f = resolver_->fragment(*position_);
  if (!mission_.active()) {
    f.stationary = true;
    f.speed_mps = 0.0;
    f.waypoints_m.clear();
    f.yielding_to.clear();
  }
  // On the radio only when teammates' prediction of the last one no longer holds.
  const double now = now_s();
  if (!sharing_.due(now, f)) return;
  context_->publisher().publish(topics::kTeamPath, safety::to_proto(f), sim_time_ns_);
  sharing_.sent(now, f);
}

void SafetyService::fill_status(v1::ServiceStatus& status) {
  const safety::ResolverCounters& c = resolver_ ? resolver_->counters() : safety::ResolverCounters{};
  const service::StatusValues add(status);
  add("conflicts", static_cast<double>(c.conflicts_detected));
  add("yields", static_cast<double>(c.yields));
  add("detours", static_cast<double>(c.detours));
  add("emergency_stops", emergency_stops_ ? emergency_stops_->value() : 0.0);
}

}  // namespace hexplore::safety_service
