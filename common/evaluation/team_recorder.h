#pragma once
// Turns what the station hears into an ExperimentRecord: trajectories and the longest BLOCKED
// stretch per robot from team/pose, communication volume per category from the size of every
// team message, planning rounds from the planners' statuses, and the counters the services report in their statuses (odometry and
// collisions, map sync, what the other map strategies would have sent, radio drops) as
// increases since the start. Pure bookkeeping; the station service feeds it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/core/team_config.h"
#include "common/evaluation/experiment_record.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/status.pb.h"

namespace hexplore::v1 {
class StationCheckpoint;
}

namespace hexplore::evaluation {

// Paper category of a team topic ("pose", "incremental_map", ...); nullopt for other topics.
std::optional<std::string> communication_category(std::string_view topic);

// Status value names the planning service reports (see services/planning).
inline constexpr std::string_view kViewsRemaining = "views_remaining";
inline constexpr std::string_view kPlanningRound = "round";
inline constexpr std::string_view kPlanningTime = "planning_time_s";

class TeamRecorder {
 public:
  explicit TeamRecorder(const core::TeamConfig& team);

  // The mission starts now (sim time of the fastest robot); earlier samples are discarded.
  void start(double sim_time_s);
  bool started() const { return start_s_.has_value(); }
  // Seconds since start (0 before start), from the latest sim time heard.
  double mission_time_s() const;
  double latest_sim_time_s() const { return latest_sim_time_s_; }

  // A pose from `robot` at sim time `sim_time_s`. Unknown robots are ignored (returns false).
  bool on_pose(const std::string& robot, double sim_time_s, const v1::RobotPose& pose);
  // `bytes` of a message on a team topic sent by `robot` (topic + header + payload).
  void on_team_message(const std::string& robot, std::string_view topic, size_t bytes);
  // A planning status; records the planning time of each new round. Returns views remaining (-1 unknown).
  int on_planning_status(const std::string& robot, const v1::ServiceStatus& status);
  // Any service's status: keeps the status counters (status_counters()) of `service`, and of
  // hlmap's the map-convergence values (RobotTrack::own_increment_seq, synced_seq).
  void on_status(const std::string& robot, std::string_view service, const v1::ServiceStatus& status);
  void on_completeness(CompletenessSample sample);

  // The recorder's whole state, for a station restarted mid-mission (record_checkpoint.cc).
  // resume() continues from a checkpoint as if the station had heard nothing for a while: it
  // counts the restart and the mission time between the checkpoint's latest sim time and
  // `now_sim_time_s` as unrecorded.
  v1::StationCheckpoint checkpoint() const;
  void resume(const v1::StationCheckpoint& checkpoint, double now_sim_time_s);

  ExperimentRecord& record() { return record_; }
  const ExperimentRecord& record() const { return record_; }

 private:
  // Keeps an hlmap status value that says how far the maps converged; false for any other.
  bool record_map_sync(RobotTrack& track, const std::string& name, double value);

  const core::TeamConfig* team_;
  ExperimentRecord record_;
  std::optional<double> start_s_;
  double latest_sim_time_s_ = 0.0;
  struct Counter {
    double at_start = 0.0;
    double latest = 0.0;
    bool seen = false;
  };
  std::map<std::string, double> last_round_;
  std::map<std::string, double> chord_length_m_;
  std::map<std::string, std::map<std::string, Counter>> counters_;  // robot -> "service.value"
};

// The status values the record keeps per robot, as "service.value" (ExperimentRecord:
// RobotTrack::counters). Every service may report the radio drops.
const std::vector<std::string>& status_counters();

}  // namespace hexplore::evaluation
