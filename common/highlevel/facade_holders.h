#pragma once
// Whose maps hold the fused map's incomplete facades, seen from one robot. Coverage fuses by
// key (seed cell, class and facing) as an OR over the sources that hold the key, so a target
// only a teammate's map holds is completed only by a map that holds the same key: this robot's
// looks at it count only where its own voxels there get the same facing. Counted because
// looks that add nothing to their target are a third of the MR1000's (common/planning/README.md,
// "looks that land in another robot's keys"): early in a default mission two thirds of the
// open facades are one robot's.

#include <cstddef>
#include <string>

#include "common/highlevel/map_fusion.h"

namespace hexplore::highlevel {

struct FacadeHolders {
  size_t own_only = 0;        // incomplete facades only this robot's map holds
  size_t shared = 0;          // held by this robot's map and a teammate's
  size_t teammates_only = 0;  // held by teammates' maps only
  // Of teammates_only: this robot's map holds the same seed cell under another key (another
  // facing or class), i.e. it sees that place, differently.
  size_t teammates_only_own_cell = 0;
};

FacadeHolders incomplete_facade_holders(const MapFusion& fusion, const std::string& own);

}  // namespace hexplore::highlevel
