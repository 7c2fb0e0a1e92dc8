// The compact envelope: headers round-trip (roster slot or name, wall time or not, payload
// flags), take a handful of bytes, and every malformed or foreign header is refused with its
// reason; wire type ids of all hexplore.v1 messages differ; team topics travel as codes;
// compressed payloads are bounded.
#include <gtest/gtest.h>

#include <random>
#include <map>
#include <set>

#include <google/protobuf/descriptor.h>

#include "common/transport/compression.h"
#include "common/transport/envelope.h"
#include "common/transport/topics.h"
#include "common/transport/type_id.h"
#include "hexplore/v1/geometry.pb.h"
#include "hexplore/v1/header.pb.h"
#include "hexplore/v1/hlmap.pb.h"
#include "hexplore/v1/mission.pb.h"
#include "hexplore/v1/motion.pb.h"
#include "hexplore/v1/plan.pb.h"
#include "hexplore/v1/pose.pb.h"
#include "hexplore/v1/safety.pb.h"
#include "hexplore/v1/scan.pb.h"
#include "hexplore/v1/status.pb.h"
#include "hexplore/v1/test_messages.pb.h"
#include "hexplore/v1/voxels.pb.h"

namespace hexplore::transport {
namespace {

const Roster kRoster({{"slugcat1", "SLUGCAT"}, {"mr1000a", "MR1000"}});

v1::Header header(const std::string& robot, const std::string& species, const std::string& service) {
  v1::Header h = make_header({robot, species, service}, 300, "hexplore.v1.RobotPose", 123'456'000'000);
  return h;
}

TEST(Envelope, ARosterSenderTakesAFewBytesAndRoundTrips) {
  const v1::Header in = header("mr1000a", "MR1000", "sim");
  std::string wire;
  encode_header(in, &kRoster, kPayloadCodec, false, wire);
  EXPECT_LE(wire.size(), 9u);  // version+flags, type id, slot+service, sequence, sim time
  EXPECT_LT(wire.size() * 7, in.ByteSizeLong());
  DecodedHeader out;
  ASSERT_FALSE(decode_header(wire.data(), wire.size(), &kRoster, out));
  EXPECT_EQ(out.header.robot_id(), "mr1000a");
  EXPECT_EQ(out.header.species(), "MR1000");
  EXPECT_EQ(out.header.service(), "sim");
  EXPECT_EQ(out.header.sequence(), 300u);
  EXPECT_EQ(out.header.sim_time_ns(), 123'456'000'000);
  EXPECT_EQ(out.header.send_time_ns(), 0);
  EXPECT_EQ(out.header.schema_version(), current_schema_version());
  EXPECT_EQ(out.type_id, type_id("hexplore.v1.RobotPose"));
  EXPECT_EQ(out.payload_flags, kPayloadCodec);
  EXPECT_FALSE(out.has_wall_time);
}

TEST(Envelope, SendersOffTheRosterGoByNameWithWallTime) {
  const v1::Header in = header("bench", "", "transport_bench");
  std::string wire;
  encode_header(in, &kRoster, 0, true, wire);
  DecodedHeader out;
  ASSERT_FALSE(decode_header(wire.data(), wire.size(), nullptr, out));  // no roster needed
  EXPECT_EQ(out.header.robot_id(), "bench");
  EXPECT_EQ(out.header.service(), "transport_bench");
  EXPECT_TRUE(out.has_wall_time);
  EXPECT_LT(std::abs(out.header.send_time_ns() - in.send_time_ns()), 1000);  // microseconds on the wire
  // A robot whose species differs from the roster's is not that roster member.
  std::string other;
  encode_header(header("slugcat1", "MR1000", "sim"), &kRoster, 0, false, other);
  ASSERT_FALSE(decode_header(other.data(), other.size(), &kRoster, out));
  EXPECT_EQ(out.header.species(), "MR1000");
}

TEST(Envelope, MalformedAndForeignHeadersAreRefusedWithTheirReason) {
  std::string wire;
  encode_header(header("slugcat1", "SLUGCAT", "hlmap"), &kRoster, kPayloadCompressed, true, wire);
  DecodedHeader out;
  for (size_t n = 0; n < wire.size(); ++n)
    EXPECT_TRUE(decode_header(wire.data(), n, &kRoster, out).has_value()) << "truncated to " << n;
  EXPECT_EQ(decode_header((wire + "x").data(), wire.size() + 1, &kRoster, out), DropReason::kMalformed);
  // A slot only means something with the sender's roster.
  std::string slotted;
  encode_header(header("slugcat1", "SLUGCAT", "hlmap"), &kRoster, 0, false, slotted);
  EXPECT_EQ(decode_header(slotted.data(), slotted.size(), nullptr, out), DropReason::kMalformed);
  const Roster smaller({});
  EXPECT_EQ(decode_header(slotted.data(), slotted.size(), &smaller, out), DropReason::kMalformed);
  std::string reserved = slotted;
  reserved[0] = static_cast<char>(reserved[0] | kHeaderReserved);
  EXPECT_EQ(decode_header(reserved.data(), reserved.size(), &kRoster, out), DropReason::kMalformed);
  // Version 1 (a protobuf Header) and any other version.
  v1::Header old = header("slugcat1", "SLUGCAT", "hlmap");
  old.set_schema_version(1);
  const std::string v1_frame = old.SerializeAsString();
  EXPECT_EQ(decode_header(v1_frame.data(), v1_frame.size(), &kRoster, out), DropReason::kWrongVersion);
  v1::Header seven = old;
  seven.set_schema_version(7);
  std::string v7;
  encode_header(seven, &kRoster, 0, false, v7);
  EXPECT_EQ(decode_header(v7.data(), v7.size(), &kRoster, out), DropReason::kWrongVersion);
  const char this_version = static_cast<char>(current_schema_version() << 5);
  EXPECT_EQ(decode_header(std::string(600, this_version).data(), 600, &kRoster, out), DropReason::kMalformed);
  // Random bytes never crash.
  std::mt19937 rng(9);
  for (int i = 0; i < 20000; ++i) {
    std::string noise(rng() % 40, '\0');
    for (char& c : noise) c = static_cast<char>(rng());
    if (!noise.empty() && (rng() & 1)) noise[0] = static_cast<char>(this_version | (noise[0] & 0x1f));
    (void)decode_header(noise.data(), noise.size(), &kRoster, out);
    (void)header_sender_key(noise.data(), noise.size());
  }
}

TEST(Envelope, LockstepSenderKeyNamesTheSenderNotTheMessage) {
  std::string a, b, c;
  v1::Header h = header("slugcat1", "SLUGCAT", "planning");
  encode_header(h, &kRoster, 0, false, a);
  h.set_sequence(301);
  h.set_sim_time_ns(999'000'000);
  encode_header(h, &kRoster, kPayloadCodec, true, b);
  encode_header(header("mr1000a", "MR1000", "planning"), &kRoster, 0, false, c);
  EXPECT_EQ(header_sender_key(a.data(), a.size()), header_sender_key(b.data(), b.size()));
  EXPECT_NE(header_sender_key(a.data(), a.size()), header_sender_key(c.data(), c.size()));
  EXPECT_EQ(header_sender_key("\x0a\x03", 2), "");
}

TEST(TypeId, EveryHexploreMessageHasItsOwnId) {
  // One message of every proto file (naming them links their descriptors in).
  std::map<uint16_t, std::string> seen;
  int types = 0;
  for (const google::protobuf::FileDescriptor* f :
       {v1::Vec3::descriptor()->file(), v1::Header::descriptor()->file(), v1::MapIncrement::descriptor()->file(),
        v1::MissionCommand::descriptor()->file(), v1::MotionCommand::descriptor()->file(),
        v1::TeamSolution::descriptor()->file(), v1::RobotPose::descriptor()->file(),
        v1::PathFragment::descriptor()->file(), v1::ScanFrame::descriptor()->file(),
        v1::ServiceStatus::descriptor()->file(), v1::TestPayload::descriptor()->file(),
        v1::VoxelDelta::descriptor()->file()}) {
    for (int i = 0; i < f->message_type_count(); ++i) {
      const std::string& name = f->message_type(i)->full_name();
      const uint16_t id = type_id(name);
      EXPECT_NE(id, 0);
      auto [it, fresh] = seen.emplace(id, name);
      EXPECT_TRUE(fresh) << name << " and " << it->second << " share id " << id;
      ++types;
    }
  }
  (void)types;
  EXPECT_GT(types, 30);
}

TEST(WireTopics, TeamTopicsTravelAsOneByteCodes) {
  for (std::string_view t : {topics::kTeamPose, topics::kTeamMap, topics::kTeamPlan, topics::kTeamPath,
                             topics::kTeamMission}) {
    const std::string_view wire = topics::wire_topic(t);
    EXPECT_EQ(wire.size(), 1u);
    EXPECT_EQ(topics::topic_from_wire(wire), t);
  }
  EXPECT_EQ(topics::wire_topic("team/echo"), "team/echo");  // not coded: by name
  EXPECT_EQ(topics::topic_from_wire("robot/r1/scan"), "robot/r1/scan");
  EXPECT_FALSE(topics::topic_from_wire(std::string("\x1f")).has_value());
  EXPECT_FALSE(topics::topic_from_wire(std::string("\x01x")).has_value());
  EXPECT_EQ(topics::wire_prefixes("team/").size(), 6u);
  EXPECT_EQ(topics::wire_prefixes("team/p").size(), 4u);  // team/p, pose, plan, path
  EXPECT_EQ(topics::wire_prefixes("robot/").size(), 1u);
}

TEST(Compression, RoundTripsAndRefusesWhatIsTooLargeOrCorrupt) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += "supervoxel " + std::to_string(i % 7) + ";";
  std::string packed, back;
  compress(text, 19, packed);
  EXPECT_LT(packed.size() * 4, text.size());
  ASSERT_TRUE(decompress(packed, text.size(), back));
  EXPECT_EQ(back, text);
  EXPECT_FALSE(decompress(packed, text.size() - 1, back));  // claims more than allowed
  EXPECT_FALSE(decompress(packed.substr(0, packed.size() - 2), text.size(), back));
  EXPECT_FALSE(decompress(packed + "x", text.size(), back));
  EXPECT_FALSE(decompress("not zstd at all", 1000, back));
  std::mt19937 rng(1);
  for (int i = 0; i < 2000; ++i) {
    std::string bad = packed;
    bad[rng() % bad.size()] ^= static_cast<char>(1 + rng() % 255);
    (void)decompress(bad, text.size(), back);
  }
}

}  // namespace
}  // namespace hexplore::transport
