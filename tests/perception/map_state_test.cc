// Teammate filtering, invalid points, change tracking, snapshots and save/load.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "common/perception/voxel_proto.h"
#include "tests/perception/synthetic_scene.h"

namespace hexplore::perception {
namespace {

using testing::add_floor;
using testing::add_patch;
using testing::pack;
using testing::scan_of;
using testing::two_species_params;

std::set<uint64_t> keys_of(const std::vector<VoxelView>& vs) {
  std::set<uint64_t> out;
  for (const VoxelView& v : vs) out.insert(pack(v.key));
  return out;
}

std::set<uint64_t> keys_of_points(const PerceptionMap& map, const std::vector<float>& pts) {
  std::set<uint64_t> out;
  for (size_t i = 0; i < pts.size(); i += 3) out.insert(pack(map.key_of({pts[i], pts[i + 1], pts[i + 2]})));
  return out;
}

void expect_same_voxels(const PerceptionMap& a, const PerceptionMap& b) {
  const std::vector<VoxelView> va = a.voxels();
  const std::vector<VoxelView> vb = b.voxels();
  ASSERT_EQ(va.size(), vb.size());
  for (size_t i = 0; i < va.size(); ++i) {
    EXPECT_EQ(va[i].key, vb[i].key);
    EXPECT_EQ(va[i].point_count, vb[i].point_count);
    EXPECT_EQ(va[i].mean, vb[i].mean);
    EXPECT_EQ(va[i].normal, vb[i].normal);
    EXPECT_EQ(va[i].flags, vb[i].flags);
    EXPECT_EQ(va[i].low_risk_species_mask, vb[i].low_risk_species_mask);
    EXPECT_EQ(va[i].observation_density, vb[i].observation_density);
  }
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("hexplore_perception_" + name)).string();
}

TEST(MapState, TeammateBodyNeverEntersTheMap) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -3, 3, -3, 3, 0.05, 0.03);
  const size_t floor_points = pts.size() / 3;
  // A teammate yawed by 30 deg standing at (1.5, 0.5): sample the sides and top of its body.
  OrientedBox body;
  body.centre = {1.5, 0.5, 0.4};
  body.orientation = Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ());
  body.half_extents_m = {0.5, 0.35, 0.35};
  const Eigen::Matrix3d r = body.orientation.toRotationMatrix();
  const Eigen::Vector3d h = body.half_extents_m;
  std::vector<float> body_pts;
  add_patch(body_pts, body.centre + r * Eigen::Vector3d(-h.x(), -h.y(), h.z()), r * Eigen::Vector3d(2 * h.x(), 0, 0),
            r * Eigen::Vector3d(0, 2 * h.y(), 0), 0.02);
  add_patch(body_pts, body.centre + r * Eigen::Vector3d(-h.x(), -h.y(), -h.z()), r * Eigen::Vector3d(2 * h.x(), 0, 0),
            r * Eigen::Vector3d(0, 0, 2 * h.z()), 0.02);
  pts.insert(pts.end(), body_pts.begin(), body_pts.end());
  const IntegrationStats stats = map.integrate(scan_of(pts, {0, 0, 1}), {body});
  EXPECT_GE(stats.dropped_teammate, body_pts.size() / 3);
  EXPECT_LT(stats.dropped_teammate, body_pts.size() / 3 + floor_points / 20) << "only the floor under the body goes too";
  for (const VoxelView& v : map.voxels()) EXPECT_LT(v.mean.z(), 0.1f) << "body voxel at " << v.mean.transpose();
}

TEST(MapState, NonFinitePointsAreDroppedCountedAndChangeNothing) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -2, 2, -2, 2, 0.05, 0.02);
  map.integrate(scan_of(pts, {0, 0, 1}), {});
  map.take_changes();
  PerceptionMap reference(two_species_params());
  reference.integrate(scan_of(pts, {0, 0, 1}), {});

  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> bad = {nan, 0, 0, 0, inf, 0, 1, 1, -inf, nan, nan, nan};
  const IntegrationStats stats = map.integrate(scan_of(bad, {0, 0, 1}), {});
  EXPECT_EQ(stats.points_in, 4u);
  EXPECT_EQ(stats.dropped_non_finite, 4u);
  EXPECT_EQ(stats.points_integrated, 0u);
  EXPECT_EQ(map.pending_changes(), 0u);
  expect_same_voxels(map, reference);

  // Mixed: the finite points integrate exactly as if alone.
  std::vector<float> patch;
  add_floor(patch, 5, 6, 5, 6, 0.05, 0.02);
  std::vector<float> mixed = patch;
  mixed.insert(mixed.end(), bad.begin(), bad.end());
  const IntegrationStats mixed_stats = map.integrate(scan_of(mixed, {5.5, 5.5, 1}), {});
  reference.integrate(scan_of(patch, {5.5, 5.5, 1}), {});
  EXPECT_EQ(mixed_stats.dropped_non_finite, 4u);
  expect_same_voxels(map, reference);

  ScanPoints no_origin = scan_of(patch, {nan, 0, 1});
  EXPECT_THROW(map.integrate(no_origin, {}), std::invalid_argument);
  expect_same_voxels(map, reference);
}

TEST(MapState, PointsBeyondMaxRangeAreDropped) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, 0, 1, 0, 1, 0.05, 0.05);
  add_floor(pts, 50, 51, 0, 1, 0.05, 0.05);
  ScanPoints scan = scan_of(pts, {0, 0, 1});
  scan.max_range_m = 40;
  const IntegrationStats stats = map.integrate(scan, {});
  EXPECT_EQ(stats.dropped_out_of_range, pts.size() / 6);
  for (const VoxelView& v : map.voxels()) EXPECT_LT(v.mean.x(), 2);
}

TEST(MapState, DeltaTrackingReportsExactlyTheChangedVoxels) {
  PerceptionMap map(two_species_params());
  std::vector<float> a;
  add_floor(a, -2, 2, -2, 2, 0.05, 0.02);
  const Eigen::Vector3d far_sensor(0, 0, 30);  // beyond l_th: observations never qualify
  map.integrate(scan_of(a, far_sensor), {});
  const std::vector<VoxelView> first = map.take_changes();
  EXPECT_EQ(keys_of(first), keys_of(map.voxels())) << "every new voxel is a change";
  EXPECT_TRUE(map.take_changes().empty());

  // The same points again: Gaussians grow but mean, normal, flags and masks stay.
  map.integrate(scan_of(a, far_sensor), {});
  EXPECT_TRUE(map.take_changes().empty());

  // A disjoint patch: exactly its own voxels.
  std::vector<float> b;
  add_floor(b, 20, 21, 20, 21, 0.05, 0.02);
  map.integrate(scan_of(b, {20.5, 20.5, 30}), {});
  EXPECT_EQ(keys_of(map.take_changes()), keys_of_points(map, b));

  // A wall on the floor: the wall, plus the floor voxels whose risk changed next to it.
  std::map<uint64_t, VoxelView> before;
  for (const VoxelView& v : map.voxels()) before[pack(v.key)] = v;
  std::vector<float> w;
  add_patch(w, {1.0, -2, 0.05}, {0, 4, 0}, {0, 0, 1.5}, 0.02);
  map.integrate(scan_of(w, {0, 0, 30}), {});
  std::set<uint64_t> expected;
  for (const VoxelView& v : map.voxels()) {
    const auto it = before.find(pack(v.key));
    if (it == before.end()) {
      expected.insert(pack(v.key));
      continue;
    }
    const VoxelView& o = it->second;
    const bool moved = (v.mean - o.mean).norm() > 0.01f;
    const bool turned = v.normal.dot(o.normal) < std::cos(5.0 * M_PI / 180.0);
    if (moved || turned || v.flags != o.flags || v.low_risk_species_mask != o.low_risk_species_mask) {
      expected.insert(pack(v.key));
    }
  }
  const std::set<uint64_t> reported = keys_of(map.take_changes());
  EXPECT_EQ(reported, expected);
  EXPECT_GT(expected.size(), keys_of_points(map, w).size()) << "floor next to the wall changed too";
}

TEST(MapState, SaveLoadRoundTripsAndResumes) {
  const std::string path = temp_path("roundtrip.map");
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -2, 2, -2, 2, 0.05, 0.02);
  add_patch(pts, {1.0, -2, 0.05}, {0, 4, 0}, {0, 0, 1.5}, 0.01);
  map.integrate(scan_of(pts, {0, 0, 1}), {});
  map.save(path);

  PerceptionMap loaded(two_species_params());
  loaded.load(path);
  EXPECT_EQ(loaded.voxel_count(), map.voxel_count());
  expect_same_voxels(map, loaded);
  EXPECT_EQ(loaded.pending_changes(), 0u);

  std::vector<float> more;
  add_floor(more, -4, -2, -2, 2, 0.05, 0.02);
  map.integrate(scan_of(more, {-3, 0, 1}), {});
  loaded.integrate(scan_of(more, {-3, 0, 1}), {});
  expect_same_voxels(map, loaded);

  PerceptionMap empty(two_species_params());
  empty.save(path);
  loaded.load(path);
  EXPECT_EQ(loaded.voxel_count(), 0u);
  std::remove(path.c_str());
}

TEST(MapState, CorruptTruncatedOrForeignFilesGiveClearErrors) {
  const std::string path = temp_path("corrupt.map");
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, -1, 1, -1, 1, 0.05, 0.02);
  map.integrate(scan_of(pts, {0, 0, 1}), {});
  map.save(path);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto write = [&](const std::string& b) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  auto error_of = [&](PerceptionMap& m) -> std::string {
    try {
      m.load(path);
    } catch (const MapFileError& e) {
      return e.what();
    }
    return "";
  };
  PerceptionMap target(two_species_params());
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x5A;
  write(flipped);
  EXPECT_NE(error_of(target).find("checksum"), std::string::npos);
  write(bytes.substr(0, bytes.size() - 100));
  EXPECT_NE(error_of(target).find("truncated"), std::string::npos);
  write(bytes.substr(0, 20));
  EXPECT_NE(error_of(target).find("truncated header"), std::string::npos);
  write("not a map at all, just some text that is long enough to fill a header");
  EXPECT_NE(error_of(target).find("bad magic"), std::string::npos);
  write(bytes);
  MapParams other = two_species_params();
  other.resolution_m = 0.1;
  PerceptionMap other_res(other);
  EXPECT_NE(error_of(other_res).find("resolution"), std::string::npos);
  EXPECT_NE(error_of(other_res).find(path), std::string::npos) << "errors name the file";
  EXPECT_EQ(target.voxel_count(), 0u) << "failed loads leave the map untouched";
  target.load(path);
  EXPECT_EQ(target.voxel_count(), map.voxel_count());
  std::filesystem::remove(path);
  EXPECT_NE(error_of(target).find("cannot open"), std::string::npos);
}

TEST(MapState, ProtoConversion) {
  PerceptionMap map(two_species_params());
  std::vector<float> pts;
  add_floor(pts, 0, 1, 0, 1, 0.05, 0.02);
  map.integrate(scan_of(pts, {0.5, 0.5, 1}), {});
  const std::vector<VoxelView> all = map.voxels();
  const v1::VoxelDelta delta = to_voxel_delta(all, map.resolution(), true);
  ASSERT_EQ(delta.voxels_size(), static_cast<int>(all.size()));
  EXPECT_TRUE(delta.full_snapshot());
  const v1::Voxel& v = delta.voxels(0);
  EXPECT_EQ(v.ix(), all[0].key.x);
  EXPECT_NEAR((v.ix() + 0.5) * delta.resolution_m(), v.mean_x(), 0.075 + 1e-6);
  EXPECT_EQ(v.flags(), all[0].flags);
  const v1::OccupiedVoxels occupied = to_occupied_voxels(all, map.resolution());
  EXPECT_EQ(occupied.keys_xyz_size(), static_cast<int>(3 * all.size()));

  v1::ScanFrame frame;
  frame.set_points_xyz_f32(std::string(reinterpret_cast<const char*>(pts.data()), pts.size() * sizeof(float)));
  frame.set_point_count(static_cast<uint32_t>(pts.size() / 3));
  std::vector<float> storage;
  ScanPoints decoded;
  EXPECT_EQ(decode_scan(frame, storage, decoded), ScanRejection::kNone);
  EXPECT_EQ(decoded.count, pts.size() / 3);
  EXPECT_EQ(storage, pts);
  frame.set_point_count(frame.point_count() + 1);
  EXPECT_EQ(decode_scan(frame, storage, decoded), ScanRejection::kSizeMismatch);
  frame.set_point_count(frame.point_count() - 1);
  frame.mutable_sensor_origin_m()->set_x(std::numeric_limits<double>::infinity());
  EXPECT_EQ(decode_scan(frame, storage, decoded), ScanRejection::kBadOrigin);
}

}  // namespace
}  // namespace hexplore::perception
