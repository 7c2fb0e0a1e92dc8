#pragma once
// A robot's own high-level-map contribution and its windowed publication: the segmenter's
// changes are recorded as they happen, and every eta_c one sequenced increment carries the
// current state of everything that changed in the window (the paper's incremental
// transmission). A snapshot of the whole contribution answers repair requests.

#include <cstdint>
#include <set>
#include <string>

#include "common/highlevel/map_fusion.h"
#include "common/highlevel/segmenter.h"

namespace hexplore::highlevel {

// A sequenced change of one source's contribution (increment or, if update.full_snapshot,
// the whole contribution up to `seq`).
struct SourcedUpdate {
  std::string source;
  uint64_t seq = 0;
  MapUpdate update;
};

class ContributionLog {
 public:
  explicit ContributionLog(std::string source) : source_(std::move(source)) {}

  // Records one segmentation result; returns it as a change of this contribution (to fuse
  // into the robot's own map right away).
  MapUpdate record(const SupervoxelSegmenter& segmenter, const SegmentationChange& change);
  // This window's increment, numbered seq() + 1. Empty windows still produce one (a
  // heartbeat), so peers notice a lost last increment and late joiners notice the source.
  SourcedUpdate take_increment();
  // The whole contribution; seq = the last increment taken.
  SourcedUpdate snapshot() const;

  const std::string& source() const { return source_; }
  uint64_t seq() const { return seq_; }
  const Contribution& contribution() const { return current_; }
  bool has_pending() const { return !pending_keys_.empty() || !pending_edges_.empty(); }

 private:
  std::string source_;
  uint64_t seq_ = 0;
  Contribution current_;
  std::set<uint64_t> pending_keys_;
  std::set<EdgeKey> pending_edges_;
};

}  // namespace hexplore::highlevel
