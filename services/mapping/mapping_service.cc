#include "services/mapping/mapping_service.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common/core/clock.h"
#include "common/core/config_error.h"
#include "common/core/endpoints.h"
#include "common/core/log.h"
#include "common/perception/voxel_proto.h"
#include "common/radio/pose_schedule.h"
#include "common/radio/vec3_proto.h"
#include "common/service/options.h"
#include "common/service/status_values.h"
#include "common/transport/topics.h"

namespace hexplore::mapping_service {
namespace {

namespace topics = transport::topics;

std::chrono::nanoseconds seconds(double s) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(s));
}

using radio::vec;

}  // namespace

MappingOptions MappingOptions::from_arguments(const std::map<std::string, std::string>& args) {
  const service::Options opts(args);
  MappingOptions o;
  o.publish_period_s = opts.number("publish-period-s", o.publish_period_s, 0.001);
  o.full_snapshot_period_s = opts.number("full-snapshot-period-s", o.full_snapshot_period_s, 0.0);
  o.save_period_s = opts.number("save-period-s", o.save_period_s, 0.0);
  o.max_pose_jump_m = opts.number("max-pose-jump-m", o.max_pose_jump_m, 0.0);
  o.reanchor_after = opts.integer("reanchor-after", o.reanchor_after, 1);
  if (opts.has("teammate-timeout-s")) o.teammate_timeout_s = opts.positive("teammate-timeout-s", 1.0);
  o.map_file = opts.text("map-file", o.map_file);
  return o;
}

void MappingService::setup(service::ServiceContext& context) {
  context_ = &context;
  robot_id_ = context.robot_id();
  options_ = MappingOptions::from_arguments(context.arguments());
  options_.map_file = core::substitute(options_.map_file, "robot", robot_id_);
  body_filter_ = core::Liveness(options_.teammate_timeout_s.value_or(context.team().params.liveness.body_filter_s));
  perception::MapParams params;
  try {
    params = perception::make_map_params(context.team(), robot_id_);
  } catch (const std::invalid_argument& e) {
    throw core::ConfigError(context.team().source_file, "robots." + robot_id_, e.what());
  }
  map_ = std::make_unique<perception::PerceptionMap>(params);

  if (!options_.map_file.empty() && std::filesystem::exists(options_.map_file)) {
    try {
      map_->load(options_.map_file);
      core::LogLine(core::LogLevel::kInfo, "mapping")
          << robot_id_ << ": resumed " << map_->voxel_count() << " voxels from " << options_.map_file;
    } catch (const perception::MapFileError& e) {
      // Keep the unreadable file for inspection instead of overwriting it at the next save.
      const std::string aside = options_.map_file + ".unreadable";
      std::error_code ec;
      std::filesystem::rename(options_.map_file, aside, ec);
      core::LogLine(core::LogLevel::kError, "mapping")
          << robot_id_ << ": " << e.what() << "; starting an empty map (old file moved to " << aside << ")";
    }
  }

  auto& m = context.metrics();
  const metrics::Labels labels{{"robot", robot_id_}};
  integration_seconds_ = m.histogram_family("hexplore_mapping_scan_integration_seconds",
                                            "Time to integrate one scan, metric updates included",
                                            metrics::latency_buckets_s())
                             ->add(labels);
  points_per_second_ =
      m.gauge_family("hexplore_mapping_points_per_second", "Points integrated per second of integration time, last scan")
          ->add(labels);
  voxel_count_ = m.gauge_family("hexplore_mapping_voxels", "Occupied voxels in the perception map")->add(labels);
  map_bytes_ = m.gauge_family("hexplore_mapping_map_bytes", "Memory held by the perception map")->add(labels);
  scans_ = m.counter_family("hexplore_mapping_scans_total", "Scans integrated")->add(labels);
  points_ = m.counter_family("hexplore_mapping_points_total", "Points integrated")->add(labels);
  rejected_ = m.counter_family("hexplore_mapping_scans_rejected_total", "Scans refused, by reason");
  dropped_points_ = m.counter_family("hexplore_mapping_points_dropped_total", "Points dropped from accepted scans, by reason");
  delta_voxels_ = m.counter_family("hexplore_mapping_delta_voxels_total", "Voxels sent in voxel deltas")->add(labels);
  delta_bytes_ = m.counter_family("hexplore_mapping_delta_bytes_total", "Payload bytes of voxel deltas sent")->add(labels);
  saves_failed_ = m.counter_family("hexplore_mapping_map_saves_failed_total", "Map saves that failed")->add(labels);
  voxel_count_->set(static_cast<double>(map_->voxel_count()));

  context.connect(robot_id_, core::ServiceKind::kSim);
  for (const auto& robot : context.team().robots) {
    if (robot.id != robot_id_) context.connect(robot.id, core::ServiceKind::kSim);
  }
  auto& sub = context.subscriber();
  sub.on<v1::ScanFrame>(topics::scan(robot_id_), [this](const transport::Received<v1::ScanFrame>& r) {
    on_scan(r.header.robot_id(), r.message, r.header.sim_time_ns());
  });
  sub.on<v1::RobotPose>(std::string(topics::kTeamPose), [this](const transport::Received<v1::RobotPose>& r) {
    on_team_pose(r.header.robot_id(), r.message, r.header.sim_time_ns());
  });
  context.responder().serve<v1::OccupiedVoxelsRequest, v1::OccupiedVoxels>(
      [this](const transport::Received<v1::OccupiedVoxelsRequest>&) {
        return perception::to_occupied_voxels(map_->voxels(), map_->resolution());
      });

  context.loop().add_timer(seconds(options_.publish_period_s), [this] { publish_changes(); });
  raw_map_bytes_total_ = m.counter_family("hexplore_mapping_raw_map_equivalent_bytes_total",
                                          "Bytes that sending the whole perception map every eta_c would have cost")
                             ->add(labels);
  context.loop().add_timer(seconds(context.team().params.eta_c_s), [this] {
    if (delta_voxel_count_ <= 0.0) return;
    const double bytes = static_cast<double>(map_->voxel_count()) * delta_payload_bytes_ / delta_voxel_count_;
    raw_map_bytes_ += bytes;
    raw_map_bytes_total_->increment(bytes);
  });
  if (options_.full_snapshot_period_s > 0.0) {
    context.loop().add_timer(seconds(options_.full_snapshot_period_s), [this] { publish_full_snapshot(); });
  }
  if (!options_.map_file.empty() && options_.save_period_s > 0.0) {
    // What a restart after a crash (SIGKILL) resumes from; the e2e restart test reads the log.
    context.loop().add_timer(seconds(options_.save_period_s), [this] { save_map(core::LogLevel::kDebug); });
  }
  // A resumed map goes out whole first, so the hlmap starts from it instead of from deltas.
  if (map_->voxel_count() > 0) publish_full_snapshot();
  context.set_state(v1::SERVICE_STATE_RUNNING, "waiting for scans");
}

void MappingService::on_shutdown(service::ServiceContext&) {
  publish_changes();
  save_map(core::LogLevel::kInfo);
}

void MappingService::fill_status(v1::ServiceStatus& status) {
  const service::StatusValues add(status);
  add("voxels", map_ ? static_cast<double>(map_->voxel_count()) : 0.0);
  add("scans_integrated", static_cast<double>(scans_integrated_));
  add("scans_rejected", static_cast<double>(scans_rejected_));
  add("raw_map_bytes", raw_map_bytes_);
}

void MappingService::reject(const std::string& reason) {
  ++scans_rejected_;
  rejected_->add({{"robot", robot_id_}, {"reason", reason}})->increment();
  core::log_once(core::LogLevel::kWarn, "mapping", "reject/" + reason,
                 robot_id_ + ": rejecting scans (" + reason + "); counted in hexplore_mapping_scans_rejected_total");
}

const char* MappingService::check_pose(const v1::ScanFrame& frame, const Eigen::Vector3d& origin) {
  if (frame.has_body_pose()) {
    const v1::Pose& p = frame.body_pose();
    const Eigen::Vector4d q(p.orientation().w(), p.orientation().x(), p.orientation().y(), p.orientation().z());
    if (!vec(p.position_m()).allFinite() || !q.allFinite()) return "implausible_pose";
  }
  if (!last_origin_ || (origin - *last_origin_).norm() <= options_.max_pose_jump_m) return nullptr;
  // A jump: refused, unless it keeps being confirmed by consistent scans (a real relocation,
  // e.g. the driver re-localised), after which the new place is taken as the anchor.
  if (jumped_origin_ && (origin - *jumped_origin_).norm() <= options_.max_pose_jump_m) {
    ++jump_streak_;
  } else {
    jump_streak_ = 1;
  }
  jumped_origin_ = origin;
  if (jump_streak_ >= options_.reanchor_after) {
    core::LogLine(core::LogLevel::kWarn, "mapping")
        << robot_id_ << ": accepting a relocation of " << (origin - *last_origin_).norm() << " m after "
        << jump_streak_ << " consistent scans";
    return nullptr;
  }
  return "pose_jump";
}

void MappingService::on_scan(const std::string& sender, const v1::ScanFrame& frame, int64_t sim_time_ns) {
  if (sender != robot_id_) {
    reject("foreign_robot");
    return;
  }
  perception::ScanPoints scan;
  const perception::ScanRejection r = perception::decode_scan(frame, scan_storage_, scan);
  if (r == perception::ScanRejection::kSizeMismatch) {
    reject("size_mismatch");
    return;
  }
  if (r == perception::ScanRejection::kBadOrigin) {
    reject("implausible_pose");
    return;
  }
  if (const char* reason = check_pose(frame, scan.sensor_origin)) {
    reject(reason);
    return;
  }
  last_origin_ = scan.sensor_origin;
  jumped_origin_.reset();
  jump_streak_ = 0;

  std::vector<perception::OrientedBox> bodies;
  const int64_t now = context_->now_ns();
  for (const auto& [id, mate] : teammates_) {
    if (!body_filter_.fresh(core::ns_to_s(now - mate.received_ns))) continue;
    // Team poses come when dead reckoning says so: where the teammate is by this scan's time.
    // The sender lets the extrapolation drift by up to threshold_m before it sends again, so the
    // body is widened (horizontally) by that much while it is extrapolated.
    perception::OrientedBox box = mate.box;
    if (sim_time_ns > 0 && mate.sim_time_ns > 0) {
      const radio::PoseScheduleOptions schedule;
      const double age_s = core::ns_to_s(sim_time_ns - mate.sim_time_ns);
      box.centre = radio::extrapolate_pose(box.centre, mate.velocity_mps, age_s, schedule.max_extrapolation_s);
      if (age_s > 0.0) {
        box.half_extents_m.x() += schedule.threshold_m;
        box.half_extents_m.y() += schedule.threshold_m;
      }
    }
    bodies.push_back(box);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const perception::IntegrationStats stats = map_->integrate(scan, bodies);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  ++scans_integrated_;
  scans_->increment();
  points_->increment(static_cast<double>(stats.points_integrated));
  integration_seconds_->observe(elapsed);
  if (elapsed > 0.0) points_per_second_->set(stats.points_integrated / elapsed);
  voxel_count_->set(static_cast<double>(map_->voxel_count()));
  auto drop = [&](const char* reason, size_t n) {
    if (n > 0) dropped_points_->add({{"robot", robot_id_}, {"reason", reason}})->increment(static_cast<double>(n));
  };
  drop("non_finite", stats.dropped_non_finite);
  drop("teammate_body", stats.dropped_teammate);
  drop("out_of_range", stats.dropped_out_of_range);
  drop("outside_map", stats.dropped_outside_map);
  if (scans_integrated_ == 1) context_->set_state(v1::SERVICE_STATE_RUNNING, "");
}

void MappingService::on_team_pose(const std::string& sender, const v1::RobotPose& pose, int64_t sim_time_ns) {
  if (sender.empty() || sender == robot_id_) return;
  perception::OrientedBox box;
  box.centre = vec(pose.pose().position_m());
  const v1::Quaternion& q = pose.pose().orientation();
  box.orientation = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
  if (box.orientation.norm() < 1e-9) box.orientation = Eigen::Quaterniond::Identity();
  box.half_extents_m = vec(pose.body_half_extents_m());
  if (box.half_extents_m.minCoeff() <= 0.0) {
    // No box in the message: the teammate's species body from the team file.
    const core::RobotConfig* robot = context_->team().find_robot(sender);
    const core::SpeciesConfig* species = robot ? context_->team().find_species(robot->species) : nullptr;
    if (species == nullptr) return;
    box.half_extents_m = species->body_half_extents_m;
  }
  if (!box.centre.allFinite() || !box.half_extents_m.allFinite()) return;
  teammates_[sender] = Teammate{box, vec(pose.velocity_mps()), context_->now_ns(), sim_time_ns};
}

void MappingService::publish_delta(const v1::VoxelDelta& delta) {
  context_->publisher().publish(topics::voxels(robot_id_), delta);
  delta_voxels_->increment(delta.voxels_size());
  delta_bytes_->increment(static_cast<double>(delta.ByteSizeLong()));
  delta_voxel_count_ += delta.voxels_size();
  delta_payload_bytes_ += static_cast<double>(delta.ByteSizeLong());
  const int64_t now_ns = context_->now_ns();
  if (now_ns - map_bytes_at_ns_ >= kMapBytesPeriodNs || now_ns < map_bytes_at_ns_) {
    map_bytes_->set(static_cast<double>(map_->memory_bytes()));
    map_bytes_at_ns_ = now_ns;
  }
}

void MappingService::publish_changes() {
  if (!map_ || map_->pending_changes() == 0) return;
  publish_delta(perception::to_voxel_delta(map_->take_changes(), map_->resolution(), false));
}

void MappingService::publish_full_snapshot() {
  if (!map_ || map_->voxel_count() == 0) return;
  map_->take_changes();  // the snapshot carries them
  publish_delta(perception::to_voxel_delta(map_->voxels(), map_->resolution(), true));
}

bool MappingService::save_map(core::LogLevel saved_level) {
  if (!map_ || options_.map_file.empty()) return false;
  try {
    map_->save(options_.map_file);
    core::LogLine(saved_level, "mapping") << robot_id_ << ": saved " << map_->voxel_count() << " voxels to "
                                          << options_.map_file;
    return true;
  } catch (const perception::MapFileError& e) {
    saves_failed_->increment();
    core::LogLine(core::LogLevel::kError, "mapping") << robot_id_ << ": " << e.what();
    return false;
  }
}

}  // namespace hexplore::mapping_service
