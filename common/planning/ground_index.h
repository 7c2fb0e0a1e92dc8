#pragma once
// Spatial hash of the traversable ground supervoxels, for "all candidate view positions
// within r of p" queries (view generation, MNSS). Results come in ascending key order.

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/high_level_map.h"

namespace hexplore::planning {

class GroundIndex {
 public:
  // `allowed` (optional) keeps only those ground keys, e.g. the ones some robot can reach.
  GroundIndex(const highlevel::HighLevelMap& map, double bucket_m,
              const std::unordered_set<uint64_t>* allowed = nullptr);
  // Traversable ground supervoxels whose centre lies within radius of p, in ascending key
  // order when `sorted` (else in bucket order, which depends on the hash table).
  std::vector<const highlevel::Supervoxel*> within(const Eigen::Vector3d& p, double radius, bool sorted = true) const;

 private:
  uint64_t bucket_of(int64_t x, int64_t y) const;
  double bucket_m_;
  std::unordered_map<uint64_t, std::vector<const highlevel::Supervoxel*>> buckets_;
};

}  // namespace hexplore::planning
