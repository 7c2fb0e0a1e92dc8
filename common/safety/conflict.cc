#include "common/safety/conflict.h"

#include <algorithm>
#include <cmath>
#include <limits>


namespace hexplore::safety {

std::string_view conflict_kind_name(ConflictKind kind) {
  switch (kind) {
    case ConflictKind::kCrossing: return "crossing";
    case ConflictKind::kHeadOn: return "head-on";
    case ConflictKind::kFollowing: return "following";
  }
  return "crossing";
}

std::optional<Conflict> find_conflict(const Path& own, const Path& peer, double safety_distance_m, double step_m) {
  if (own.empty() || peer.empty()) return std::nullopt;
  const auto a = sample_path(own, step_m);
  const auto b = sample_path(peer, step_m);
  const double limit2 = safety_distance_m * safety_distance_m;
  double own_entry = std::numeric_limits<double>::infinity();
  double peer_entry = std::numeric_limits<double>::infinity();
  for (const auto& pa : a) {
    for (const auto& pb : b) {
      if ((pa.point - pb.point).head<2>().squaredNorm() < limit2) {
        own_entry = std::min(own_entry, pa.s_m);
        peer_entry = std::min(peer_entry, pb.s_m);
      }
    }
  }
  if (!std::isfinite(own_entry)) return std::nullopt;
  Conflict c;
  c.own_entry_m = own_entry;
  c.peer_entry_m = peer_entry;
  c.own_point = point_at(own, own_entry);
  c.peer_point = point_at(peer, peer_entry);
  const Eigen::Vector3d da = direction_at(own, own_entry);
  const Eigen::Vector3d db = direction_at(peer, peer_entry);
  const double cosine = da.dot(db);
  if (da.squaredNorm() > 0 && db.squaredNorm() > 0 && cosine < -0.7) {
    c.kind = ConflictKind::kHeadOn;
  } else if (da.squaredNorm() > 0 && db.squaredNorm() > 0 && cosine > 0.7) {
    c.kind = ConflictKind::kFollowing;
  } else {
    c.kind = ConflictKind::kCrossing;
  }
  return c;
}

double time_to_reach(double distance_m, double speed_mps) {
  if (!(speed_mps > 1e-9)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, distance_m) / speed_mps;
}

}  // namespace hexplore::safety
