#include "common/highlevel/facade_holders.h"

#include <gtest/gtest.h>

namespace hexplore::highlevel {
namespace {

Supervoxel facade(const core::GridCell& cell, Facing facing, bool covered) {
  Supervoxel s;
  s.key = supervoxel_key(cell, SurfaceClass::kFacade, facing);
  s.surface = SurfaceClass::kFacade;
  s.center = Eigen::Vector3d(cell.x + 0.5, cell.y + 0.5, cell.z + 0.5);
  s.normal = Eigen::Vector3d::UnitX();
  s.covered = covered;
  s.voxel_count = 20;
  s.covered_voxels = covered ? 20 : 0;
  return s;
}

TEST(FacadeHolders, CountsWhoseMapsHoldTheOpenFacades) {
  MapFusion fusion({1, 2});
  MapUpdate mine, theirs;
  mine.upserts = {facade({1, 0, 0}, Facing::kPlusX, false),    // mine only
                  facade({2, 0, 0}, Facing::kPlusX, false),    // both
                  facade({4, 0, 0}, Facing::kMinusX, false)};  // its cell, another facing
  theirs.upserts = {facade({2, 0, 0}, Facing::kPlusX, false),
                    facade({3, 0, 0}, Facing::kPlusX, false),   // theirs only
                    facade({4, 0, 0}, Facing::kPlusX, false),   // theirs only; I hold the cell as -x
                    facade({5, 0, 0}, Facing::kPlusX, true)};   // complete: not counted
  fusion.apply("me", mine);
  fusion.apply("mate", theirs);
  const FacadeHolders h = incomplete_facade_holders(fusion, "me");
  EXPECT_EQ(h.own_only, 2u);  // cell 1 and my -x face of cell 4
  EXPECT_EQ(h.shared, 1u);
  EXPECT_EQ(h.teammates_only, 2u);
  EXPECT_EQ(h.teammates_only_own_cell, 1u);
  // Seen from the teammate, the same map reads the other way round.
  const FacadeHolders theirs_view = incomplete_facade_holders(fusion, "mate");
  EXPECT_EQ(theirs_view.own_only, 2u);
  EXPECT_EQ(theirs_view.teammates_only, 2u);
  EXPECT_EQ(theirs_view.teammates_only_own_cell, 1u);
}

}  // namespace
}  // namespace hexplore::highlevel
