#pragma once
// Where the mission stands for one robot, as the station's MissionCommands (team/mission)
// set it: active, stopped, or halted by an emergency stop (which only a start lifts). A
// command for another robot is ignored; one without a target is for the whole team. The
// services that obey the station (safety, sim, planning) read commands through this one
// class, so "for me?" and the reason reported in the status are decided in one place.

#include <optional>
#include <string>

#include "hexplore/v1/mission.pb.h"

namespace hexplore::service {

class MissionState {
 public:
  enum class State { kActive, kStopped, kEmergency };

  // `waiting_for_start`: begin stopped until a start (--wait-for-start).
  explicit MissionState(bool waiting_for_start = false);

  // The state `command` moves this robot to, or nullopt when it is not a stop, an emergency
  // stop or a start for `robot_id` (e.g. a planner switch, or a command for a teammate). A
  // repeated command returns its state again (a driver that missed the first one halts).
  std::optional<State> apply(const v1::MissionCommand& command, const std::string& robot_id);

  bool active() const { return state_ == State::kActive; }
  // Why the robot is not active ("mission stopped", "emergency stop: <why>", ...); empty when active.
  const std::string& reason() const { return reason_; }

 private:
  State state_ = State::kActive;
  std::string reason_;
};

// Whether `command` is for `robot_id` (no target: the whole team).
bool addressed_to(const v1::MissionCommand& command, const std::string& robot_id);

}  // namespace hexplore::service
