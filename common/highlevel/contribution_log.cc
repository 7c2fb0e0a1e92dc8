#include "common/highlevel/contribution_log.h"

namespace hexplore::highlevel {

MapUpdate ContributionLog::record(const SupervoxelSegmenter& segmenter, const SegmentationChange& change) {
  MapUpdate u;
  u.removals = change.removed;
  for (uint64_t key : change.upserted) {
    if (const Supervoxel* sv = segmenter.find(key)) u.upserts.push_back(wire_rounded(*sv));
  }
  u.edge_upserts = change.edges_added;
  u.edge_removals = change.edges_removed;
  current_.apply(u);
  for (uint64_t key : change.removed) pending_keys_.insert(key);
  for (uint64_t key : change.upserted) pending_keys_.insert(key);
  for (const EdgeKey& e : change.edges_added) pending_edges_.insert(e);
  for (const EdgeKey& e : change.edges_removed) pending_edges_.insert(e);
  return u;
}

SourcedUpdate ContributionLog::take_increment() {
  SourcedUpdate inc;
  inc.source = source_;
  inc.seq = ++seq_;
  for (uint64_t key : pending_keys_) {
    auto it = current_.supervoxels.find(key);
    if (it != current_.supervoxels.end()) {
      inc.update.upserts.push_back(it->second);
    } else {
      inc.update.removals.push_back(key);
    }
  }
  for (const EdgeKey& e : pending_edges_) {
    if (current_.edges.count(e) != 0) {
      inc.update.edge_upserts.push_back(e);
    } else {
      inc.update.edge_removals.push_back(e);
    }
  }
  pending_keys_.clear();
  pending_edges_.clear();
  return inc;
}

SourcedUpdate ContributionLog::snapshot() const {
  SourcedUpdate snap;
  snap.source = source_;
  snap.seq = seq_;
  snap.update = current_.snapshot();
  return snap;
}

}  // namespace hexplore::highlevel
