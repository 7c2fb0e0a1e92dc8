#pragma once
// hexplore_hlmap: one robot's high-level map process. It segments its own perception map
// (robot/<id>/voxels) into supervoxels and topology edges, publishes its contribution
// incrementally on team/map every eta_c, fuses its peers' contributions (repairing losses by
// MapRepairRequest -> MapSnapshot), and serves the fused map to its own planning: a
// FusedMapRequest snapshot, then FusedMapUpdate increments on robot/<id>/hlmap.

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/highlevel/contribution_log.h"
#include "common/highlevel/facade_holders.h"
#include "common/highlevel/map_fusion.h"
#include "common/highlevel/peer_sync.h"
#include "common/highlevel/segmenter.h"
#include "common/service/service.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::hlmap_service {

class HlmapService : public service::Service {
 public:
  core::ServiceKind kind() const override { return core::ServiceKind::kHlmap; }
  void setup(service::ServiceContext& context) override;
  void fill_status(v1::ServiceStatus& status) override;

 private:
  void on_voxels(const v1::VoxelDelta& delta);
  void on_increment(const v1::MapIncrement& increment);
  void on_snapshot(const v1::MapSnapshot& snapshot);
  // Counts and logs (once per teammate) the supervoxels from_proto left out as malformed.
  void count_malformed(const highlevel::SourcedUpdate& update);
  void apply_ready(std::vector<highlevel::SourcedUpdate> ready);
  // Compares this robot's copy of `update.source`'s contribution with the digest the source
  // sent (update.digest) and asks for a snapshot when they differ.
  void verify_digest(const highlevel::SourcedUpdate& update);
  // Known, no gap, no snapshot wanted, and the last digest compared was equal.
  bool in_sync(const std::string& peer) const;
  v1::MapSnapshot serve_repair(const v1::MapRepairRequest& request);
  v1::FusedMapUpdate serve_fused(const v1::FusedMapRequest& request);
  void window();
  // Adds one window of the full-map strategy (encoded only when the contribution changed).
  void count_full_map(bool changed);
  double now_s() const;

  service::ServiceContext* context_ = nullptr;
  std::string robot_id_;
  std::vector<std::string> peers_;  // the teammates whose contributions this robot fuses
  highlevel::SegmenterParams params_;
  std::vector<int> levels_;
  std::unique_ptr<highlevel::SupervoxelSegmenter> segmenter_;
  std::unique_ptr<highlevel::ContributionLog> log_;
  std::unique_ptr<highlevel::MapFusion> fusion_;
  std::unique_ptr<highlevel::PeerSync> sync_;
  uint64_t fused_version_ = 0;
  double repair_timeout_s_ = 2.0;
  size_t window_team_bytes_ = 0;
  size_t window_snapshot_bytes_ = 0;
  // Table 4-5's full strategy: what broadcasting the whole contribution every eta_c, in the
  // same wire form as the increments, would have cost so far.
  double full_map_bytes_ = 0.0;
  size_t full_map_window_bytes_ = 0;  // the last window's, reused while nothing changes

  struct Metrics {
    metrics::Histogram* segmentation_s = nullptr;
    metrics::Histogram* topology_s = nullptr;
    metrics::Histogram* fusion_s = nullptr;
    metrics::Gauge* supervoxels = nullptr;
    metrics::Gauge* own_supervoxels = nullptr;
    metrics::Gauge* edges = nullptr;
    metrics::Gauge* graph_vertices = nullptr;
    metrics::Gauge* voxels = nullptr;
    metrics::Gauge* window_bytes_team_map = nullptr;
    metrics::Gauge* window_bytes_hlmap = nullptr;
    metrics::Gauge* window_bytes_snapshots = nullptr;
    // Incomplete facades of the fused map by whose maps hold them (highlevel/facade_holders.h).
    metrics::Gauge* facades_own_only = nullptr;
    metrics::Gauge* facades_shared = nullptr;
    metrics::Gauge* facades_teammates_only = nullptr;
    metrics::Gauge* facades_teammates_own_cell = nullptr;
    metrics::Counter* gaps_detected = nullptr;
    metrics::Counter* gaps_repaired = nullptr;
    metrics::Counter* repair_requests = nullptr;
    metrics::Counter* peer_restarts = nullptr;
    metrics::Counter* stale_updates = nullptr;
    metrics::Counter* digest_mismatches = nullptr;
    metrics::Counter* snapshots_served = nullptr;
    metrics::Counter* bad_deltas = nullptr;
    metrics::Counter* malformed_voxels = nullptr;
    metrics::Counter* malformed_supervoxels = nullptr;
    metrics::Counter* full_map_bytes = nullptr;
  } metrics_;
  highlevel::FacadeHolders facade_holders_;  // as of the last window
  highlevel::PeerSyncStats reported_;  // sync stats already added to the counters
  // Peers whose contribution, as applied here, differed from the digest they sent with it.
  std::set<std::string> diverged_;
  // Of those, the ones whose snapshot differed too: no more snapshots are asked of them until a
  // digest matches (a snapshot per increment would not repair them).
  std::set<std::string> unrepairable_;
  double digests_checked_ = 0.0;
  double digest_mismatches_ = 0.0;
};

}  // namespace hexplore::hlmap_service
