#include "common/highlevel/contribution_log.h"

#include <cmath>

namespace hexplore::highlevel {

void ContributionLog::record(const SupervoxelSegmenter& segmenter, const SegmentationChange& change) {
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
}

bool ContributionLog::significant(const Supervoxel& p, const Supervoxel& n) const {
  if (p.covered != n.covered || p.traversal_requirement != n.traversal_requirement || p.surface != n.surface ||
      p.gap != n.gap) {
    return true;
  }
  if ((p.center - n.center).norm() > tolerance_.center_m) return true;
  const double cos_angle = std::clamp(p.normal.dot(n.normal), -1.0, 1.0);
  if (std::acos(cos_angle) > tolerance_.normal_deg * M_PI / 180.0) return true;
  const double count = std::max(1, p.voxel_count);
  return std::abs(n.voxel_count - p.voxel_count) > tolerance_.voxel_count_ratio * count ||
         std::abs(n.covered_voxels - p.covered_voxels) > tolerance_.voxel_count_ratio * count;
}

SourcedUpdate ContributionLog::take_increment() {
  SourcedUpdate inc;
  inc.source = source_;
  inc.seq = ++seq_;
  inc.incarnation = incarnation_;
  for (uint64_t key : pending_keys_) {
    auto now = current_.supervoxels.find(key);
    auto pub = published_.supervoxels.find(key);
    if (now == current_.supervoxels.end()) {
      if (pub != published_.supervoxels.end()) {
        inc.update.removals.push_back(key);
        published_.supervoxels.erase(pub);
      }
    } else if (pub == published_.supervoxels.end() || significant(pub->second, now->second)) {
      inc.update.upserts.push_back(now->second);
      published_.supervoxels[key] = now->second;
    }
  }
  for (const EdgeKey& e : pending_edges_) {
    const bool now = current_.edges.count(e) != 0;
    const bool pub = published_.edges.count(e) != 0;
    if (now && !pub) {
      inc.update.edge_upserts.push_back(e);
      published_.edges.insert(e);
    } else if (!now && pub) {
      inc.update.edge_removals.push_back(e);
      published_.edges.erase(e);
    }
  }
  pending_keys_.clear();
  pending_edges_.clear();
  // A heartbeat changes nothing: the digest of the last change still holds.
  if (!inc.update.empty()) published_digest_ = published_.digest();
  inc.digest = published_digest_;
  return inc;
}

SourcedUpdate ContributionLog::snapshot() const {
  SourcedUpdate snap;
  snap.source = source_;
  snap.seq = seq_;
  snap.incarnation = incarnation_;
  snap.update = published_.snapshot();
  snap.digest = published_digest_;
  return snap;
}

}  // namespace hexplore::highlevel
