// The map codec: increments and snapshots round-trip exactly at wire precision, so that a
// source's own contribution (fused as highlevel::wire_rounded) and what its peers decode are
// the same supervoxels, bit for bit; edges and removals survive; malformed frames are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "common/highlevel/map_proto.h"
#include "common/highlevel/supervoxel.h"
#include "common/highlevel/wire_precision.h"
#include "common/radio/map_codec.h"
#include "common/radio/map_dictionary.h"
#include "common/transport/envelope.h"
#include "common/transport/payload_wire.h"
#include "common/transport/type_id.h"
#include "hexplore/v1/hlmap.pb.h"
#include "tests/radio/codec_fixtures.h"

namespace hexplore::radio {
namespace {

using testing::decode;
using testing::encode;

constexpr double kEtaS = 1.0;

// Supervoxels grown from neighbouring seed cells of a patch, as a segmenter produces them.
std::vector<highlevel::Supervoxel> patch(uint32_t seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.6, 0.6);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<highlevel::Supervoxel> out;
  for (int i = 0; i < count; ++i) {
    highlevel::Supervoxel s;
    const core::GridCell cell{10 + i % 7, -3 + i / 7, i % 5 == 0 ? 1 : 0};
    s.surface = i % 3 == 0 ? highlevel::SurfaceClass::kFacade : highlevel::SurfaceClass::kGround;
    s.key = highlevel::supervoxel_key(cell, s.surface);
    s.center = core::cell_center(cell, kEtaS) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    s.normal = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    s.covered = i % 4 == 0;
    s.traversal_requirement = s.ground() ? 1 + i % 3 : 0;
    s.voxel_count = 5 + static_cast<int>(rng() % 300);
    s.covered_voxels = s.covered ? s.voxel_count : s.voxel_count / 3;
    s.gap = s.covered ? core::CoverageGap::kNone : static_cast<core::CoverageGap>(1 + rng() % 4);
    out.push_back(highlevel::wire_rounded(s));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
  return out;
}

highlevel::SourcedUpdate increment(uint32_t seed) {
  highlevel::SourcedUpdate inc;
  inc.source = "mr1000a";
  inc.seq = 42;
  inc.update.upserts = patch(seed, 60);
  inc.update.removals = {core::seed_key({3, 3, 0}), core::seed_key({4, 3, 0}) | highlevel::kFacadeKeyBit};
  for (size_t i = 0; i + 1 < inc.update.upserts.size(); i += 2)
    if (inc.update.upserts[i].ground() && inc.update.upserts[i + 1].ground())
      inc.update.edge_upserts.push_back(highlevel::EdgeKey::of(inc.update.upserts[i].key, inc.update.upserts[i + 1].key));
  inc.update.edge_removals.push_back(highlevel::EdgeKey::of(core::seed_key({1, 1, 0}), core::seed_key({2, 1, 0})));
  return inc;
}

highlevel::Contribution contribution_of(const highlevel::SourcedUpdate& inc) {
  highlevel::Contribution c;
  c.apply(inc.update);
  return c;
}

TEST(WirePrecision, PackedNormalsAreStableAndClose) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d n = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const highlevel::PackedNormal p = highlevel::pack_normal(n);
    const Eigen::Vector3d back = highlevel::unpack_normal(p);
    EXPECT_LT(std::acos(std::clamp(back.dot(n), -1.0, 1.0)), 1.0 * M_PI / 180.0);
    // Packing what unpacking gave yields the same bytes: a re-sent supervoxel never drifts.
    const highlevel::PackedNormal again = highlevel::pack_normal(back);
    EXPECT_EQ(again.u, p.u);
    EXPECT_EQ(again.v, p.v);
  }
  EXPECT_EQ(highlevel::unpack_normal(highlevel::pack_normal(Eigen::Vector3d::Zero())), Eigen::Vector3d::UnitZ());
}

TEST(MapCodec, PeersDecodeExactlyWhatTheSourceFuses) {
  const MapCodec codec(false, kEtaS);
  const auto roster = testing::roster();
  const highlevel::SourcedUpdate inc = increment(1);
  const v1::MapIncrement message = highlevel::to_increment(inc, contribution_of(inc));
  const std::string wire = encode(codec, message, &roster);
  EXPECT_LT(wire.size() * 3, message.ByteSizeLong());
  v1::MapIncrement decoded;
  ASSERT_TRUE(decode(codec, wire, &roster, decoded));
  const highlevel::SourcedUpdate back = highlevel::from_proto(decoded);
  EXPECT_EQ(back.source, "mr1000a");
  EXPECT_EQ(back.seq, 42u);
  ASSERT_EQ(back.update.upserts.size(), inc.update.upserts.size());
  for (size_t i = 0; i < inc.update.upserts.size(); ++i) EXPECT_EQ(back.update.upserts[i], inc.update.upserts[i]) << i;
  EXPECT_EQ(back.update.removals, inc.update.removals);
  EXPECT_EQ(back.update.edge_upserts, inc.update.edge_upserts);
  EXPECT_EQ(back.update.edge_removals, inc.update.edge_removals);
}

TEST(MapCodec, SnapshotsRoundTripToo) {
  const MapCodec codec(true, kEtaS);
  const highlevel::SourcedUpdate inc = increment(2);
  const highlevel::Contribution c = contribution_of(inc);
  highlevel::SourcedUpdate snap{"slugcat2", 9, c.snapshot()};
  const v1::MapSnapshot message = highlevel::to_snapshot(snap, c);
  v1::MapSnapshot decoded;
  ASSERT_TRUE(decode(codec, encode(codec, message, nullptr), nullptr, decoded));  // named source
  const highlevel::SourcedUpdate back = highlevel::from_proto(decoded);
  EXPECT_EQ(back.source, "slugcat2");
  EXPECT_EQ(back.seq, 9u);
  EXPECT_TRUE(back.update.full_snapshot);
  EXPECT_EQ(back.update.upserts, snap.update.upserts);
  EXPECT_EQ(back.update.edge_upserts, snap.update.edge_upserts);
}

TEST(MapCodec, AReceiversCopyHasTheDigestTheSourceSent) {
  const MapCodec codec(false, kEtaS);
  const auto roster = testing::roster();
  highlevel::SourcedUpdate inc = increment(4);
  const highlevel::Contribution source = contribution_of(inc);
  inc.digest = source.digest();
  v1::MapIncrement decoded;
  ASSERT_TRUE(decode(codec, encode(codec, highlevel::to_increment(inc, source), &roster), &roster, decoded));
  const highlevel::SourcedUpdate back = highlevel::from_proto(decoded);
  EXPECT_EQ(back.digest, inc.digest);
  highlevel::Contribution copy;
  copy.apply(back.update);
  EXPECT_EQ(copy.digest(), back.digest);
}

TEST(MapCodec, TheDigestSeesEveryDifferenceThatTravelsAndNoOrder) {
  const highlevel::SourcedUpdate inc = increment(5);
  const highlevel::Contribution c = contribution_of(inc);
  highlevel::SourcedUpdate reversed = inc;
  std::reverse(reversed.update.upserts.begin(), reversed.update.upserts.end());
  std::reverse(reversed.update.edge_upserts.begin(), reversed.update.edge_upserts.end());
  EXPECT_EQ(contribution_of(reversed).digest(), c.digest());
  EXPECT_NE(c.digest(), 0u);
  EXPECT_NE(highlevel::Contribution{}.digest(), 0u);  // 0 means "no digest" on the wire
  auto changed = [&](auto&& change) {
    highlevel::Contribution other = c;
    change(other);
    return other.digest() != c.digest();
  };
  const uint64_t incomplete = std::find_if(inc.update.upserts.begin(), inc.update.upserts.end(),
                                           [](const auto& s) { return !s.covered; })->key;
  EXPECT_TRUE(changed([](auto& o) { o.supervoxels.erase(o.supervoxels.begin()); }));
  EXPECT_TRUE(changed([](auto& o) { o.edges.erase(o.edges.begin()); }));
  EXPECT_TRUE(changed([&](auto& o) { o.supervoxels[incomplete].covered_voxels += 1; }));
  EXPECT_TRUE(changed([&](auto& o) { o.supervoxels[incomplete].center.x() += 1.0 / 64; }));
  EXPECT_TRUE(changed([&](auto& o) { o.supervoxels[incomplete].covered = true; }));
  // Below the wire's precision, nothing changed.
  EXPECT_FALSE(changed([&](auto& o) { o.supervoxels[incomplete].center.x() += 1e-6; }));
}

TEST(MapCodec, AnEmptyIncrementIsAFewBytes) {
  const MapCodec codec(false, kEtaS);
  const auto roster = testing::roster();
  v1::MapIncrement heartbeat;
  heartbeat.set_source_robot("slugcat1");
  heartbeat.set_increment_seq(300);
  heartbeat.set_incarnation(1'796'000'000'000);  // ms since the epoch, as hlmap sets it: 6 bytes
  heartbeat.set_contribution_digest(0x9e3779b9);  // 4 bytes
  const std::string wire = encode(codec, heartbeat, &roster);
  EXPECT_LE(wire.size(), 15u);
  v1::MapIncrement out;
  ASSERT_TRUE(decode(codec, wire, &roster, out));
  EXPECT_EQ(out.increment_seq(), 300u);
  EXPECT_EQ(out.incarnation(), 1'796'000'000'000u);
  EXPECT_EQ(out.contribution_digest(), 0x9e3779b9u);
  EXPECT_EQ(out.supervoxels_size(), 0);
}

TEST(MapCodec, RefusesMalformedInput) {
  const MapCodec codec(false, kEtaS);
  const auto roster = testing::roster();
  const highlevel::SourcedUpdate inc = increment(3);
  const std::string wire = encode(codec, highlevel::to_increment(inc, contribution_of(inc)), &roster);
  testing::survives_malformed<v1::MapIncrement>(codec, wire, &roster);
  v1::MapIncrement out;
  // A count the frame cannot hold is refused before anything is allocated for it.
  // (robot slot, seq, incarnation, digest, then a supervoxel count of 2^32 - 1)
  std::string huge("\x02\x01\x01\x00\x00\x00\x00\xff\xff\xff\xff\x0f\x00", 13);
  EXPECT_FALSE(decode(codec, huge, &roster, out));
}

// On the radio an increment is compressed with the map dictionary: the frame names it, a peer
// holding it gets back exactly what was sent, and a socket without it (a teammate built with
// another dictionary, or none) refuses the frame rather than misreading it.
TEST(MapDictionary, AnIncrementTravelsCompressedWithItAndOnlyAPeerHoldingItReadsIt) {
  auto table = std::make_shared<transport::CodecTable>();
  table->add(std::make_shared<MapCodec>(false, kEtaS));
  transport::SocketOptions with;
  with.codecs = table;
  with.roster = std::make_shared<transport::Roster>(testing::roster());
  const highlevel::SourcedUpdate inc = increment(5);
  const v1::MapIncrement message = highlevel::to_increment(inc, contribution_of(inc));
  const uint16_t type = transport::type_id(v1::MapIncrement::descriptor()->full_name());
  std::string frame;
  const uint8_t flags = transport::encode_payload(message, type, true, with, frame);
  ASSERT_TRUE(flags & transport::kPayloadCompressed);
  EXPECT_EQ(transport::frame_dictionary_id(frame), map_dictionary().id());

  std::string scratch;
  std::string_view bytes;
  ASSERT_TRUE(transport::unpack_payload(frame, flags, type, with, scratch, bytes));
  v1::MapIncrement back, direct;
  ASSERT_TRUE(transport::parse_payload(bytes, flags, type, with, back));
  ASSERT_TRUE(decode(MapCodec(false, kEtaS), encode(MapCodec(false, kEtaS), message, with.roster.get()),
                     with.roster.get(), direct));
  EXPECT_EQ(back.SerializeAsString(), direct.SerializeAsString());

  transport::SocketOptions without = with;
  without.codecs = nullptr;
  EXPECT_FALSE(transport::unpack_payload(frame, flags, type, without, scratch, bytes));
}

TEST(MapDictionary, RefusesBytesThatAreNoDictionaryAndFramesOfAnother) {
  EXPECT_THROW(transport::CompressionDictionary("just some bytes, no dictionary header", 19), std::invalid_argument);
  std::string plain;
  transport::compress(std::string(500, 'x'), 19, plain);
  std::string out;
  EXPECT_FALSE(map_dictionary().decompress(plain, 1000, out));  // a frame without its id
}

}  // namespace
}  // namespace hexplore::radio
