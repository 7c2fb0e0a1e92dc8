#pragma once
// team/map increments (and the repair snapshots peers ask for) on the radio. Supervoxels and
// edges travel column by column so that zstd (transport compression) finds the repetition:
//   keys     seed-cell steps from the previous key (sorted keys step by one cell), facade bit
//   flags    removed, covered, surface
//   centres  1/64 m steps from the seed cell's centre (highlevel::wire_precision), a byte or
//            two per axis where a float took four
//   normals  16-bit octahedral
//   counts   traversal requirement, voxel count, and for incomplete supervoxels the covered
//            voxels and the coverage gap
//   edges    each endpoint as seed-cell steps (the second from the first)
// The source robot is a roster slot. Edge lengths are not carried: receivers recompute them
// from the centres (HighLevelMap::apply does), so they decode as zero. A source fuses its own
// contribution at exactly the precision decoded here (highlevel::wire_rounded).

#include "common/transport/payload_codec.h"

namespace hexplore::radio {

// One codec class for both message types (they share their fields); `snapshot` picks which.
class MapCodec : public transport::PayloadCodec {
 public:
  // `eta_s_m`: the team's seed interval (params.eta_s_m), which turns a key into a position
  // near the centre; only the size of the encoding depends on it.
  MapCodec(bool snapshot, double eta_s_m) : snapshot_(snapshot), eta_s_m_(eta_s_m) {}
  const std::string& type() const override;
  void encode(const google::protobuf::MessageLite& message, const transport::Roster* roster,
              std::string& out) const override;
  bool decode(std::string_view data, const transport::Roster* roster,
              google::protobuf::MessageLite& message) const override;
  // map_dictionary(): a one-second increment is too small for zstd to find much alone.
  const transport::CompressionDictionary* dictionary() const override;

 private:
  bool snapshot_;
  double eta_s_m_;
};

}  // namespace hexplore::radio
