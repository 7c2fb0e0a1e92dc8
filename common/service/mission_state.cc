#include "common/service/mission_state.h"

namespace hexplore::service {

bool addressed_to(const v1::MissionCommand& command, const std::string& robot_id) {
  return command.target_robot().empty() || command.target_robot() == robot_id;
}

MissionState::MissionState(bool waiting_for_start) {
  if (waiting_for_start) {
    state_ = State::kStopped;
    reason_ = "waiting for mission start";
  }
}

std::optional<MissionState::State> MissionState::apply(const v1::MissionCommand& command, const std::string& robot_id) {
  if (!addressed_to(command, robot_id)) return std::nullopt;
  switch (command.command_case()) {
    case v1::MissionCommand::kEmergencyStop: {
      const std::string& why = command.emergency_stop().reason();
      state_ = State::kEmergency;
      reason_ = "emergency stop" + (why.empty() ? std::string() : ": " + why);
      return state_;
    }
    case v1::MissionCommand::kStop:
      // A stop does not lift an emergency stop: only a start does.
      if (state_ != State::kEmergency) {
        state_ = State::kStopped;
        reason_ = "mission stopped";
      }
      return state_;
    case v1::MissionCommand::kStart:
      state_ = State::kActive;
      reason_.clear();
      return state_;
    default:
      return std::nullopt;
  }
}

}  // namespace hexplore::service
