#include "common/highlevel/contribution_log.h"

#include <algorithm>
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
  record(u);
}

void ContributionLog::record(const MapUpdate& u) {
  current_.apply(u);
  for (uint64_t key : u.removals) pending_keys_.insert(key);
  for (const Supervoxel& sv : u.upserts) pending_keys_.insert(sv.key);
  for (const EdgeKey& e : u.edge_upserts) pending_edges_.insert(e);
  for (const EdgeKey& e : u.edge_removals) pending_edges_.insert(e);
}

ContributionLog::Change ContributionLog::change_between(const Supervoxel& p, const Supervoxel& n) const {
  if (p.covered != n.covered || p.traversal_requirement != n.traversal_requirement || p.surface != n.surface ||
      p.gap != n.gap) {
    return Change::kDiscrete;
  }
  if ((p.center - n.center).norm() > tolerance_.center_m) return Change::kGeometry;
  const double cos_angle = std::clamp(p.normal.dot(n.normal), -1.0, 1.0);
  if (std::acos(cos_angle) > tolerance_.normal_deg * M_PI / 180.0) return Change::kGeometry;
  const double count = std::max(1, p.voxel_count);
  if (std::abs(n.voxel_count - p.voxel_count) > tolerance_.voxel_count_ratio * count ||
      std::abs(n.covered_voxels - p.covered_voxels) > tolerance_.voxel_count_ratio * count) {
    return Change::kGeometry;
  }
  return Change::kNone;
}

SourcedUpdate ContributionLog::take_increment() {
  SourcedUpdate inc;
  inc.source = source_;
  inc.seq = ++seq_;
  inc.incarnation = incarnation_;
  const auto hold = static_cast<uint64_t>(std::max(1, tolerance_.geometry_resend_windows));
  std::set<uint64_t> held;  // geometry changes that wait for their key's next resend window
  for (uint64_t key : pending_keys_) {
    auto now = current_.supervoxels.find(key);
    auto pub = published_.supervoxels.find(key);
    if (now == current_.supervoxels.end()) {
      if (pub != published_.supervoxels.end()) {
        inc.update.removals.push_back(key);
        published_.supervoxels.erase(pub);
        sent_in_.erase(key);
      }
      continue;
    }
    if (pub != published_.supervoxels.end()) {
      const Change change = change_between(pub->second, now->second);
      if (change == Change::kNone) continue;
      // Only a covered supervoxel's geometry waits: no view aims at it. An incomplete one's
      // centre and normal are those of its unseen part, where the next view looks.
      if (change == Change::kGeometry && now->second.covered && seq_ < sent_in_[key] + hold) {
        held.insert(key);
        continue;
      }
    }
    inc.update.upserts.push_back(now->second);
    published_.supervoxels[key] = now->second;
    sent_in_[key] = seq_;
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
  pending_keys_ = std::move(held);
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
