#include "common/highlevel/facade_holders.h"

#include <algorithm>
#include <vector>

namespace hexplore::highlevel {
namespace {

// Whether `c` holds any supervoxel of `key`'s seed cell under another class or facing.
bool holds_cell_otherwise(const Contribution& c, uint64_t key) {
  const uint64_t cell = key & core::kSeedKeyCellMask;
  for (const uint64_t facade : {uint64_t{0}, kFacadeKeyBit})
    for (int f = 0; f < kFacingCount; ++f) {
      const uint64_t other = cell | facade | (uint64_t(f) << kFacingKeyShift);
      if (other != key && c.supervoxels.count(other) != 0) return true;
    }
  return false;
}

}  // namespace

FacadeHolders incomplete_facade_holders(const MapFusion& fusion, const std::string& own) {
  FacadeHolders out;
  const Contribution* mine = fusion.contribution(own);
  std::vector<const Contribution*> teammates;
  for (const std::string& source : fusion.sources())
    if (source != own) teammates.push_back(fusion.contribution(source));
  for (const auto& entry : fusion.map().supervoxels()) {
    // A named copy: clang 14 (the fuzz build) refuses lambdas that capture a structured binding.
    const uint64_t key = entry.first;
    if (!entry.second.facade() || entry.second.covered) continue;
    const bool held_here = mine != nullptr && mine->supervoxels.count(key) != 0;
    const bool held_elsewhere =
        std::any_of(teammates.begin(), teammates.end(), [&](const Contribution* c) { return c->supervoxels.count(key) != 0; });
    if (held_here && held_elsewhere) {
      ++out.shared;
    } else if (held_here) {
      ++out.own_only;
    } else {
      ++out.teammates_only;
      if (mine != nullptr && holds_cell_otherwise(*mine, key)) ++out.teammates_only_own_cell;
    }
  }
  return out;
}

}  // namespace hexplore::highlevel
