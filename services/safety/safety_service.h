#pragma once
// The safety process of one robot: takes the executable path from planning, resolves conflicts
// with teammates (paper "Path-Conflict Resolution Strategy") and sends the approved path or a
// stop to the robot driver. Shares its own near path on team/path when it changed or once per
// eta_c (common/safety/fragment_sharing.h): teammates advance the last fragment they heard
// along its path, as this service does with theirs. Obeys mission commands: an emergency stop
// halts the robot at once and refuses paths until a StartMission; a StopMission halts it the
// same way.

#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "common/core/liveness.h"
#include "common/safety/fragment_sharing.h"
#include "common/safety/resolver.h"
#include "common/service/mission_state.h"
#include "common/service/service.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/motion.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/safety.pb.h"

namespace hexplore::safety_service {

class SafetyService : public service::Service {
 public:
  core::ServiceKind kind() const override { return core::ServiceKind::kSafety; }
  // Options (after --config/--robot): --wait-for-start true|false (default false: drive as soon
  // as planning sends a path; true: hold still until the station's StartMission);
  // --decision-clock sim|wall (default sim: decide every 0.2 s of the driver's sim time, taken
  // from its pose messages, so a faster or lockstep sim gets the same decisions; wall: every
  // 0.2 s of wall time). Without sim time in the poses, wall time is used either way.
  void setup(service::ServiceContext& context) override;
  void on_shutdown(service::ServiceContext& context) override;
  void fill_status(v1::ServiceStatus& status) override;

 private:
  struct Peer {
    std::optional<safety::Fragment> fragment;
    int64_t fragment_ns = 0;          // receive time, loop clock
    int64_t fragment_sim_ns = 0;      // sim time stamped by the sender (0 = none)
    std::optional<v1::RobotPose> pose;
    int64_t pose_ns = 0;
    int64_t pose_sim_ns = 0;
  };

  void on_pose(const v1::RobotPose& pose, int64_t sim_time_ns);
  void on_path(const v1::ExecutablePath& path);
  void on_mission(const v1::MissionCommand& command);
  // One decision: resolve, command the driver, share the fragment.
  void cycle();
  void halt(const std::string& reason);
  // Every teammate heard of: its fresh fragment (moved to where a newer pose puts it), else a
  // fragment from its pose (a silent teammate stays, as a stopped box at its last pose).
  std::vector<safety::Fragment> peers() const;
  // Whether the teammate's latest pose was sent after its latest fragment.
  bool pose_is_newer(const Peer& peer) const;
  // Whether a message received at (wall, sim) is too old to act on.
  bool stale(int64_t received_ns, int64_t sent_sim_ns) const;
  // Seconds since a message of (wall, sim) was sent, on the clock stale() uses.
  double age_s(int64_t received_ns, int64_t sent_sim_ns) const;
  // A teammate's body half extents, from its species in the team file.
  Eigen::Vector3d half_extents_of(const std::string& id) const;
  void publish(const v1::MotionCommand& command);
  void share_fragment();
  double now_s() const;

  service::ServiceContext* context_ = nullptr;
  std::string robot_id_;
  std::unique_ptr<safety::ConflictResolver> resolver_;
  double default_speed_mps_ = 0.5;
  // How old a teammate's fragment or pose may be to move it (params.liveness.obstacle_s).
  core::Liveness obstacles_{core::LivenessParams{}.obstacle_s};
  safety::FragmentSchedule sharing_;
  std::optional<Eigen::Vector3d> position_;
  int64_t sim_time_ns_ = 0;
  bool sim_clock_ = true;              // --decision-clock sim
  int64_t last_decision_sim_ns_ = -1;
  safety::Path desired_;
  double path_speed_mps_ = 0.0;
  std::optional<Eigen::Vector3d> look_at_;
  std::map<std::string, Peer> peers_;
  service::MissionState mission_;  // active, stopped or halted, by the station's commands
  safety::Decision last_;
  std::ofstream trace_;  // decision trace (--trace-dir), common/safety/decision_trace.h
  safety::ResolverCounters reported_;   // counters already added to the metrics

  metrics::Counter* conflicts_ = nullptr;
  metrics::Counter* yields_ = nullptr;
  metrics::Counter* detours_ = nullptr;
  metrics::Counter* deadlock_breaks_ = nullptr;
  metrics::Counter* emergency_stops_ = nullptr;
  metrics::Gauge* yielding_ = nullptr;
};

}  // namespace hexplore::safety_service
