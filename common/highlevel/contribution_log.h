#pragma once
// A robot's own high-level-map contribution and its windowed publication: the segmenter's
// changes are recorded as they happen, and every eta_c one sequenced increment carries the
// current state of everything that changed in the window (the paper's incremental
// transmission). Changes below a tolerance (a centre drifting by millimetres as points
// accumulate) wait until they add up, which is most of the saving over resending, and a
// covered supervoxel's geometry that keeps changing goes out every few windows rather than in
// each. What was published is the robot's contribution: its own fused map uses exactly that,
// as its peers do.
// A snapshot of the whole published contribution answers repair requests.

#include <cstdint>
#include <set>
#include <string>
#include <unordered_map>

#include "common/highlevel/map_fusion.h"
#include "common/highlevel/segmenter.h"

namespace hexplore::highlevel {

// A sequenced change of one source's contribution (increment or, if update.full_snapshot,
// the whole contribution up to `seq`). Sequence numbers restart at 1 when the source's hlmap
// restarts; `incarnation` (its start time, larger after every restart) says which numbering
// a seq belongs to.
struct SourcedUpdate {
  std::string source;
  uint64_t seq = 0;
  MapUpdate update;
  uint64_t incarnation = 0;
  // The source's Contribution::digest() after this update (0: not given): what a receiver's
  // copy must equal once it applied it.
  uint32_t digest = 0;
};

// A published supervoxel is re-sent when a discrete attribute (coverage, traversal
// requirement, class, coverage gap) changes, at once, or when its geometry drifts past these
// bounds: in the next window while it is incomplete (views aim at its centre and normal), at
// most once every `geometry_resend_windows` windows once it is covered.
struct PublishTolerance {
  // One voxel (the hlmap service passes params.map_resolution_m): a centre closer than that to
  // where it was says nothing the map can resolve. Re-sends were mostly centres creeping as
  // voxels joined (77 % of them on the multi-building mission at 5 cm; at 10 cm still 47 % on
  // the default one, stop 53).
  double center_m = 0.15;
  double normal_deg = 5.0;
  double voxel_count_ratio = 0.2;
  // A supervoxel under a robot's sensor grows and shifts in window after window (60 % of the
  // records of a multi-building mission were such geometry re-sends, 36 % of covered
  // supervoxels, stop 56); no view aims at a covered one, so its drift can wait. 1: every window.
  int geometry_resend_windows = 3;
};

class ContributionLog {
 public:
  // `incarnation` marks every increment and snapshot of this log (see SourcedUpdate).
  explicit ContributionLog(std::string source, uint64_t incarnation = 0, PublishTolerance tolerance = {})
      : source_(std::move(source)), incarnation_(incarnation), tolerance_(tolerance) {}

  // Records one segmentation result (nothing is published until take_increment).
  void record(const SupervoxelSegmenter& segmenter, const SegmentationChange& change);
  // The same for a change already in map form: upserts carry the supervoxels' current state,
  // at wire precision.
  void record(const MapUpdate& change);
  // This window's increment, numbered seq() + 1; fuse its update as the robot's own
  // contribution. Empty windows still produce one (a heartbeat), so peers notice a lost last
  // increment and late joiners notice the source.
  SourcedUpdate take_increment();
  // The whole published contribution; seq = the last increment taken.
  SourcedUpdate snapshot() const;

  const std::string& source() const { return source_; }
  uint64_t incarnation() const { return incarnation_; }
  uint64_t seq() const { return seq_; }
  // What peers hold of this robot (edge lengths on the wire come from these centres).
  const Contribution& contribution() const { return published_; }

 private:
  enum class Change { kNone, kGeometry, kDiscrete };
  Change change_between(const Supervoxel& published, const Supervoxel& now) const;

  std::string source_;
  uint64_t incarnation_;
  PublishTolerance tolerance_;
  uint64_t seq_ = 0;
  Contribution current_;    // the segmenter's state
  Contribution published_;  // what the increments so far carried
  uint32_t published_digest_ = Contribution{}.digest();  // published_.digest(), kept with it
  std::set<uint64_t> pending_keys_;
  std::unordered_map<uint64_t, uint64_t> sent_in_;  // key -> seq of the increment that last carried it
  std::set<EdgeKey> pending_edges_;
};

}  // namespace hexplore::highlevel
