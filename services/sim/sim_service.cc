#include "services/sim/sim_service.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "common/core/clock.h"
#include "common/core/config_error.h"
#include "common/core/log.h"
#include "common/radio/vec3_proto.h"
#include "common/service/options.h"
#include "common/service/status_values.h"
#include "common/sim/mesh_io.h"
#include "common/core/rng.h"
#include "common/sim/scene_error.h"
#include "common/sim/sim_proto.h"
#include "common/transport/topics.h"

namespace hexplore::sim_service {
namespace {

namespace topics = transport::topics;

using radio::vec;

}  // namespace

SimOptions SimOptions::from_arguments(const std::map<std::string, std::string>& args) {
  const service::Options opts(args);
  SimOptions o;
  o.real_time_factor = opts.number("real-time-factor", o.real_time_factor, 0.01, 100.0);
  o.step_hz = opts.number("step-hz", o.step_hz, 1.0, 1000.0);
  o.scan_hz = opts.number("scan-hz", o.scan_hz, 0.01, 100.0);
  o.scene_dir = opts.text("scene-dir", o.scene_dir);
  return o;
}

void SimService::load_world(service::ServiceContext& context, const std::string& scene_dir) {
  const auto& team = context.team();
  scene_ = sim::load_team_scene(team);
  const std::string& scene = scene_.name;  // the resolved name or path
  caster_ = std::make_unique<sim::RayCaster>(scene_.mesh);
  if (!scene_dir.empty() && sim::is_builtin_scene(scene)) {
    std::filesystem::create_directories(scene_dir);
    const auto path = std::filesystem::path(scene_dir) / (scene + "_seed" + std::to_string(team.params.seed) + ".ply");
    sim::write_mesh(scene_.mesh, path.string());
  }
}

void SimService::setup(service::ServiceContext& context) {
  context_ = &context;
  robot_id_ = context.robot_id();
  const core::RobotConfig* robot = context.robot();
  const core::SpeciesConfig* species = context.species();
  if (!robot || !species) throw core::ConfigError(context.team().source_file, "robots", "sim needs a robot of the team");

  const SimOptions options = SimOptions::from_arguments(context.arguments());
  bodies_ = core::Liveness(context.team().params.liveness.sim_body_s);
  const double rtf = options.real_time_factor;
  clock_ = sim::SimClock(rtf);
  step_ns_ = static_cast<int64_t>(1e9 / options.step_hz);
  scan_period_ns_ = static_cast<int64_t>(1e9 / options.scan_hz);

  try {
    load_world(context, options.scene_dir);
    const uint32_t index = static_cast<uint32_t>(*context.team().robot_index(robot_id_));
    motion_ = std::make_unique<sim::RobotMotion>(*caster_, *species, robot->start_position_m,
                                            robot->start_yaw_deg * M_PI / 180.0, index + 1);
  } catch (const sim::SceneError& e) {
    throw core::ConfigError(context.team().source_file, "scene", e.what());
  }

  auto& m = context.metrics();
  const metrics::Labels labels = {{"robot", robot_id_}};
  auto* scan_family = m.histogram_family("hexplore_sim_scan_seconds", "Time to cast one LiDAR frame",
                                         metrics::latency_buckets_s());
  auto* rays_family = m.gauge_family("hexplore_sim_rays_per_second", "Rays cast per second in the last LiDAR frame");
  const uint64_t robot_seed = core::sim_seed(context.team().params.seed, *context.team().robot_index(robot_id_) + 1);
  for (size_t i = 0; i < species->lidars.size(); ++i) {
    Sensor s;
    s.model = std::make_unique<sim::LidarModel>(species->lidars[i], core::sim_seed(robot_seed, i + 1));
    const metrics::Labels sensor_labels = {{"robot", robot_id_}, {"sensor", species->lidars[i].name}};
    s.scan_seconds = scan_family->add(sensor_labels);
    s.rays_per_second = rays_family->add(sensor_labels);
    sensors_.push_back(std::move(s));
  }
  blocked_ = m.counter_family("hexplore_sim_blocked_total", "Times the robot stopped on terrain beyond its limits")
                 ->add(labels);
  collisions_ = m.counter_family("hexplore_sim_collisions_total", "Contacts between this robot and a teammate")->add(labels);
  maneuvers_ = m.counter_family("hexplore_sim_maneuvers_total",
                                "Manoeuvres round an obstacle the path's straight line ran into (local_maneuver.h)")
                   ->add(labels);
  emergency_stops_ = m.counter_family("hexplore_sim_emergency_stops_total", "Emergency stops obeyed")->add(labels);
  odometry_m_ = m.gauge_family("hexplore_sim_odometry_meters", "Trajectory length travelled")->add(labels);
  sim_time_s_ = m.gauge_family("hexplore_sim_time_seconds", "Simulation time")->add(labels);
  auto* position = m.gauge_family("hexplore_sim_position_meters", "Body position in the scene frame");
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) position_m_[a] = position->add({{"robot", robot_id_}, {"axis", axes[a]}});
  auto* state = m.gauge_family("hexplore_sim_motion_state", "1 for the robot's current motion state, 0 for the others");
  for (sim::MotionState s : {sim::MotionState::kIdle, sim::MotionState::kMoving, sim::MotionState::kStopped, sim::MotionState::kBlocked,
                        sim::MotionState::kEmergencyStop})
    motion_state_[s] = state->add({{"robot", robot_id_}, {"state", sim::to_string(s)}});

  if (transport::RadioMedium* radio = context.radio()) radio_slot_ = radio->roster().slot(robot_id_);

  // Inputs: own safety (motion), teammates' sims (sim/body), the station (mission).
  context.connect(robot_id_, core::ServiceKind::kSafety);
  for (const auto& other : context.team().robots)
    if (other.id != robot_id_) context.connect(other.id, core::ServiceKind::kSim);
  auto& sub = context.subscriber();
  sub.on<v1::MotionCommand>(topics::motion(robot_id_),
                            [this](const transport::Received<v1::MotionCommand>& r) { on_motion(r.message); });
  sub.on<v1::RobotPose>(std::string(topics::kSimBody), [this](const transport::Received<v1::RobotPose>& r) {
    on_body(r.header.robot_id(), r.message);
  });
  context.on_mission([this](const v1::MissionCommand& command) { on_mission(command); });

  // In lockstep the loop's clock is sim time itself: one step per step period, as fast as the
  // team can go; otherwise the real-time factor turns a sim step into a wall-clock period.
  const auto period = std::chrono::nanoseconds(
      context.lockstep() ? step_ns_ : std::max<int64_t>(clock_.wall_period_ns(step_ns_), 1'000'000));
  context.loop().add_timer(period, [this] { tick(); });
  const Eigen::Vector3d at = motion_->ground_position();
  char where[96];
  std::snprintf(where, sizeof(where), "(%.2f, %.2f, %.2f)", at.x(), at.y(), at.z());
  core::LogLine(core::LogLevel::kInfo, "sim") << robot_id_ << ": " << scene_.name << " (" << scene_.mesh.triangle_count()
                                              << " triangles), " << species->name << " at " << where
                                              << (context.lockstep() ? std::string(", lockstep") : ", rtf " + std::to_string(rtf));
  context.set_state(v1::SERVICE_STATE_RUNNING, sim::to_string(motion_->state()));
  update_gauges();
  publish_pose();
}

void SimService::on_shutdown(service::ServiceContext&) {
  if (motion_) motion_->stop();
}

void SimService::on_motion(const v1::MotionCommand& command) {
  if (command.has_follow()) {
    std::vector<Eigen::Vector3d> path;
    for (const auto& w : command.follow().waypoints_m()) path.push_back(vec(w));
    motion_->follow(std::move(path), command.follow().speed_mps());
    if (command.follow().has_look_at()) look_at_ = vec(command.follow().look_at_m());
    else look_at_.reset();
  } else if (command.has_stop()) {
    motion_->stop();
  }
}

void SimService::on_mission(const v1::MissionCommand& command) {
  const auto state = mission_.apply(command, robot_id_);
  if (!state) return;
  switch (*state) {
    case service::MissionState::State::kEmergency:
      if (motion_->state() != sim::MotionState::kEmergencyStop) emergency_stops_->increment();
      motion_->emergency_stop();
      publish_pose();  // report the halt at once, not at the next step
      break;
    case service::MissionState::State::kStopped:
      motion_->stop();
      publish_pose();
      break;
    case service::MissionState::State::kActive:
      motion_->release();
      break;
  }
}

void SimService::on_body(const std::string& sender, const v1::RobotPose& pose) {
  if (sender == robot_id_ || sender.empty()) return;
  const auto index = context_->team().robot_index(sender);
  if (!index) return;
  Teammate& t = teammates_[sender];
  t.box.id = static_cast<uint32_t>(*index) + 1;
  t.box.center = vec(pose.pose().position_m());
  const auto& q = pose.pose().orientation();
  Eigen::Quaterniond orientation(q.w(), q.x(), q.y(), q.z());
  t.box.orientation = orientation.norm() > 1e-9 ? orientation.normalized() : Eigen::Quaterniond::Identity();
  Eigen::Vector3d half = vec(pose.body_half_extents_m());
  if (!(half.minCoeff() > 0)) {
    const auto* robot = context_->team().find_robot(sender);
    const auto* species = robot ? context_->team().find_species(robot->species) : nullptr;
    half = species ? species->body_half_extents_m : Eigen::Vector3d(0.5, 0.35, 0.4);
  }
  t.box.half_extents = half;
  t.received_ns = context_->now_ns();
}

std::vector<sim::ProxyBox> SimService::live_teammates() const {
  std::vector<sim::ProxyBox> out;
  const int64_t now = context_->now_ns();
  for (const auto& [id, t] : teammates_)
    if (bodies_.fresh(core::ns_to_s(now - t.received_ns))) out.push_back(t.box);
  return out;
}

void SimService::tick() {
  const std::vector<sim::ProxyBox> mates = live_teammates();
  clock_.step(step_ns_);
  motion_->step(core::ns_to_s(step_ns_), mates);
  if (motion_->state() == sim::MotionState::kBlocked && last_state_ != sim::MotionState::kBlocked) {
    blocked_->increment();
    const Eigen::Vector3d at = motion_->ground_position();
    char where[96];
    std::snprintf(where, sizeof(where), "(%.2f, %.2f, %.2f)", at.x(), at.y(), at.z());
    core::LogLine(core::LogLevel::kInfo, "sim") << robot_id_ << ": blocked (" << sim::to_string(motion_->block_reason())
                                               << ") at " << where;
  }
  last_state_ = motion_->state();
  if (motion_->maneuvers() > reported_maneuvers_) {
    maneuvers_->increment(motion_->maneuvers() - reported_maneuvers_);
    reported_maneuvers_ = motion_->maneuvers();
  }
  if (motion_->collisions() > reported_collisions_) {
    collisions_->increment(motion_->collisions() - reported_collisions_);
    reported_collisions_ = motion_->collisions();
    // Rare and always worth a line: where, and how close the nearest teammate's centre was.
    const Eigen::Vector3d at = motion_->ground_position();
    double nearest = std::numeric_limits<double>::infinity();
    for (const sim::ProxyBox& m : mates) nearest = std::min(nearest, (m.center - motion_->body_pose().translation()).head<2>().norm());
    char where[128];
    std::snprintf(where, sizeof(where), "(%.2f, %.2f, %.2f), nearest teammate centre %.2f m", at.x(), at.y(), at.z(), nearest);
    core::LogLine(core::LogLevel::kWarn, "sim") << robot_id_ << ": contact with a teammate at " << where;
  }
  update_gauges();
  publish_pose();
  if (clock_.now_ns() >= next_scan_ns_) {
    next_scan_ns_ = clock_.now_ns() + scan_period_ns_;
    scan_all();
  }
  context_->set_state(v1::SERVICE_STATE_RUNNING, sim::to_string(motion_->state()));
}

void SimService::update_gauges() {
  odometry_m_->set(motion_->odometry_m());
  sim_time_s_->set(core::ns_to_s(clock_.now_ns()));
  const Eigen::Vector3d at = motion_->ground_position();
  for (int a = 0; a < 3; ++a) position_m_[a]->set(at[a]);
  for (auto& [s, gauge] : motion_state_) gauge->set(s == motion_->state() ? 1.0 : 0.0);
}

void SimService::scan_all() {
  const std::vector<sim::ProxyBox> mates = live_teammates();
  const Eigen::Isometry3d body = motion_->body_pose();
  for (auto& s : sensors_) {
    if (look_at_) s.model->aim_at(*look_at_, body);
    const int64_t start = core::monotonic_ns();
    const sim::LidarScan scan = s.model->scan(*caster_, body, mates);
    const double seconds = std::max(1e-9, core::ns_to_s(core::monotonic_ns() - start));
    s.scan_seconds->observe(seconds);
    s.rays_per_second->set(static_cast<double>(scan.rays) / seconds);
    context_->publisher().publish(topics::scan(robot_id_), sim::to_scan_frame(scan, body, s.model->config().max_range_m),
                                  clock_.now_ns());
  }
}

void SimService::publish_pose() {
  v1::RobotPose pose;
  sim::set_pose(pose.mutable_pose(), motion_->body_pose());
  radio::set(pose.mutable_velocity_mps(), motion_->velocity());
  pose.set_state(sim::to_proto(motion_->state()));
  radio::set(pose.mutable_body_half_extents_m(), motion_->species().body_half_extents_m);
  pose.set_odometry_m(motion_->odometry_m());
  pose.set_collisions(motion_->collisions());
  auto& pub = context_->publisher();
  pub.publish(topics::pose(robot_id_), pose, clock_.now_ns());
  pub.publish(topics::kSimBody, pose, clock_.now_ns());
  if (radio_slot_) context_->radio()->positions().update(*radio_slot_, context_->now_ns(), motion_->body_pose().translation());
  // The radio only when teammates' extrapolation of the last team pose no longer holds.
  const double now_s = core::ns_to_s(clock_.now_ns());
  const Eigen::Vector3d at = motion_->body_pose().translation();
  const Eigen::Matrix3d r = motion_->body_pose().linear();
  const double heading = std::atan2(r(1, 0), r(0, 0));
  if (team_pose_schedule_.due(now_s, at, heading, pose.state())) {
    pub.publish(topics::kTeamPose, pose, clock_.now_ns());
    team_pose_schedule_.sent(now_s, at, motion_->velocity(), heading, pose.state());
  }
}

void SimService::fill_status(v1::ServiceStatus& status) {
  if (!motion_) return;
  const service::StatusValues add(status);
  add("sim_time_s", core::ns_to_s(clock_.now_ns()));
  add("odometry_m", motion_->odometry_m());
  add("collisions", motion_->collisions());
  add("blocked", motion_->state() == sim::MotionState::kBlocked ? 1.0 : 0.0);
}

}  // namespace hexplore::sim_service
