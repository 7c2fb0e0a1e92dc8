#pragma once
// The ground station: starts the mission, relays mission commands (start, stop, emergency
// stop, switch planner) to the team, and records the experiment: trajectories and traffic
// from the team topics, planning rounds from the planners' statuses, and completeness from
// periodic map snapshots of every robot's mapping service. When the mission is over it
// writes the results folder and stops (its process exit ends a launched team). While the
// mission runs it keeps a checkpoint of the record in the results folder
// (evaluation/record_checkpoint.h); a station restarted mid-mission resumes it.

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "common/metrics/registry.h"
#include "common/service/service.h"
#include "common/evaluation/completeness_evaluator.h"
#include "common/evaluation/mission_monitor.h"
#include "common/evaluation/report_script.h"
#include "common/evaluation/team_recorder.h"
#include "services/station/station_progress.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/station.pb.h"

namespace hexplore::station_service {

struct StationOptions {
  std::string results_dir = "results/latest";
  double snapshot_period_s = 10.0;  // how often robots' maps are fetched for completeness
  double start_wait_s = 60.0;       // start even if some robot is silent after this long
  bool autostart = true;            // send StartMission once every robot is heard
  bool observable = true;           // compute the observable-completeness mask
  double settle_s = 5.0;            // see evaluation::MissionMonitorOptions
  double progress_period_s = 5.0;   // progress line on stdout (0: none)
  // How often each planner is asked why its targets are open (open_targets.csv); 0: only
  // at the end of the mission.
  double open_targets_period_s = 0.0;
  // --report false: no figures; --report-script PATH: what draws them from the results folder
  // (a mission's figures never fail it: without Python the station says so and goes on).
  bool report = true;
  std::string report_script = evaluation::report_script_path("run_report.py");

  // From the service's "--name value" arguments; throws core::ConfigError on a bad value.
  static StationOptions from_arguments(const std::map<std::string, std::string>& arguments);
};

// The station's own Prometheus gauges (team overview dashboard). Every series exists from
// setup on, at 0, so that dashboards have data before the first snapshot round ends.
class StationGauges {
 public:
  StationGauges(metrics::Registry& registry, const core::TeamConfig& team);
  void on_completeness(const evaluation::CompletenessSample& sample);
  void on_tick(double mission_time_s, size_t robots_heard, bool started);

 private:
  metrics::Gauge* team_ = nullptr;
  metrics::Gauge* observable_ = nullptr;
  std::map<std::string, metrics::Gauge*> per_robot_;
  metrics::Gauge* mission_time_s_ = nullptr;
  metrics::Gauge* robots_heard_ = nullptr;
  metrics::Gauge* mission_started_ = nullptr;
};

class StationService : public service::Service {
 public:
  StationService() = default;
  core::ServiceKind kind() const override { return core::ServiceKind::kStation; }
  void setup(service::ServiceContext& context) override;
  void on_shutdown(service::ServiceContext& context) override;
  void fill_status(v1::ServiceStatus& status) override;
  // The finished mission's record (nullptr before the mission is over). Read it only after the
  // station's loop has ended (ServiceHost::wait), e.g. to summarise several runs.
  const evaluation::ExperimentRecord* result() const { return record_complete_ ? &recorder_->record() : nullptr; }
  // The latest progress; safe to read from another thread while the station's loop runs (a
  // host drawing a live progress line).
  StationProgress progress() const;

 private:
  void subscribe_team(service::ServiceContext& context);
  void tick();
  void request_snapshots();
  // Asks every robot's planning why its coverage targets are still open (end of mission).
  void request_open_targets();
  void publish_mission(const v1::MissionCommand& command);
  void update_progress();  // progress_ from the recorder, and the progress line when due
  void finish(const std::string& reason);
  // A checkpoint in the results folder left by a station that stopped mid-mission: kept to
  // resume from once the team is heard (resumable_), unless it is of another team or broken.
  void find_checkpoint();
  // Resumes the record from resumable_ when the team's clock is past it (true), else drops it:
  // it was left by an earlier mission.
  bool resume_from_checkpoint();
  void save_checkpoint();

  service::ServiceContext* context_ = nullptr;
  StationOptions options_;
  std::unique_ptr<evaluation::CompletenessEvaluator> evaluator_;
  std::unique_ptr<evaluation::TeamRecorder> recorder_;
  std::unique_ptr<evaluation::MissionMonitor> monitor_;
  std::unique_ptr<StationGauges> gauges_;
  std::set<std::string> heard_;  // robots whose pose arrived
  std::optional<double> first_heard_s_;  // loop clock (sim time in lockstep)
  double loop_s() const { return core::ns_to_s(context_->now_ns()); }
  double last_snapshot_s_ = -1e9;
  double last_progress_s_ = -1e9;
  double last_open_targets_s_ = 0.0;
  int snapshots_pending_ = 0;
  int reports_pending_ = 0;
  bool finished_ = false;
  bool record_complete_ = false;  // the record is complete
  std::string end_reason_;
  int64_t start_wall_ns_ = 0;
  double wall_before_resume_s_ = 0.0;  // wall time of the mission before this station resumed it
  std::string checkpoint_path_;         // "" in lockstep: station and team are one process there
  std::optional<v1::StationCheckpoint> resumable_;
  metrics::Counter* checkpoint_errors_ = nullptr;
  mutable std::mutex progress_mutex_;
  StationProgress progress_;  // guarded by progress_mutex_
};

}  // namespace hexplore::station_service
