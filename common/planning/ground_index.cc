#include "common/planning/ground_index.h"

#include <algorithm>
#include <cmath>

namespace hexplore::planning {

uint64_t GroundIndex::bucket_of(int64_t x, int64_t y) const {
  return (uint64_t(x + (int64_t{1} << 31)) << 32) | uint64_t(y + (int64_t{1} << 31));
}

GroundIndex::GroundIndex(const highlevel::HighLevelMap& map, double bucket_m,
                         const std::unordered_set<uint64_t>* allowed)
    : bucket_m_(bucket_m) {
  for (const auto& [key, sv] : map.supervoxels()) {
    if (!sv.traversable() || (allowed && !allowed->count(key))) continue;
    buckets_[bucket_of(int64_t(std::floor(sv.center.x() / bucket_m_)), int64_t(std::floor(sv.center.y() / bucket_m_)))]
        .push_back(&sv);
  }
}

std::vector<const highlevel::Supervoxel*> GroundIndex::within(const Eigen::Vector3d& p, double radius, bool sorted) const {
  std::vector<const highlevel::Supervoxel*> out;
  const int64_t x0 = int64_t(std::floor((p.x() - radius) / bucket_m_)), x1 = int64_t(std::floor((p.x() + radius) / bucket_m_));
  const int64_t y0 = int64_t(std::floor((p.y() - radius) / bucket_m_)), y1 = int64_t(std::floor((p.y() + radius) / bucket_m_));
  const double r2 = radius * radius;
  for (int64_t x = x0; x <= x1; ++x)
    for (int64_t y = y0; y <= y1; ++y) {
      const auto it = buckets_.find(bucket_of(x, y));
      if (it == buckets_.end()) continue;
      for (const auto* sv : it->second)
        if ((sv->center - p).squaredNorm() <= r2) out.push_back(sv);
    }
  if (sorted) std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->key < b->key; });
  return out;
}

}  // namespace hexplore::planning
