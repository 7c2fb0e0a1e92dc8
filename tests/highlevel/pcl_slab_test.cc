// The paper's claim about noisy ground ("Supervoxel Segmentation", Fig. cluster-noisy-ground):
// on a LiDAR-thickened ground slab the original supervoxel clustering (PCL's
// SupervoxelClustering, Papon et al.) seeds both seed layers the slab straddles and splits the
// ground of one seed column into two supervoxels, while the improved segmentation (BFS seed
// merging within eta_e) keeps exactly one ground supervoxel per column spanning the thickness.
// PCL is included only here.

#include <map>
#include <set>

#include <gtest/gtest.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include "common/highlevel/segmenter.h"
#include "tests/highlevel/synthetic_map.h"

namespace hexplore::highlevel {
namespace {

constexpr double kResolution = 0.05;  // perception voxels; the +/-5 cm noise spans 2-3 of them
constexpr double kSeed = 1.0;         // eta_s
constexpr double kSize = 8.0;

struct ColumnCounts {
  size_t columns = 0;        // eta_s columns holding a supervoxel centre
  size_t split_columns = 0;  // columns holding more than one
  size_t supervoxels = 0;
};

ColumnCounts count_columns(const std::vector<Eigen::Vector3d>& centres) {
  std::map<std::pair<int, int>, int> per_column;
  for (const auto& c : centres) per_column[{static_cast<int>(std::floor(c.x() / kSeed)), static_cast<int>(std::floor(c.y() / kSeed))}]++;
  ColumnCounts out;
  out.columns = per_column.size();
  out.supervoxels = centres.size();
  for (const auto& [column, n] : per_column)
    if (n > 1) ++out.split_columns;
  return out;
}

TEST(NoisyGroundSlab, PclSupervoxelsSplitTheSlabImprovedSegmentationDoesNot) {
  const auto points = testing::noisy_slab_points(kSize, kSize, 0.0, 0.05, 1600.0, 1);

  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : points) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::SupervoxelClustering<pcl::PointXYZ> pcl_clustering(static_cast<float>(kResolution), static_cast<float>(kSeed));
  pcl_clustering.setUseSingleCameraTransform(false);
  pcl_clustering.setInputCloud(cloud);
  pcl_clustering.setSpatialImportance(1.0f);
  pcl_clustering.setNormalImportance(1.0f);
  pcl_clustering.setColorImportance(0.0f);
  std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZ>::Ptr> clusters;
  pcl_clustering.extract(clusters);
  std::vector<Eigen::Vector3d> pcl_centres;
  for (const auto& [label, sv] : clusters) pcl_centres.push_back(sv->centroid_.getVector3fMap().cast<double>());
  const ColumnCounts pcl = count_columns(pcl_centres);

  testing::Voxelizer vox(kResolution);
  for (const auto& p : points) vox.add(p, testing::kGroundFlags, 0b1, Eigen::Vector3f::UnitZ());
  SegmenterParams params;
  params.resolution_m = kResolution;
  params.eta_s_m = kSeed;
  SupervoxelSegmenter improved(params, {1});
  improved.update(vox.samples());
  std::vector<Eigen::Vector3d> improved_centres;
  for (const auto& [key, sv] : improved.supervoxels()) improved_centres.push_back(sv.center);
  const ColumnCounts ours = count_columns(improved_centres);

  std::printf("PCL SupervoxelClustering: %zu supervoxels in %zu columns, %zu columns split\n", pcl.supervoxels,
              pcl.columns, pcl.split_columns);
  std::printf("improved segmentation:    %zu supervoxels in %zu columns, %zu columns split\n", ours.supervoxels,
              ours.columns, ours.split_columns);
  const size_t area_columns = static_cast<size_t>(kSize * kSize / (kSeed * kSeed));
  EXPECT_EQ(ours.supervoxels, area_columns);
  EXPECT_EQ(ours.split_columns, 0u);
  EXPECT_GT(pcl.supervoxels, area_columns * 3 / 2) << "PCL seeds both layers of the thick slab";
  EXPECT_GT(pcl.split_columns, area_columns / 4);
}

}  // namespace
}  // namespace hexplore::highlevel
