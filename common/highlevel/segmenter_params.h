#pragma once
// The supervoxel segmenter's parameters: seed interval, merge distance, wavefront range and the
// patch size that keeps a supervoxel an ISE, and how the team's parameters become them.

namespace hexplore::core {
struct AlgorithmParams;
}

namespace hexplore::highlevel {

struct SegmenterParams {
  double resolution_m = 0.15;  // perception-map voxel size
  double eta_s_m = 1.0;        // seed interval
  double eta_e_m = 0.2;        // seeds of adjacent cells closer than this are merged
  // Wavefront range in voxel hops; 0 = the largest range not exceeding eta_s / 2 + a quarter
  // cell (about 0.75 eta_s). Voxels out of reach of every seed join their own cell's seed.
  int max_hops = 0;
  // A supervoxel is an ISE while it holds a connected patch (26-neighbourhood) of at least
  // this many incomplete voxels. The paper segments the ISE voxels on their own, dropping
  // seeds with too few neighbours as noise, so scattered incomplete voxels at the edges of a
  // covered surface never make an ISE supervoxel; 1 is the literal "every voxel covered" rule.
  // common/planning/README.md ("The coverage model") has the measured effect.
  int min_ise_patch_voxels = 1;

  // The team's (params: map_resolution_m, eta_s_m, eta_e_m, min_ise_patch_voxels), as every
  // hlmap service segments with.
  static SegmenterParams from(const core::AlgorithmParams& params);
  // Throws std::invalid_argument naming the bad field.
  void validate() const;
};

}  // namespace hexplore::highlevel
