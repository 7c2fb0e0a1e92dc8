#pragma once
// Reliable delivery of peers' increments over a lossy publish/subscribe channel (ZeroMQ
// guide, Clone pattern): per-source sequence numbers, gap detection, buffering of early
// increments, and the decision of which repair requests (MapRepairRequest) to send when.
// A source's restart shows as a newer incarnation: its old contribution is void and its new
// one is fetched whole unless its increment 1 arrived. It holds no sockets: the service feeds
// it messages and sends what it asks for.

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "common/highlevel/contribution_log.h"

namespace hexplore::highlevel {

struct RepairRequest {
  std::string source;
  uint64_t from_seq = 0;  // 0: the whole contribution (first contact, late join)
};

struct PeerSyncStats {
  uint64_t increments_applied = 0;
  uint64_t duplicates = 0;
  uint64_t gaps_detected = 0;
  uint64_t gaps_repaired = 0;
  uint64_t snapshots_applied = 0;
  uint64_t repair_requests = 0;
  uint64_t restarts = 0;
  uint64_t stale = 0;  // from an incarnation older than the source's latest
};

class PeerSync {
 public:
  // `self` is this robot's id (its own increments are ignored); a repair request without an
  // answer is repeated after `repair_timeout_s`.
  explicit PeerSync(std::string self, double repair_timeout_s = 1.0);

  // Asks for `source`'s whole contribution at the next due_requests (late join, restart).
  void want_snapshot(const std::string& source);
  // A received increment; returns what may be applied now, in order (the increment itself
  // and any buffered successors), or nothing when it is a duplicate or follows a gap. From a
  // newer incarnation, an empty full snapshot (the old contribution is void) comes first.
  std::vector<SourcedUpdate> on_increment(SourcedUpdate increment);
  // A received snapshot (update.full_snapshot, seq = upto_seq); returns it followed by the
  // buffered increments it makes applicable; nothing when it is older than what is applied.
  std::vector<SourcedUpdate> on_snapshot(SourcedUpdate snapshot);
  // Repair requests to send now.
  std::vector<RepairRequest> due_requests(double now_s);

  uint64_t applied_seq(const std::string& source) const;
  uint64_t incarnation(const std::string& source) const;  // of what is applied (0: unknown)
  bool in_sync(const std::string& source) const;  // known, no gap, no snapshot wanted
  const PeerSyncStats& stats() const { return stats_; }

 private:
  struct Peer {
    uint64_t incarnation = 0;
    uint64_t applied = 0;
    std::map<uint64_t, SourcedUpdate> pending;  // received after a gap
    bool need_repair = false;
    double requested_at = -std::numeric_limits<double>::infinity();
  };
  void drain(Peer& peer, std::vector<SourcedUpdate>& out);
  // False for an update of an older incarnation than `peer`'s; for a newer one, starts the
  // peer afresh (an empty full snapshot appended to `out` voids what was applied before).
  bool adopt_incarnation(Peer& peer, const SourcedUpdate& update, std::vector<SourcedUpdate>& out);

  std::string self_;
  double timeout_s_;
  std::map<std::string, Peer> peers_;
  PeerSyncStats stats_;
};

}  // namespace hexplore::highlevel
