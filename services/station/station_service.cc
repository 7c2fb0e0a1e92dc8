#include "services/station/station_service.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "common/core/clock.h"
#include "common/core/coverage_gap.h"
#include "common/core/endpoints.h"
#include "common/core/log.h"
#include "common/service/options.h"
#include "common/service/status_values.h"
#include "common/evaluation/record_checkpoint.h"
#include "common/evaluation/report_script.h"
#include "common/evaluation/results_writer.h"
#include "common/transport/topics.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/safety.pb.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::station_service {
namespace {

using namespace std::chrono_literals;
constexpr auto kTick = 250ms;
constexpr auto kSnapshotTimeout = 5000ms;
constexpr double kFinalSnapshotWaitS = 8.0;

// "OPEN_TARGET_HAS_VIEW" -> "has_view".
std::string lowercase_after_prefix(const std::string& name, const std::string& prefix) {
  std::string out = name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// What the message took on the radio: its topic, header and payload frames as received.
template <typename M>
size_t wire_bytes(const transport::Received<M>& r) {
  return r.wire_bytes;
}

}  // namespace

StationGauges::StationGauges(metrics::Registry& registry, const core::TeamConfig& team) {
  const std::string station(core::kStationId);
  auto* completeness = registry.gauge_family(
      "hexplore_station_completeness_ratio",
      "Reconstruction completeness of the team's union map (scope team) and of what the team could observe "
      "(scope observable), at the last snapshot round");
  team_ = completeness->add({{"robot", station}, {"scope", "team"}});
  observable_ = completeness->add({{"robot", station}, {"scope", "observable"}});
  // Labelled with the robot it is about, so that the dashboards' robot selector applies.
  auto* per_robot = registry.gauge_family("hexplore_station_robot_completeness_ratio",
                                          "Reconstruction completeness of one robot's own map, at the last snapshot round");
  for (const auto& robot : team.robots) per_robot_[robot.id] = per_robot->add({{"robot", robot.id}});
  mission_time_s_ = registry.gauge_family("hexplore_station_mission_time_seconds",
                                          "Sim time since the mission start (0 before it)")->add({{"robot", station}});
  robots_heard_ = registry.gauge_family("hexplore_station_robots_heard",
                                        "Robots whose team/pose the station has heard")->add({{"robot", station}});
  mission_started_ = registry.gauge_family("hexplore_station_mission_started",
                                           "1 once the station started the mission")->add({{"robot", station}});
}

void StationGauges::on_completeness(const evaluation::CompletenessSample& sample) {
  team_->set(sample.team);
  observable_->set(sample.team_observable);
  for (const auto& [robot, value] : sample.per_robot)
    if (auto it = per_robot_.find(robot); it != per_robot_.end()) it->second->set(value);
}

void StationGauges::on_tick(double mission_time_s, size_t robots_heard, bool started) {
  mission_time_s_->set(mission_time_s);
  robots_heard_->set(static_cast<double>(robots_heard));
  mission_started_->set(started ? 1.0 : 0.0);
}

StationOptions StationOptions::from_arguments(const std::map<std::string, std::string>& args) {
  const service::Options opts(args);
  StationOptions o;
  o.results_dir = opts.text("results", o.results_dir);
  o.snapshot_period_s = opts.number("snapshot-period-s", o.snapshot_period_s, 0.0);
  o.start_wait_s = opts.number("start-wait-s", o.start_wait_s, 0.0);
  o.settle_s = opts.number("end-settle-s", o.settle_s, 0.0);
  o.progress_period_s = opts.number("progress-period-s", o.progress_period_s, 0.0);
  o.open_targets_period_s = opts.number("open-targets-period-s", o.open_targets_period_s, 0.0);
  o.autostart = opts.flag("autostart", o.autostart);
  o.report = opts.flag("report", o.report);
  o.report_script = opts.text("report-script", o.report_script);
  o.observable = opts.flag("observable", o.observable);
  return o;
}

void StationService::setup(service::ServiceContext& context) {
  context_ = &context;
  options_ = StationOptions::from_arguments(context.arguments());
  start_wall_ns_ = core::monotonic_ns();
  evaluation::EvaluatorOptions eval;
  eval.observable = options_.observable;
  evaluator_ = std::make_unique<evaluation::CompletenessEvaluator>(context.team(), eval);
  recorder_ = std::make_unique<evaluation::TeamRecorder>(context.team());
  // In the composed team process (fast mode) every socket is inproc.
  recorder_->record().mode = context.lockstep()                             ? "lockstep"
                             : context.team().transport.scheme == "inproc" ? "composed"
                                                                           : "processes";
  evaluation::MissionMonitorOptions monitor;
  monitor.time_limit_s = context.team().time_limit_s;
  monitor.settle_s = options_.settle_s;
  // Never shorter than two route time-outs: a robot may stay silent on planning that long.
  monitor.silent_after_s = std::max(context.team().params.liveness.station_s, 2.0 * context.team().params.eta_t_s);
  monitor_ = std::make_unique<evaluation::MissionMonitor>(monitor);
  gauges_ = std::make_unique<StationGauges>(context.metrics(), context.team());
  checkpoint_errors_ = context.metrics()
                           .counter_family("hexplore_station_checkpoint_errors_total",
                                           "Station checkpoints that could not be written, or found broken at start")
                           ->add({});
  // In lockstep the station shares the team's process: it cannot restart on its own.
  if (!context.lockstep()) {
    checkpoint_path_ = (std::filesystem::path(options_.results_dir) / evaluation::kCheckpointFileName).string();
    std::error_code ec;  // a folder that cannot be made shows as failed saves, counted
    std::filesystem::create_directories(options_.results_dir, ec);
    find_checkpoint();
  }

  subscribe_team(context);
  // On authenticated links only the holder of the station's key may command the team (an
  // operator's tool uses it: `hexplore_station --send`); a robot's key may not.
  const bool authenticated = context.socket_options().curve != nullptr;
  metrics::Counter* refused = context.metrics()
                                  .counter_family("hexplore_station_refused_commands_total",
                                                  "Mission command requests refused: not from the station's key")
                                  ->add({});
  context.responder().serve<v1::MissionCommand, v1::ServiceStatus>(
      [this, authenticated, refused](const transport::Received<v1::MissionCommand>& request) {
        v1::ServiceStatus ack;
        ack.set_service("station");
        if (authenticated && request.authenticated_member != core::kStationId) {
          refused->increment();
          core::log_once(core::LogLevel::kWarn, "station", "refused-command:" + std::string(request.authenticated_member),
                         "refused a mission command from '" + std::string(request.authenticated_member) +
                             "': only the station's key may command the team (logged once per member)");
          ack.set_state(v1::SERVICE_STATE_RUNNING);
          ack.set_detail("refused: mission commands are accepted only from the station's key");
          return ack;
        }
        publish_mission(request.message);
        ack.set_state(v1::SERVICE_STATE_RUNNING);
        ack.set_detail("relayed " + request.message.ShortDebugString());
        return ack;
      });
  context.loop().add_timer(kTick, [this] { tick(); });
  core::LogLine(core::LogLevel::kInfo, "station")
      << "recording " << context.team().robots.size() << " robots on '" << context.team().scene << "' into "
      << options_.results_dir;
}

void StationService::subscribe_team(service::ServiceContext& context) {
  for (const auto& robot : context.team().robots) {
    // Mapping for its status (what sending the whole perception map would cost).
    for (auto kind : {core::ServiceKind::kSim, core::ServiceKind::kMapping, core::ServiceKind::kHlmap,
                      core::ServiceKind::kPlanning, core::ServiceKind::kSafety})
      context.connect(robot.id, kind);
  }
  auto& sub = context.subscriber();
  sub.on<v1::RobotPose>(std::string(transport::topics::kTeamPose), [this](const auto& r) {
    const std::string robot = r.header.robot_id();
    if (!recorder_->on_pose(robot, core::ns_to_s(r.header.sim_time_ns()), r.message)) return;
    if (!first_heard_s_) first_heard_s_ = loop_s();
    heard_.insert(robot);
    recorder_->on_team_message(robot, r.topic, wire_bytes(r));
  });
  sub.on<v1::MapIncrement>(std::string(transport::topics::kTeamMap),
                           [this](const auto& r) { recorder_->on_team_message(r.header.robot_id(), r.topic, wire_bytes(r)); });
  sub.on<v1::TeamSolution>(std::string(transport::topics::kTeamPlan),
                           [this](const auto& r) { recorder_->on_team_message(r.header.robot_id(), r.topic, wire_bytes(r)); });
  sub.on<v1::PathFragment>(std::string(transport::topics::kTeamPath),
                           [this](const auto& r) { recorder_->on_team_message(r.header.robot_id(), r.topic, wire_bytes(r)); });
  for (const auto& robot : context.team().robots) {
    sub.on<v1::ServiceStatus>(transport::topics::status(robot.id), [this](const auto& r) {
      recorder_->on_status(r.header.robot_id(), r.header.service(), r.message);
      if (r.header.service() != "planning") return;
      const int views = recorder_->on_planning_status(r.header.robot_id(), r.message);
      if (views >= 0 && recorder_->started())
        monitor_->on_planning_status(r.header.robot_id(), recorder_->mission_time_s(), views);
    });
  }
}

void StationService::publish_mission(const v1::MissionCommand& command) {
  context_->publisher().publish(transport::topics::kTeamMission, command,
                                core::s_to_ns(recorder_->latest_sim_time_s()));
  core::LogLine(core::LogLevel::kInfo, "station") << "mission command: " << command.ShortDebugString();
}

void StationService::tick() {
  if (finished_) return;
  gauges_->on_tick(recorder_->mission_time_s(), heard_.size(), recorder_->started());
  const size_t robots = context_->team().robots.size();
  if (!recorder_->started()) {
    const bool everyone = heard_.size() == robots;
    const bool waited = first_heard_s_ && loop_s() - *first_heard_s_ > options_.start_wait_s;
    if ((everyone || waited) && resumable_ && resume_from_checkpoint()) return;
    if (options_.autostart && (everyone || waited)) {
      v1::MissionCommand start;
      start.mutable_start();
      publish_mission(start);
      recorder_->start(recorder_->latest_sim_time_s());
      core::LogLine(core::LogLevel::kInfo, "station")
          << "mission started with " << heard_.size() << "/" << robots << " robots heard";
    }
    return;
  }
  const double t = recorder_->mission_time_s();
  if (t - last_snapshot_s_ >= options_.snapshot_period_s && snapshots_pending_ == 0) {
    last_snapshot_s_ = t;
    request_snapshots();
  }
  if (options_.open_targets_period_s > 0 && t - last_open_targets_s_ >= options_.open_targets_period_s &&
      reports_pending_ == 0) {
    last_open_targets_s_ = t;
    request_open_targets();
  }
  update_progress();
  if (const auto reason = monitor_->check(t)) finish(*reason);
}

void StationService::request_snapshots() {
  for (const auto& robot : context_->team().robots) {
    v1::OccupiedVoxelsRequest request;
    request.set_requester("station");
    ++snapshots_pending_;
    context_->requester(robot.id, core::ServiceKind::kMapping)
        .request<v1::OccupiedVoxelsRequest, v1::OccupiedVoxels>(
            request,
            [this, id = robot.id](const transport::Received<v1::OccupiedVoxels>* reply) {
              --snapshots_pending_;
              if (reply != nullptr)
                evaluator_->set_robot_map(id, reply->message.resolution_m(),
                                          {reply->message.keys_xyz().data(),
                                           static_cast<size_t>(reply->message.keys_xyz_size())});
              if (snapshots_pending_ > 0) return;
              evaluation::CompletenessSample sample = evaluator_->evaluate(recorder_->mission_time_s());
              gauges_->on_completeness(sample);
              recorder_->on_completeness(std::move(sample));
              save_checkpoint();
            },
            kSnapshotTimeout);
  }
}

void StationService::request_open_targets() {
  for (const auto& robot : context_->team().robots) {
    v1::OpenTargetsRequest request;
    request.set_requester("station");
    ++reports_pending_;
    context_->requester(robot.id, core::ServiceKind::kPlanning)
        .request<v1::OpenTargetsRequest, v1::OpenTargetsReport>(
            request,
            [this, id = robot.id](const transport::Received<v1::OpenTargetsReport>* reply) {
              --reports_pending_;
              if (reply == nullptr) return;  // a robot that is gone has no report
              std::vector<evaluation::OpenTargetRow> rows;
              for (const v1::OpenTarget& t : reply->message.targets()) {
                evaluation::OpenTargetRow row;
                row.key = t.key();
                row.center = {t.center_m().x(), t.center_m().y(), t.center_m().z()};
                row.facade = t.facade();
                row.voxels = int(t.voxel_count());
                row.covered_voxels = int(t.covered_voxels());
                row.gap = std::string(core::to_string(core::coverage_gap_from_wire(uint32_t(t.coverage_gap()))));
                row.state = v1::OpenTargetState_Name(t.state());
                if (row.state.empty()) row.state = "unknown";
                else row.state = lowercase_after_prefix(row.state, "OPEN_TARGET_");
                row.attempts = int(t.attempts());
                rows.push_back(std::move(row));
              }
              recorder_->record().add_open_targets_report(id, recorder_->mission_time_s(), std::move(rows));
            },
            kSnapshotTimeout);
  }
}

StationProgress StationService::progress() const {
  const std::lock_guard<std::mutex> lock(progress_mutex_);
  return progress_;
}

void StationService::update_progress() {
  const double t = recorder_->mission_time_s();
  const auto& samples = recorder_->record().completeness;
  StationProgress now;
  now.started = true;
  now.mission_time_s = t;
  now.team_completeness = samples.empty() ? 0.0 : samples.back().team;
  now.live_robots = monitor_->live_robots(t);
  {
    const std::lock_guard<std::mutex> lock(progress_mutex_);
    progress_ = now;
  }
  if (options_.progress_period_s <= 0.0 || t - last_progress_s_ < options_.progress_period_s) return;
  last_progress_s_ = t;
  std::string states;
  for (const auto& [id, track] : recorder_->record().robots)
    states += " " + id + "=" + (track.last_state.empty() ? "?" : track.last_state.substr(13));
  std::printf("[station] t=%6.1fs completeness=%5.1f%% live=%d%s\n", t, 100.0 * now.team_completeness,
              now.live_robots, states.c_str());
  std::fflush(stdout);
}

void StationService::finish(const std::string& reason) {
  finished_ = true;
  end_reason_ = reason;
  v1::MissionCommand stop;
  stop.mutable_stop();
  publish_mission(stop);
  core::LogLine(core::LogLevel::kInfo, "station") << "mission over: " << reason << "; fetching final maps";
  // One last snapshot round and each planner's open targets, then write and stop; waits at
  // most kFinalSnapshotWaitS.
  const double deadline = loop_s() + kFinalSnapshotWaitS;
  if (snapshots_pending_ == 0) request_snapshots();
  request_open_targets();
  context_->loop().add_timer(kTick, [this, deadline] {
    if ((snapshots_pending_ > 0 || reports_pending_ > 0) && loop_s() < deadline) return;
    auto& record = recorder_->record();
    record.end_reason = end_reason_;
    record.exploration_time_s = recorder_->mission_time_s();
    record.wall_time_s = wall_before_resume_s_ + core::ns_to_s(core::monotonic_ns() - start_wall_ns_);
    record.final_map_points_m = evaluator_->union_points();
    record.map_resolution_m = context_->team().params.map_resolution_m;
    record_complete_ = true;
    try {
      const auto files = evaluation::write_results(record, options_.results_dir);
      // The results hold the whole record now; a station started later begins a new one.
      std::error_code ignored;  // a checkpoint left behind is found to be an earlier mission's
      if (!checkpoint_path_.empty()) std::filesystem::remove(checkpoint_path_, ignored);
      std::printf("[station] mission over (%s) after %.1f s sim time; completeness %.1f%%; results in %s (%zu files)\n",
                  end_reason_.c_str(), record.exploration_time_s, 100.0 * record.final_team_completeness(),
                  options_.results_dir.c_str(), files.size());
      std::fflush(stdout);
      if (options_.report) {
        if (const auto why_not = evaluation::run_report_script(options_.report_script, options_.results_dir))
          std::printf("[station] figures not drawn: %s\n", why_not->c_str());
        else
          std::printf("[station] figures and report.md in %s\n", options_.results_dir.c_str());
        std::fflush(stdout);
      }
    } catch (const std::exception& e) {
      core::log(core::LogLevel::kError, "station", e.what());
    }
    context_->loop().stop();
  });
}

void StationService::find_checkpoint() {
  try {
    resumable_ = evaluation::load_checkpoint(checkpoint_path_);
  } catch (const evaluation::CheckpointError& e) {
    checkpoint_errors_->increment();
    core::LogLine(core::LogLevel::kWarn, "station") << e.what() << "; starting a new record";
    return;
  }
  if (!resumable_) return;
  if (const std::string why = evaluation::checkpoint_mismatch(*resumable_, context_->team()); !why.empty()) {
    core::LogLine(core::LogLevel::kWarn, "station")
        << checkpoint_path_ << " is not a record of this team's mission (" << why << "); starting a new record";
    resumable_.reset();
    return;
  }
  core::LogLine(core::LogLevel::kInfo, "station")
      << "found the record of a mission in progress (" << checkpoint_path_ << ", mission time "
      << resumable_->latest_sim_time_s() - resumable_->start_sim_time_s() << " s); resuming it once the team is heard";
}

bool StationService::resume_from_checkpoint() {
  const v1::StationCheckpoint checkpoint = std::move(*resumable_);
  resumable_.reset();
  const double now = recorder_->latest_sim_time_s();
  // The robots' sim clocks go on while the station is down; behind the checkpoint, they are
  // a new mission's.
  if (now < checkpoint.latest_sim_time_s()) {
    core::LogLine(core::LogLevel::kInfo, "station")
        << "the record in " << checkpoint_path_ << " ends at sim time " << checkpoint.latest_sim_time_s()
        << " s, the team is at " << now << " s: an earlier mission's; starting a new record";
    return false;
  }
  recorder_->resume(checkpoint, now);
  const double mission_s = recorder_->mission_time_s();
  last_snapshot_s_ = checkpoint.completeness_size() > 0
                         ? checkpoint.completeness(checkpoint.completeness_size() - 1).sim_time_s()
                         : mission_s;
  last_open_targets_s_ = mission_s;
  wall_before_resume_s_ =
      std::max(0.0, core::ns_to_s(core::wall_time_ns()) - 1e-3 * static_cast<double>(checkpoint.start_wall_ms()));
  start_wall_ns_ = core::monotonic_ns();
  core::LogLine(core::LogLevel::kInfo, "station")
      << "resumed the mission record at mission time " << mission_s << " s (restart "
      << recorder_->record().station_restarts << "; "
      << mission_s - (checkpoint.latest_sim_time_s() - checkpoint.start_sim_time_s()) << " s unrecorded)";
  return true;
}

void StationService::save_checkpoint() {
  if (checkpoint_path_.empty() || finished_) return;
  v1::StationCheckpoint checkpoint = recorder_->checkpoint();
  const double wall_s = wall_before_resume_s_ + core::ns_to_s(core::monotonic_ns() - start_wall_ns_);
  checkpoint.set_start_wall_ms(static_cast<int64_t>(1e3 * (core::ns_to_s(core::wall_time_ns()) - wall_s)));
  try {
    evaluation::save_checkpoint(checkpoint, checkpoint_path_);
  } catch (const evaluation::CheckpointError& e) {
    checkpoint_errors_->increment();
    core::log_once(core::LogLevel::kWarn, "station", "checkpoint-save",
                   std::string(e.what()) + " (a restarted station could not resume the record; logged once)");
  }
}

void StationService::on_shutdown(service::ServiceContext& context) {
  if (finished_ || !recorder_ || !recorder_->started()) return;
  save_checkpoint();
  core::log(core::LogLevel::kWarn, "station",
            checkpoint_path_.empty() ? "stopped before the mission ended; no results written"
                                     : "stopped before the mission ended; no results written, the record is in " +
                                           checkpoint_path_ + " for a station started again");
}

void StationService::fill_status(v1::ServiceStatus& status) {
  if (!recorder_) return;
  const service::StatusValues add(status);
  add("mission_time_s", recorder_->mission_time_s());
  const auto& samples = recorder_->record().completeness;
  add("completeness", samples.empty() ? 0.0 : samples.back().team);
}

}  // namespace hexplore::station_service
