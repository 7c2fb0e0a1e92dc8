#include "common/highlevel/segmenter.h"

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "tests/highlevel/synthetic_map.h"

namespace hexplore::highlevel {
namespace {

using testing::CampusSpec;
using testing::campus_voxels;
using testing::kGroundFlags;
using testing::voxel_at;

const std::vector<int> kLevels = {1, 2};

CampusSpec small_campus() {
  CampusSpec spec;
  spec.size_m = 14.0;
  spec.buildings = 1;
  spec.building_m = 6.0;
  return spec;
}

void expect_same(const SupervoxelSegmenter& a, const SupervoxelSegmenter& b) {
  ASSERT_EQ(a.supervoxels().size(), b.supervoxels().size());
  for (const auto& [key, sv] : a.supervoxels()) {
    const Supervoxel* other = b.find(key);
    ASSERT_NE(other, nullptr) << "key " << key;
    EXPECT_EQ(sv, *other) << "key " << key;
  }
  EXPECT_EQ(a.edges(), b.edges());
}

TEST(Segmenter, SupervoxelCarriesCoveredCountAndTheCommonestGap) {
  testing::Voxelizer vox(0.15);
  for (double x = 0.05; x < 0.9; x += 0.15)
    for (double y = 0.05; y < 0.9; y += 0.15) vox.add({x, y, 0.0}, kGroundFlags, 0b1, Eigen::Vector3f::UnitZ());
  auto voxels = vox.samples();
  ASSERT_GE(voxels.size(), 30u);
  for (size_t i = 0; i < voxels.size(); ++i) {
    if (i < 10) {
      voxels[i].flags |= kVoxelCovered;
    } else {
      voxels[i].flags &= ~uint32_t(kVoxelCovered);
      voxels[i].gap = i < 14 ? core::CoverageGap::kAngle : core::CoverageGap::kDensity;
    }
  }
  SupervoxelSegmenter seg(SegmenterParams{}, {1});
  seg.update(voxels);
  ASSERT_EQ(seg.supervoxels().size(), 1u);
  const Supervoxel& s = seg.supervoxels().begin()->second;
  EXPECT_FALSE(s.covered);
  EXPECT_EQ(s.covered_voxels, 10);
  EXPECT_EQ(s.gap, core::CoverageGap::kDensity);
}

TEST(Segmenter, NoisyThickSlabIsOneLayer) {
  // +/-5 cm of noise on a 5 cm grid: a slab two to three voxels thick that straddles the
  // z = 0 seed boundary, so seeds exist in two vertically adjacent cells of every column.
  const double res = 0.05;
  testing::Voxelizer vox(res);
  for (const auto& p : testing::noisy_slab_points(8.0, 8.0, 0.0, 0.05, 1600.0, 3))
    vox.add(p, kGroundFlags, 0b1, Eigen::Vector3f::UnitZ());
  const auto voxels = vox.samples();
  SegmenterParams params;
  params.resolution_m = res;
  SupervoxelSegmenter seg(params, {1});
  seg.update(voxels);

  std::map<std::pair<int, int>, std::set<uint64_t>> per_column;  // eta_s column -> supervoxels
  std::map<uint64_t, std::set<int>> layers;                      // supervoxel -> voxel z indices
  for (const auto& v : voxels) {
    const uint64_t key = seg.supervoxel_of(v.key);
    ASSERT_NE(key, 0u);
    const auto cell = seed_cell_of(key);
    per_column[{cell.x, cell.y}].insert(key);
    layers[key].insert(v.key.z);
  }
  EXPECT_EQ(per_column.size(), 64u);
  for (const auto& [column, keys] : per_column) EXPECT_EQ(keys.size(), 1u) << column.first << "," << column.second;
  for (const auto& [key, zs] : layers) EXPECT_GE(zs.size(), 2u) << "supervoxel spans the slab thickness";
  for (const auto& [key, sv] : seg.supervoxels()) {
    EXPECT_TRUE(sv.ground());
    EXPECT_NEAR(sv.center.z(), 0.0, 0.02);
  }
}

TEST(Segmenter, TraversalRequirementFollowsPaperTable) {
  // Species A, B, C at levels 1, 2, 3; bit k = species index k.
  const std::vector<int> levels = {1, 2, 3};
  EXPECT_EQ(traversal_requirement(0b000, levels), 0);  // supervoxel 1: N/A
  EXPECT_EQ(traversal_requirement(0b100, levels), 3);  // supervoxel 2: only C
  EXPECT_EQ(traversal_requirement(0b110, levels), 2);  // supervoxel 3: B and C
  EXPECT_EQ(traversal_requirement(0b111, levels), 1);  // supervoxel 4: everyone
  // Levels need not follow the index order.
  EXPECT_EQ(traversal_requirement(0b011, {3, 2, 1}), 2);

  // Within one supervoxel the requirement comes from the AND of its voxels' masks.
  SupervoxelSegmenter seg({}, levels);
  std::vector<VoxelSample> patch;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      patch.push_back(voxel_at({x, y, 0}, 0.15, kGroundFlags, (x == 2 && y == 2) ? 0b100u : 0b111u,
                               Eigen::Vector3f::UnitZ()));
  seg.update(patch);
  ASSERT_EQ(seg.supervoxels().size(), 1u);
  EXPECT_EQ(seg.supervoxels().begin()->second.traversal_requirement, 3);
  patch[2 * 6 + 2].low_risk_species_mask = 0b110;
  seg.update(std::span(&patch[2 * 6 + 2], 1));
  EXPECT_EQ(seg.supervoxels().begin()->second.traversal_requirement, 2);
}

TEST(Segmenter, CoverageIsAllVoxelsCoveredWithTheLiteralRule) {
  SegmenterParams literal;
  literal.min_ise_patch_voxels = 1;
  SupervoxelSegmenter seg(literal, kLevels);
  std::vector<VoxelSample> patch;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      patch.push_back(voxel_at({x, y, 0}, 0.15, kGroundFlags | kVoxelCovered, 0b11, Eigen::Vector3f::UnitZ()));
  patch[7].flags &= ~kVoxelCovered;
  seg.update(patch);
  ASSERT_EQ(seg.supervoxels().size(), 1u);
  EXPECT_FALSE(seg.supervoxels().begin()->second.covered);
  patch[7].flags |= kVoxelCovered;
  const auto change = seg.update(std::span(&patch[7], 1));
  EXPECT_TRUE(seg.supervoxels().begin()->second.covered);
  EXPECT_EQ(change.upserted.size(), 1u);
  EXPECT_EQ(change.relabelled_voxels, 0u) << "attribute changes do not re-grow regions";
}

// A 6 x 6 covered patch with incomplete voxels at the given (x, y) positions.
std::vector<VoxelSample> patch_with_open(const std::vector<std::pair<int, int>>& open) {
  std::vector<VoxelSample> patch;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y) {
      const bool is_open = std::count(open.begin(), open.end(), std::pair{x, y}) > 0;
      patch.push_back(voxel_at({x, y, 0}, 0.15, kGroundFlags | (is_open ? 0u : uint32_t(kVoxelCovered)), 0b11,
                               Eigen::Vector3f::UnitZ()));
    }
  return patch;
}

TEST(Segmenter, ScatteredIncompleteVoxelsDoNotMakeAnIse) {
  SegmenterParams params;
  params.min_ise_patch_voxels = 4;
  {  // four isolated specks (no two of them neighbours): noise at the default threshold
    SupervoxelSegmenter seg(params, kLevels);
    seg.update(patch_with_open({{0, 0}, {0, 5}, {5, 0}, {5, 5}}));
    ASSERT_EQ(seg.supervoxels().size(), 1u);
    const Supervoxel& s = seg.supervoxels().begin()->second;
    EXPECT_TRUE(s.covered);
    EXPECT_EQ(s.covered_voxels, 32) << "the count still tells how many voxels are complete";
  }
  {  // three in a diagonal chain (26-connected) and one apart: the patch is 3 < 4
    SupervoxelSegmenter seg(params, kLevels);
    seg.update(patch_with_open({{1, 1}, {2, 2}, {3, 3}, {5, 0}}));
    EXPECT_TRUE(seg.supervoxels().begin()->second.covered);
  }
  {  // four connected: an ISE, and it stays one until a voxel of the patch is covered
    SupervoxelSegmenter seg(params, kLevels);
    auto patch = patch_with_open({{1, 1}, {2, 2}, {3, 3}, {3, 4}});
    seg.update(patch);
    EXPECT_FALSE(seg.supervoxels().begin()->second.covered);
    VoxelSample fixed = patch[3 * 6 + 3];
    fixed.flags |= kVoxelCovered;
    seg.update(std::span(&fixed, 1));
    EXPECT_TRUE(seg.supervoxels().begin()->second.covered);
  }
}

TEST(Segmenter, FacadeAndGroundInOneCellGetDistinctKeys) {
  SupervoxelSegmenter seg({}, kLevels);
  std::vector<VoxelSample> v;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y) v.push_back(voxel_at({x, y, 0}, 0.15, kGroundFlags, 0b11, Eigen::Vector3f::UnitZ()));
  for (int y = 0; y < 6; ++y)
    for (int z = 1; z < 6; ++z) v.push_back(voxel_at({0, y, z}, 0.15, 0, 0, Eigen::Vector3f::UnitX()));
  seg.update(v);
  ASSERT_EQ(seg.supervoxels().size(), 2u);
  const uint64_t ground = supervoxel_key({0, 0, 0}, SurfaceClass::kGround);
  const uint64_t wall = supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kPlusX);
  ASSERT_NE(seg.find(ground), nullptr);
  ASSERT_NE(seg.find(wall), nullptr);
  EXPECT_TRUE(seg.find(ground)->traversable());
  EXPECT_TRUE(seg.find(wall)->facade());
  EXPECT_NEAR(seg.find(wall)->normal.x(), 1.0, 1e-9);
  EXPECT_EQ(seg.edge_count(), 0u) << "edges join ground supervoxels only";
}

// The paper's segmentation follows the boundaries of objects: the two faces of a wall (their
// normals oriented to the sensors that saw them) and a ceiling over them are separate
// supervoxels, although all lie in one seed cell and touch each other.
TEST(Segmenter, TheFacesOfAWallAndTheCeilingAboveAreSeparateSupervoxels) {
  SupervoxelSegmenter seg({}, kLevels);
  std::vector<VoxelSample> v;
  for (int y = 0; y < 6; ++y)
    for (int z = 0; z < 5; ++z) {
      v.push_back(voxel_at({1, y, z}, 0.15, 0, 0, -Eigen::Vector3f::UnitX()));  // outer face, seen from -x
      v.push_back(voxel_at({2, y, z}, 0.15, 0, 0, Eigen::Vector3f::UnitX()));   // inner face, seen from +x
    }
  for (int x = 3; x < 6; ++x)
    for (int y = 0; y < 6; ++y) v.push_back(voxel_at({x, y, 5}, 0.15, 0, 0, -Eigen::Vector3f::UnitZ()));  // ceiling
  seg.update(v);
  ASSERT_EQ(seg.supervoxels().size(), 3u);
  const Supervoxel* outer = seg.find(supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kMinusX));
  const Supervoxel* inner = seg.find(supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kPlusX));
  const Supervoxel* ceiling = seg.find(supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kDown));
  ASSERT_TRUE(outer && inner && ceiling);
  EXPECT_EQ(outer->voxel_count, 30);
  EXPECT_EQ(inner->voxel_count, 30);
  EXPECT_EQ(ceiling->voxel_count, 18);
  EXPECT_NEAR(outer->normal.x(), -1.0, 1e-9);
  EXPECT_NEAR(inner->normal.x(), 1.0, 1e-9);
  EXPECT_NEAR(ceiling->normal.z(), -1.0, 1e-9);

  // A voxel whose normal turns joins the supervoxel of its new facing.
  VoxelSample turned = v[0];
  turned.normal = Eigen::Vector3f::UnitX();
  seg.update(std::span(&turned, 1));
  EXPECT_EQ(seg.find(supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kMinusX))->voxel_count, 29);
  EXPECT_EQ(seg.find(supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing::kPlusX))->voxel_count, 31);
}

TEST(SupervoxelKey, CarriesCellSurfaceAndFacing) {
  for (const core::GridCell cell : {core::GridCell{0, 0, 0}, core::GridCell{-5, 17, -3},
                                    core::GridCell{524287, -524288, 3}}) {
    for (int f = 0; f < kFacingCount; ++f) {
      const uint64_t key = supervoxel_key(cell, SurfaceClass::kFacade, Facing(f));
      EXPECT_EQ(seed_cell_of(key), cell);
      EXPECT_EQ(surface_of_key(key), SurfaceClass::kFacade);
      EXPECT_EQ(facing_of_key(key), Facing(f));
    }
    const uint64_t ground = supervoxel_key(cell, SurfaceClass::kGround);
    EXPECT_EQ(ground, core::seed_key(cell));
    EXPECT_EQ(seed_cell_of(ground), cell);
    EXPECT_EQ(surface_of_key(ground), SurfaceClass::kGround);
  }
  EXPECT_EQ(facing_of(Eigen::Vector3f(0.9f, 0.3f, 0.2f)), Facing::kPlusX);
  EXPECT_EQ(facing_of(Eigen::Vector3f(0.1f, -0.9f, 0.2f)), Facing::kMinusY);
  EXPECT_EQ(facing_of(Eigen::Vector3f(0.5f, 0.0f, -0.8f)), Facing::kDown);
  EXPECT_EQ(facing_of(Eigen::Vector3f(0.0f, 0.0f, 0.0f)), Facing::kNone);
}

TEST(Segmenter, SameVoxelSetGivesSameSupervoxelsInAnyDeltaOrder) {
  const auto voxels = campus_voxels(small_campus());
  SupervoxelSegmenter reference({}, kLevels);
  reference.update(voxels);
  ASSERT_GT(reference.supervoxels().size(), 100u);
  ASSERT_GT(reference.edge_count(), 100u);

  for (uint32_t seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    auto shuffled = voxels;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    SupervoxelSegmenter seg({}, kLevels);
    // Deltas of random size; some voxels first arrive with other attributes or class, and
    // some voxels that end up absent come and go.
    std::uniform_int_distribution<int> chunk(50, 800);
    std::uniform_int_distribution<int> coin(0, 39);
    size_t i = 0;
    while (i < shuffled.size()) {
      const size_t n = std::min<size_t>(chunk(rng), shuffled.size() - i);
      std::vector<VoxelSample> delta(shuffled.begin() + i, shuffled.begin() + i + n);
      std::vector<VoxelSample> later;
      for (auto& v : delta) {
        if (coin(rng) == 0) {
          VoxelSample wrong = v;
          wrong.flags ^= kVoxelGround;
          wrong.flags |= kVoxelCovered;
          wrong.low_risk_species_mask = 0b01;
          later.push_back(v);
          v = wrong;
        }
        if (coin(rng) == 0) {
          VoxelSample ghost = voxel_at({v.key.x, v.key.y, v.key.z + 40}, 0.15, kGroundFlags, 0b11, Eigen::Vector3f::UnitZ());
          seg.update(std::span(&ghost, 1));
          ghost.flags |= kVoxelRemoved;
          later.push_back(ghost);
        }
      }
      seg.update(delta);
      seg.update(later);
      i += n;
    }
    expect_same(reference, seg);
  }
}

TEST(Segmenter, IncrementalUpdatesMatchFullSegmentation) {
  auto voxels = campus_voxels(small_campus());
  std::mt19937 rng(11);
  SupervoxelSegmenter seg({}, kLevels);
  seg.update(voxels);
  // Remove a corridor, change classes in a patch and add a ramp, in several deltas.
  std::map<core::GridCell, VoxelSample> current;
  for (const auto& v : voxels) current[v.key] = v;
  for (int round = 0; round < 6; ++round) {
    std::vector<VoxelSample> delta;
    std::uniform_int_distribution<int> pick(0, static_cast<int>(voxels.size()) - 1);
    for (int k = 0; k < 300; ++k) {
      VoxelSample v = voxels[pick(rng)];
      switch (k % 3) {
        case 0: v.flags |= kVoxelRemoved; current.erase(v.key); break;
        case 1: v.flags ^= kVoxelGround; current[v.key] = v; break;
        default: v.key.z += 3; current[v.key] = v; break;
      }
      delta.push_back(v);
    }
    const auto change = seg.update(delta);
    EXPECT_FALSE(change.empty());
  }
  std::vector<VoxelSample> final_set;
  for (const auto& [k, v] : current) final_set.push_back(v);
  SupervoxelSegmenter fresh({}, kLevels);
  fresh.update(final_set);
  EXPECT_EQ(seg.voxel_count(), final_set.size());
  expect_same(fresh, seg);
}

TEST(Segmenter, ReplaceAllDropsVoxelsMissingFromASnapshot) {
  auto voxels = campus_voxels(small_campus());
  SupervoxelSegmenter seg({}, kLevels);
  seg.update(voxels);
  const std::vector<VoxelSample> half(voxels.begin(), voxels.begin() + voxels.size() / 2);
  seg.replace_all(half);
  SupervoxelSegmenter fresh({}, kLevels);
  fresh.update(half);
  EXPECT_EQ(seg.voxel_count(), half.size());
  expect_same(fresh, seg);
}

TEST(Segmenter, ReportsChangesThatReproduceTheMap) {
  // Replaying the reported changes must rebuild exactly the segmenter's map.
  const auto voxels = campus_voxels(small_campus());
  SupervoxelSegmenter seg({}, kLevels);
  std::map<uint64_t, Supervoxel> replay;
  std::set<EdgeKey> replay_edges;
  for (size_t i = 0; i < voxels.size(); i += 500) {
    const size_t n = std::min<size_t>(500, voxels.size() - i);
    const auto change = seg.update(std::span(voxels.data() + i, n));
    for (uint64_t k : change.removed) replay.erase(k);
    for (uint64_t k : change.upserted) replay[k] = *seg.find(k);
    for (const auto& e : change.edges_removed) replay_edges.erase(e);
    for (const auto& e : change.edges_added) replay_edges.insert(e);
  }
  ASSERT_EQ(replay.size(), seg.supervoxels().size());
  for (const auto& [k, sv] : replay) EXPECT_EQ(sv, *seg.find(k));
  const auto edges = seg.edges();
  EXPECT_EQ(std::vector<EdgeKey>(replay_edges.begin(), replay_edges.end()), edges);
}

}  // namespace
}  // namespace hexplore::highlevel
