// Authenticated team links (ZeroMQ CURVE): key files, and on tcp loopback a team member that
// receives while a rogue with a valid-looking but unknown key, and one without keys, are
// refused and counted; a client that does not reach the member it expects gets nothing.
#include <gtest/gtest.h>

#include <fstream>

#include "common/transport/curve_keys.h"
#include "common/transport/event_loop.h"
#include "common/transport/publisher.h"
#include "common/transport/subscriber.h"
#include "hexplore/v1/test_messages.pb.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::transport {
namespace {

using namespace std::chrono_literals;

// r1 and r2 are the team; `rogue` has a well-formed pair nobody listed.
struct TeamKeys {
  testing::ScratchDir dir{"curve_team"};
  std::shared_ptr<const CurveKeyring> ring;
  TeamKeys() {
    for (const char* m : {"r1", "r2"}) write_curve_key_pair(dir.path().string(), m, generate_curve_key_pair());
    ring = CurveKeyring::load(dir.path().string(), {"r1", "r2"});
  }
  SocketOptions options(const std::string& member) const {
    SocketOptions o;
    o.curve = std::make_shared<CurveCredentials>(CurveCredentials{member, ring->own_pair(member), ring});
    return o;
  }
};

v1::TestPayload payload(uint64_t counter) {
  v1::TestPayload m;
  m.set_counter(counter);
  return m;
}

TEST(CurveKeys, WrittenPairsLoadBackAndBadFilesAreNamed) {
  TeamKeys team;
  const CurveKeyPair r1 = team.ring->own_pair("r1");
  EXPECT_EQ(r1.public_key, team.ring->public_key("r1"));
  EXPECT_TRUE(is_z85_key(r1.secret_key));
  EXPECT_NE(team.ring->public_key("r1"), team.ring->public_key("r2"));
  EXPECT_THROW(team.ring->public_key("r3"), std::invalid_argument);
  // A member without a file, a garbled file, a secret that is another member's.
  EXPECT_THROW(CurveKeyring::load(team.dir.path().string(), {"r1", "r3"}), std::runtime_error);
  std::ofstream(team.dir.file("bad.public")) << "not a key\n";
  try {
    CurveKeyring::load(team.dir.path().string(), {"bad"});
    FAIL() << "a garbled key file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.public"), std::string::npos) << e.what();
  }
  std::filesystem::copy_file(team.dir.file("r2.secret"), team.dir.file("r1.secret"),
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_THROW(team.ring->own_pair("r1"), std::runtime_error);
}

TEST(CurveKeys, TwoMembersWithOnePublicKeyAreRefused) {
  TeamKeys team;
  std::filesystem::copy_file(team.dir.file("r1.public"), team.dir.file("r3.public"));
  EXPECT_THROW(CurveKeyring::load(team.dir.path().string(), {"r1", "r3"}), std::runtime_error);
}

TEST(CurveLinks, MemberReceivesWhileRoguesAreRefusedAndCounted) {
  TeamKeys team;
  Context server_ctx;
  std::vector<CurveGuard::Refusal> refusals;
  std::mutex refusals_mutex;
  server_ctx.enable_curve(team.ring, [&](CurveGuard::Refusal why, const std::string&) {
    std::lock_guard<std::mutex> lock(refusals_mutex);
    refusals.push_back(why);
  });
  Publisher pub(server_ctx, {"r1", "SLUGCAT", "test"}, "tcp://127.0.0.1:*", team.options("r1"));

  Context member_ctx, rogue_ctx;
  Subscriber member(member_ctx, team.options("r2"));
  member.connect(pub.endpoint(), "r1");
  // The rogue knows r1's public key (public keys are not secret) but holds a pair of its own.
  SocketOptions rogue_options;
  rogue_options.curve = std::make_shared<CurveCredentials>(CurveCredentials{"r2", generate_curve_key_pair(), team.ring});
  Subscriber rogue(rogue_ctx, rogue_options);
  rogue.connect(pub.endpoint(), "r1");
  Subscriber plain(rogue_ctx);  // no keys at all
  plain.connect(pub.endpoint());

  int member_got = 0, rogue_got = 0, plain_got = 0;
  member.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { ++member_got; });
  rogue.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { ++rogue_got; });
  plain.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { ++plain_got; });
  // Publish for up to 5 s until the member has had ten messages and both rogues were refused.
  auto refused = [&](CurveGuard::Refusal why) {
    std::lock_guard<std::mutex> lock(refusals_mutex);
    return std::count(refusals.begin(), refusals.end(), why) > 0;
  };
  for (int i = 0; i < 500; ++i) {
    pub.publish("team/test", payload(uint64_t(i + 1)));
    while (member.receive_one(0ms) || rogue.receive_one(0ms) || plain.receive_one(0ms)) {
    }
    if (member_got >= 10 && refused(CurveGuard::Refusal::kUnknownKey) && refused(CurveGuard::Refusal::kHandshake)) break;
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_GE(member_got, 10);
  EXPECT_EQ(rogue_got, 0);
  EXPECT_EQ(plain_got, 0);
  EXPECT_TRUE(refused(CurveGuard::Refusal::kUnknownKey)) << "the unknown key was not counted";
  EXPECT_TRUE(refused(CurveGuard::Refusal::kHandshake)) << "the peer without keys was not counted";
  EXPECT_GE(server_ctx.curve_guard()->accepted(), 1u);
  EXPECT_GE(server_ctx.curve_guard()->refused(), 2u);
}

TEST(CurveLinks, ClientGetsNothingFromAServerWithoutTheExpectedKey) {
  TeamKeys team;
  // A squatter on r1's port: its own pair, a guard that would admit r2.
  Context squatter_ctx;
  squatter_ctx.enable_curve(team.ring);
  SocketOptions squatter_options;
  squatter_options.curve = std::make_shared<CurveCredentials>(CurveCredentials{"r1", generate_curve_key_pair(), team.ring});
  Publisher squatter(squatter_ctx, {"r1", "SLUGCAT", "test"}, "tcp://127.0.0.1:*", squatter_options);

  Context member_ctx;
  Subscriber member(member_ctx, team.options("r2"));
  member.connect(squatter.endpoint(), "r1");  // expects r1's real key
  int got = 0;
  member.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { ++got; });
  for (int i = 0; i < 50; ++i) {
    squatter.publish("team/test", payload(uint64_t(i + 1)));
    while (member.receive_one(0ms)) {
    }
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_EQ(got, 0);
}

TEST(CurveLinks, AServerWithKeysNeedsAGuard) {
  TeamKeys team;
  Context ctx;  // no enable_curve: libzmq would admit any CURVE client
  EXPECT_THROW(Publisher(ctx, {"r1", "SLUGCAT", "test"}, "tcp://127.0.0.1:*", team.options("r1")), std::logic_error);
}

TEST(CurveLinks, InprocStaysPlainBesideCurveTcp) {
  TeamKeys team;
  Context ctx;
  ctx.enable_curve(team.ring);
  Publisher pub(ctx, {"r1", "SLUGCAT", "test"}, "inproc://curve-beside", team.options("r1"));
  Subscriber sub(ctx);  // no keys: inproc is within the process
  sub.connect("inproc://curve-beside");
  int got = 0;
  sub.on<v1::TestPayload>("team/", [&](const Received<v1::TestPayload>&) { ++got; });
  for (int i = 0; i < 100 && got == 0; ++i) {
    pub.publish("team/test", payload(uint64_t(i + 1)));
    sub.receive_one(10ms);
  }
  EXPECT_GT(got, 0);
}

}  // namespace
}  // namespace hexplore::transport
