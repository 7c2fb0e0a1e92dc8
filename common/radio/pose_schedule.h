#pragma once
// When a robot's pose goes on the radio (team/pose). Dead reckoning, as networked simulation
// does it (IEEE 1278 DIS entity-state updates): teammates extrapolate the last pose along its
// velocity (extrapolate_pose), so a new one is due only when that extrapolation has drifted
// from the truth, when the heading turned, when the motion state changed (teammates react to
// MOVING -> IDLE), or when the heartbeat period passed (teammates time out silent robots).
// A robot driving a straight segment or standing still thus sends one pose per heartbeat,
// where a fixed rate would send every period.

#include <optional>

#include <Eigen/Core>

namespace hexplore::radio {

struct PoseScheduleOptions {
  // Extrapolation error that makes a pose due. Receivers that must not mistake a teammate for
  // terrain (the mapping filter) widen its body by this much while they extrapolate.
  double threshold_m = 0.3;
  double heading_deg = 25.0;      // heading change that makes a pose due
  double min_interval_s = 0.5;    // drift-triggered poses no closer together than this
  double heartbeat_s = 2.0;       // a pose at least this often
  double max_extrapolation_s = 3.0;  // receivers extrapolate no further (extrapolate_pose)

  // Throws std::invalid_argument naming the bad field.
  void validate() const;
};

// Where a pose of `position` moving at `velocity` puts the robot `age_s` later: straight on,
// for at most `max_s` (a robot not heard from for longer is assumed to have stopped).
Eigen::Vector3d extrapolate_pose(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double age_s,
                                 double max_s);

class PoseSchedule {
 public:
  explicit PoseSchedule(PoseScheduleOptions options = {});

  // Whether the pose now (true position, heading in radians, motion state) must be sent.
  bool due(double now_s, const Eigen::Vector3d& position, double heading_rad, int state) const;
  // Records what was sent, as receivers will extrapolate it.
  void sent(double now_s, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double heading_rad,
            int state);
  const PoseScheduleOptions& options() const { return options_; }

 private:
  struct Sent {
    double time_s;
    Eigen::Vector3d position;
    Eigen::Vector3d velocity;
    double heading_rad;
    int state;
  };
  PoseScheduleOptions options_;
  std::optional<Sent> last_;
};

}  // namespace hexplore::radio
