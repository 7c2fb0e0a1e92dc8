// PerceptionMap::save / load: a small self-describing header around octomap's node stream.

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/perception/perception_map.h"

namespace hexplore::perception {
namespace {

constexpr char kMagic[8] = {'H', 'X', 'P', 'M', 'A', 'P', '\r', '\n'};  // \r\n catches text-mode mangling
// 2: VoxelData keeps failed-observation minima and the published coverage gap.
// 3: a 16-bit point count and the fused-surface density.
constexpr uint32_t kVersion = 3;

struct FileHeader {
  char magic[8];
  uint32_t version;
  uint32_t voxel_data_bytes;  // sizeof(VoxelData): the node layout the stream was written with
  double resolution_m;
  uint32_t species_count;
  uint32_t reserved;
  uint64_t voxel_count;
  uint64_t payload_bytes;
  uint64_t payload_fnv1a;
};
static_assert(sizeof(FileHeader) == 56);

uint64_t fnv1a(const std::string& bytes) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

void PerceptionMap::save(const std::string& path) const {
  std::ostringstream payload_stream(std::ios::binary);
  tree_.writeData(payload_stream);
  const std::string payload = payload_stream.str();
  FileHeader h{};
  std::memcpy(h.magic, kMagic, sizeof(kMagic));
  h.version = kVersion;
  h.voxel_data_bytes = sizeof(VoxelData);
  h.resolution_m = params_.resolution_m;
  h.species_count = static_cast<uint32_t>(params_.species.size());
  h.voxel_count = voxel_count_;
  h.payload_bytes = payload.size();
  h.payload_fnv1a = fnv1a(payload);
  // Write beside the target and rename, so a crash mid-save never leaves a truncated map.
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw MapFileError("perception map save: cannot open '" + tmp + "' for writing");
    out.write(reinterpret_cast<const char*>(&h), sizeof(h));
    out.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    out.flush();
    if (!out) throw MapFileError("perception map save: write to '" + tmp + "' failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    throw MapFileError("perception map save: cannot rename '" + tmp + "' to '" + path + "'");
  }
}

void PerceptionMap::load(const std::string& path) {
  auto fail = [&](const std::string& what) { throw MapFileError("perception map '" + path + "': " + what); };
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open for reading");
  FileHeader h{};
  in.read(reinterpret_cast<char*>(&h), sizeof(h));
  if (in.gcount() != static_cast<std::streamsize>(sizeof(h))) fail("truncated header");
  if (std::memcmp(h.magic, kMagic, sizeof(kMagic)) != 0) fail("not a hexplore perception map (bad magic)");
  if (h.version != kVersion) fail("unsupported version " + std::to_string(h.version));
  if (h.voxel_data_bytes != sizeof(VoxelData)) {
    fail("voxel layout of " + std::to_string(h.voxel_data_bytes) + " bytes, this build uses " +
         std::to_string(sizeof(VoxelData)));
  }
  if (h.resolution_m != params_.resolution_m) {
    fail("resolution " + std::to_string(h.resolution_m) + " m differs from the configured " +
         std::to_string(params_.resolution_m) + " m");
  }
  if (h.species_count != params_.species.size()) {
    fail("built for " + std::to_string(h.species_count) + " species, the team has " +
         std::to_string(params_.species.size()));
  }
  if (h.payload_bytes > (uint64_t{1} << 40)) fail("implausible payload size");
  std::string payload(h.payload_bytes, '\0');
  in.read(payload.data(), static_cast<std::streamsize>(payload.size()));
  if (static_cast<uint64_t>(in.gcount()) != h.payload_bytes) {
    fail("truncated: " + std::to_string(in.gcount()) + " of " + std::to_string(h.payload_bytes) + " payload bytes");
  }
  if (in.peek() != std::char_traits<char>::eof()) fail("trailing bytes after the payload");
  if (fnv1a(payload) != h.payload_fnv1a) fail("payload checksum mismatch (corrupt file)");

  VoxelOcTree loaded(params_.resolution_m);
  if (payload.empty()) {  // an empty map writes no nodes at all
    if (h.voxel_count != 0) fail("no octree payload but the header says " + std::to_string(h.voxel_count) + " voxels");
    tree_.swapContent(loaded);
    voxel_count_ = 0;
    changed_.clear();
    return;
  }
  std::istringstream payload_stream(payload, std::ios::binary);
  loaded.readData(payload_stream);
  if (!payload_stream) fail("octree stream could not be parsed");
  size_t leaves = 0;
  for (auto it = loaded.begin_leafs(), end = loaded.end_leafs(); it != end; ++it) {
    if (it.getDepth() != loaded.getTreeDepth()) fail("octree has a leaf above voxel depth");
    VoxelData& d = it->data();
    d.flags &= static_cast<uint8_t>(~(kFlagChangePending | kFlagScratchGeometry | kFlagScratchRisk | kFlagScratchTouched));
    ++leaves;
  }
  if (leaves != h.voxel_count) {
    fail("holds " + std::to_string(leaves) + " voxels, header says " + std::to_string(h.voxel_count));
  }
  tree_.swapContent(loaded);
  voxel_count_ = leaves;
  changed_.clear();
}

}  // namespace hexplore::perception
