#include "common/highlevel/peer_sync.h"

namespace hexplore::highlevel {

PeerSync::PeerSync(std::string self, double repair_timeout_s)
    : self_(std::move(self)), timeout_s_(repair_timeout_s) {}

void PeerSync::want_snapshot(const std::string& source) {
  if (source == self_) return;
  Peer& p = peers_[source];
  if (!p.need_repair) p.requested_at = -std::numeric_limits<double>::infinity();
  p.need_repair = true;
}

void PeerSync::drain(Peer& peer, std::vector<SourcedUpdate>& out) {
  while (!peer.pending.empty()) {
    auto it = peer.pending.begin();
    if (it->first <= peer.applied) {
      peer.pending.erase(it);
      continue;
    }
    if (it->first != peer.applied + 1) break;
    peer.applied = it->first;
    out.push_back(std::move(it->second));
    ++stats_.increments_applied;
    peer.pending.erase(it);
  }
}

bool PeerSync::adopt_incarnation(Peer& peer, const SourcedUpdate& update, std::vector<SourcedUpdate>& out) {
  if (update.incarnation < peer.incarnation) {
    ++stats_.stale;
    return false;
  }
  if (update.incarnation == peer.incarnation) return true;
  if (peer.applied > 0 || !peer.pending.empty()) {
    // The source restarted: what it sent before is void, and its new numbering is met as on
    // first contact (increment 1 applies; any later one is a gap that fetches a snapshot).
    ++stats_.restarts;
    SourcedUpdate reset;
    reset.source = update.source;
    reset.incarnation = update.incarnation;
    reset.update.full_snapshot = true;
    out.push_back(std::move(reset));
    peer = Peer{};
  }
  peer.incarnation = update.incarnation;
  return true;
}

std::vector<SourcedUpdate> PeerSync::on_increment(SourcedUpdate inc) {
  std::vector<SourcedUpdate> out;
  if (inc.source == self_ || inc.seq == 0) return out;
  Peer& p = peers_[inc.source];
  if (!adopt_incarnation(p, inc, out)) return out;
  if (inc.seq <= p.applied) {
    ++stats_.duplicates;
    return out;
  }
  if (inc.seq == p.applied + 1 && !(p.applied == 0 && p.need_repair && inc.seq != 1)) {
    p.applied = inc.seq;
    out.push_back(std::move(inc));
    ++stats_.increments_applied;
    drain(p, out);
    if (p.pending.empty() && p.need_repair && p.applied > 0) {
      // A wanted snapshot is still useful only if nothing was ever applied.
      p.need_repair = false;
    }
    return out;
  }
  const uint64_t seq = inc.seq;
  p.pending.emplace(seq, std::move(inc));
  if (!p.need_repair) {
    ++stats_.gaps_detected;
    p.need_repair = true;
    p.requested_at = -std::numeric_limits<double>::infinity();
  }
  return out;
}

std::vector<SourcedUpdate> PeerSync::on_snapshot(SourcedUpdate snap) {
  std::vector<SourcedUpdate> out;
  if (snap.source == self_) return out;
  Peer& p = peers_[snap.source];
  if (!adopt_incarnation(p, snap, out)) return out;
  if (snap.seq < p.applied) return out;  // older than what is applied
  snap.update.full_snapshot = true;
  p.applied = snap.seq;
  out.push_back(std::move(snap));
  ++stats_.snapshots_applied;
  drain(p, out);
  if (p.need_repair) {
    if (p.pending.empty()) {
      p.need_repair = false;
      ++stats_.gaps_repaired;
    } else {
      p.requested_at = -std::numeric_limits<double>::infinity();  // still a gap: ask again
    }
  }
  return out;
}

std::vector<RepairRequest> PeerSync::due_requests(double now_s) {
  std::vector<RepairRequest> out;
  for (auto& [source, p] : peers_) {
    if (!p.need_repair || now_s - p.requested_at < timeout_s_) continue;
    p.requested_at = now_s;
    out.push_back({source, p.applied == 0 ? 0 : p.applied + 1});
    ++stats_.repair_requests;
  }
  return out;
}

uint64_t PeerSync::incarnation(const std::string& source) const {
  auto it = peers_.find(source);
  return it == peers_.end() ? 0 : it->second.incarnation;
}

uint64_t PeerSync::applied_seq(const std::string& source) const {
  auto it = peers_.find(source);
  return it == peers_.end() ? 0 : it->second.applied;
}

bool PeerSync::in_sync(const std::string& source) const {
  auto it = peers_.find(source);
  return it != peers_.end() && !it->second.need_repair && it->second.pending.empty();
}

}  // namespace hexplore::highlevel
