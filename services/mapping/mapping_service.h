#pragma once
// The mapping process of one robot: integrates its own LiDAR scans into the basic perception
// map (paper "Basic Perception-Map Representation"), filters teammates' bodies out using their
// shared poses, publishes voxel deltas to its hlmap on robot/<id>/voxels, answers snapshot
// requests, and keeps the map on disk so a restart resumes it.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "common/core/liveness.h"
#include "common/core/log.h"
#include "common/metrics/registry.h"
#include "common/perception/perception_map.h"
#include "common/service/service.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/scan.pb.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::mapping_service {

// Service options, from "--name value" arguments (defaults in brackets).
struct MappingOptions {
  double publish_period_s = 0.5;        // --publish-period-s: voxel delta period
  double full_snapshot_period_s = 30.0; // --full-snapshot-period-s: full delta for late joiners (0: only at start)
  std::string map_file;                 // --map-file: load at start, save on shutdown and periodically;
                                        // "{robot}" becomes the robot id (one option for a whole team)
  double save_period_s = 60.0;          // --save-period-s (0: only on shutdown)
  double max_pose_jump_m = 5.0;         // --max-pose-jump-m: sensor origin jump between scans
  int reanchor_after = 10;              // --reanchor-after: consistent jumped scans accepted as a relocation
  // --teammate-timeout-s: teammate poses older than this do not filter scans (default: the
  // team file's params.liveness.body_filter_s, core/liveness.h).
  std::optional<double> teammate_timeout_s;

  // Throws service::OptionError naming the option.
  static MappingOptions from_arguments(const std::map<std::string, std::string>& args);
};

class MappingService : public service::Service {
 public:
  core::ServiceKind kind() const override { return core::ServiceKind::kMapping; }
  void setup(service::ServiceContext& context) override;
  void on_shutdown(service::ServiceContext& context) override;
  void fill_status(v1::ServiceStatus& status) override;

 private:
  struct Teammate {
    perception::OrientedBox box;
    Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
    int64_t received_ns = 0;  // loop clock
    int64_t sim_time_ns = 0;  // when the pose was taken (0: unknown)
  };

  void on_scan(const std::string& sender, const v1::ScanFrame& frame, int64_t sim_time_ns);
  void on_team_pose(const std::string& sender, const v1::RobotPose& pose, int64_t sim_time_ns);
  // Null when the scan's pose is plausible; else the rejection reason.
  const char* check_pose(const v1::ScanFrame& frame, const Eigen::Vector3d& origin);
  void reject(const std::string& reason);
  void publish_changes();
  void publish_full_snapshot();
  void publish_delta(const v1::VoxelDelta& delta);
  // Logs "saved N voxels to F" at `saved_level`; false when there is no map file or the save
  // failed (counted, logged).
  bool save_map(core::LogLevel saved_level);

  service::ServiceContext* context_ = nullptr;
  std::string robot_id_;
  MappingOptions options_;
  core::Liveness body_filter_{core::LivenessParams{}.body_filter_s};  // which teammate poses still filter scans
  std::unique_ptr<perception::PerceptionMap> map_;
  std::map<std::string, Teammate> teammates_;
  std::optional<Eigen::Vector3d> last_origin_;
  std::optional<Eigen::Vector3d> jumped_origin_;
  int jump_streak_ = 0;
  std::vector<float> scan_storage_;
  uint64_t scans_integrated_ = 0;
  // Table 4-5's raw strategy: what sending the whole perception map every eta_c would have
  // cost so far (voxels times the mean bytes of a voxel in this robot's deltas).
  double raw_map_bytes_ = 0.0;
  double delta_payload_bytes_ = 0.0;
  double delta_voxel_count_ = 0.0;
  metrics::Counter* raw_map_bytes_total_ = nullptr;
  uint64_t scans_rejected_ = 0;

  metrics::Histogram* integration_seconds_ = nullptr;
  metrics::Gauge* points_per_second_ = nullptr;
  metrics::Gauge* voxel_count_ = nullptr;
  metrics::Gauge* map_bytes_ = nullptr;
  // OcTree::memoryUsage walks every leaf; done for each delta it was 4 % of a mission's CPU.
  static constexpr int64_t kMapBytesPeriodNs = 5'000'000'000;
  int64_t map_bytes_at_ns_ = -kMapBytesPeriodNs;
  metrics::Counter* scans_ = nullptr;
  metrics::Counter* points_ = nullptr;
  metrics::CounterFamily* rejected_ = nullptr;
  metrics::CounterFamily* dropped_points_ = nullptr;
  metrics::Counter* delta_voxels_ = nullptr;
  metrics::Counter* delta_bytes_ = nullptr;
  metrics::Counter* saves_failed_ = nullptr;
};

}  // namespace hexplore::mapping_service
