#pragma once
// The sim process of one robot (paper: decentralized simulation): loads the team's world,
// simulates only its own robot (body, LiDARs, motion) and publishes scans and poses with sim
// time: every motion step on robot/<id>/pose, and to the team on team/pose when dead
// reckoning says so (common/radio/pose_schedule.h). Teammates are kinematic proxy boxes driven
// by the other sims' sim/body (the simulated world's physics, not radio traffic) and are hit
// by this robot's rays. Executes MotionCommands from its safety service and obeys mission
// commands: stop halts, emergency stop halts at once and ignores motion until StartMission.
// With a radio model it reports the robot's true position for the range check.
// Its options (after --config/--robot) are SimOptions.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/core/liveness.h"
#include "common/radio/pose_schedule.h"
#include "common/service/mission_state.h"
#include "common/service/service.h"
#include "common/sim/lidar.h"
#include "common/sim/ray_caster.h"
#include "common/sim/robot_motion.h"
#include "common/sim/scenes.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/motion.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/scan.pb.h"

namespace hexplore::sim_service {

struct SimOptions {
  double scan_hz = 2.0;           // --scan-hz: LiDAR frames per sim second, every sensor
  double step_hz = 20.0;          // --step-hz: motion steps and pose messages per sim second
  double real_time_factor = 1.0;  // --real-time-factor: sim seconds per wall second
  std::string scene_dir;          // --scene-dir: write the generated scene mesh there (created on demand)

  // Throws service::OptionError naming the option.
  static SimOptions from_arguments(const std::map<std::string, std::string>& args);
};

class SimService : public service::Service {
 public:
  core::ServiceKind kind() const override { return core::ServiceKind::kSim; }
  void setup(service::ServiceContext& context) override;
  void on_shutdown(service::ServiceContext& context) override;
  void fill_status(v1::ServiceStatus& status) override;

 private:
  struct Teammate {
    sim::ProxyBox box;
    int64_t received_ns = 0;  // on the loop's clock
  };
  struct Sensor {
    std::unique_ptr<sim::LidarModel> model;
    metrics::Histogram* scan_seconds = nullptr;
    metrics::Gauge* rays_per_second = nullptr;
  };

  void load_world(service::ServiceContext& context, const std::string& scene_dir);
  void on_motion(const v1::MotionCommand& command);
  void on_mission(const v1::MissionCommand& command);
  void on_body(const std::string& sender, const v1::RobotPose& pose);
  void tick();
  void scan_all();
  void publish_pose();
  void update_gauges();
  std::vector<sim::ProxyBox> live_teammates() const;

  service::ServiceContext* context_ = nullptr;
  std::string robot_id_;
  sim::SceneInfo scene_;
  std::unique_ptr<sim::RayCaster> caster_;
  std::unique_ptr<sim::RobotMotion> motion_;
  service::MissionState mission_;  // what the station's commands asked of this robot
  std::vector<Sensor> sensors_;
  std::map<std::string, Teammate> teammates_;
  core::Liveness bodies_{core::LivenessParams{}.sim_body_s};  // a proxy whose sim went silent goes
  std::optional<Eigen::Vector3d> look_at_;
  sim::SimClock clock_;
  int64_t step_ns_ = 50'000'000;
  int64_t scan_period_ns_ = 500'000'000;
  int64_t next_scan_ns_ = 0;
  sim::MotionState last_state_ = sim::MotionState::kIdle;
  uint32_t reported_collisions_ = 0;
  uint32_t reported_maneuvers_ = 0;
  radio::PoseSchedule team_pose_schedule_;
  std::optional<uint32_t> radio_slot_;  // this robot's slot when a radio model wants positions

  metrics::Counter* blocked_ = nullptr;
  metrics::Counter* maneuvers_ = nullptr;
  metrics::Counter* collisions_ = nullptr;
  metrics::Counter* emergency_stops_ = nullptr;
  metrics::Gauge* odometry_m_ = nullptr;
  metrics::Gauge* sim_time_s_ = nullptr;
  metrics::Gauge* position_m_[3] = {nullptr, nullptr, nullptr};  // x, y, z
  std::map<sim::MotionState, metrics::Gauge*> motion_state_;         // 1 for the current state
};

}  // namespace hexplore::sim_service
