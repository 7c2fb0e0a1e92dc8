#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include <octomap/OcTree.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include "common/evaluation/map_export.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::evaluation {
namespace {

const std::vector<Eigen::Vector3f> kPoints = {{0.075f, 0.075f, 0.075f}, {1.075f, 0.075f, 2.075f}, {3.075f, 2.075f, 4.075f}};

TEST(MapExport, EachFileLoadsBackWithItsLibrary) {
  const hexplore::testing::ScratchDir scratch("map_export_test");
  const auto files = export_map(kPoints, 0.15, scratch.path().string());
  ASSERT_EQ(files.size(), 3u);

  for (const char* name : {"map.ply", "map.pcd"}) {
    pcl::PointCloud<pcl::PointXYZRGB> cloud;
    const std::string path = (scratch.path() / name).string();
    const int rc = std::string(name).ends_with(".ply") ? pcl::io::loadPLYFile(path, cloud) : pcl::io::loadPCDFile(path, cloud);
    ASSERT_EQ(rc, 0) << name;
    ASSERT_EQ(cloud.size(), kPoints.size()) << name;
    EXPECT_NEAR(cloud[1].x, 1.075f, 1e-6) << name;
    EXPECT_NEAR(cloud[2].z, 4.075f, 1e-6) << name;
    // Coloured by height: the lowest point blue, the highest red.
    EXPECT_GT(cloud[0].b, cloud[0].r) << name;
    EXPECT_GT(cloud[2].r, cloud[2].b) << name;
  }

  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary((scratch.path() / "map.bt").string()));
  EXPECT_DOUBLE_EQ(tree.getResolution(), 0.15);
  for (const auto& p : kPoints) {
    const octomap::OcTreeNode* node = tree.search(p.x(), p.y(), p.z());
    ASSERT_NE(node, nullptr);
    EXPECT_TRUE(tree.isNodeOccupied(node));
  }
  EXPECT_EQ(tree.search(2.0, 2.0, 0.5), nullptr);  // nothing was mapped there
}

TEST(MapExport, AnEmptyMapWritesNothingAndABadResolutionIsAnError) {
  const hexplore::testing::ScratchDir scratch("map_export_empty");
  EXPECT_TRUE(export_map({}, 0.15, scratch.path().string()).empty());
  EXPECT_THROW(export_map(kPoints, 0.0, scratch.path().string()), std::invalid_argument);
  EXPECT_THROW(export_map(kPoints, 0.15, "/proc/hexplore-cannot-write"), std::runtime_error);
}

TEST(MapExport, TheMapsPointsReadBackFromItsPcd) {
  const hexplore::testing::ScratchDir scratch("map_export_read_back");
  export_map(kPoints, 0.15, scratch.path().string());
  EXPECT_EQ(load_map_points((scratch.path() / "map.pcd").string()), kPoints);
  EXPECT_THROW(load_map_points((scratch.path() / "missing.pcd").string()), std::runtime_error);
}

TEST(MapExport, HeightColourRunsFromBlueToRed) {
  EXPECT_EQ(height_colour(0.0, 0.0, 10.0), Eigen::Vector3i(40, 70, 220));
  EXPECT_EQ(height_colour(10.0, 0.0, 10.0), Eigen::Vector3i(215, 40, 40));
  EXPECT_EQ(height_colour(-5.0, 0.0, 10.0), height_colour(0.0, 0.0, 10.0));  // clamped
  EXPECT_EQ(height_colour(3.0, 3.0, 3.0), Eigen::Vector3i(40, 70, 220));     // a flat map
}

}  // namespace
}  // namespace hexplore::evaluation
