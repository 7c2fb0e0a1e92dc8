// The give-up ledger's rules, and which of its targets each team solution carries.
#include "common/planning/give_up_ledger.h"
#include "common/planning/give_up_sharing.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace hexplore::planning {
namespace {

using Entries = std::vector<std::pair<uint64_t, int>>;

TEST(GiveUpLedger, ByDefaultGivesUpAfterOneLookOrThreeTries) {
  GiveUpLedger l;
  EXPECT_TRUE(l.observed(1, {0, 0, 0}, 30));  // stayed incomplete after a look
  EXPECT_TRUE(l.given_up(1, 30));
  EXPECT_FALSE(l.failed(2, 10));  // blocked on the way: no look
  EXPECT_FALSE(l.failed(2, 10));
  EXPECT_TRUE(l.failed(2, 10));  // three tries of any kind
}

TEST(GiveUpLedger, WithTwoViewsGivesUpAfterTwoDistinctSpotsOrThreeTries) {
  GiveUpLedger l{GiveUpRules{.views = 2}};
  EXPECT_FALSE(l.observed(1, {0, 0, 0}, 30));
  EXPECT_FALSE(l.observed(1, {0.5, 0, 0}, 30));  // the same spot, again
  EXPECT_FALSE(l.given_up(1, 30));
  EXPECT_TRUE(l.observed(1, {3, 0, 0}, 30));  // a second, distinct spot
  EXPECT_TRUE(l.given_up(1, 30));

  EXPECT_FALSE(l.failed(2, 10));
  EXPECT_FALSE(l.observed(2, {0, 0, 0}, 10));
  EXPECT_TRUE(l.failed(2, 10));  // three tries of any kind
}

TEST(GiveUpLedger, ATargetIsTriedFromTheSpotsItStayedOpenFromAndTheirSurroundings) {
  GiveUpLedger l{GiveUpRules{.views = 2}};
  EXPECT_FALSE(l.tried_from(1, {0, 0, 0}));
  l.observed(1, {0, 0, 0.4}, 30);
  EXPECT_TRUE(l.tried_from(1, {1.0, 0, 0}));   // ground 1 m from where the robot stood
  EXPECT_FALSE(l.tried_from(1, {2.0, 0, 0}));  // a distinct spot
  EXPECT_FALSE(l.tried_from(2, {0, 0, 0}));
  l.failed(3, 10);  // a try that observed nothing marks no spot
  EXPECT_FALSE(l.tried_from(3, {0, 0, 0}));
}

TEST(GiveUpLedger, AGrownTargetComesBack) {
  GiveUpLedger l;
  l.merge(5, 40);  // a teammate gave it up at 40 voxels
  EXPECT_TRUE(l.given_up(5, 40));
  EXPECT_TRUE(l.given_up(5, 50));
  EXPECT_FALSE(l.given_up(5, 51));  // grown by more than a quarter: worth a look again
  l.merge(5, 30);                    // a smaller count does not lower the bar
  EXPECT_FALSE(l.given_up(5, 51));
  EXPECT_TRUE(l.given_up(5, 49));
}

TEST(GiveUpLedger, EveryChangeTakesARevisionAndARepeatedMergeNone) {
  GiveUpLedger l;
  EXPECT_EQ(l.revision(), 0u);
  EXPECT_TRUE(l.observed(7, {0, 0, 0}, 30));
  const uint64_t after_own = l.revision();
  EXPECT_GT(after_own, 0u);
  l.merge(3, 20);  // a teammate's
  const uint64_t after_merge = l.revision();
  EXPECT_GT(after_merge, after_own);
  l.merge(3, 20);  // the same again (the teammate's next message, or our own coming back)
  l.merge(3, 10);  // a smaller count changes nothing
  EXPECT_EQ(l.revision(), after_merge);
  EXPECT_EQ(l.given_up_since(after_own), (Entries{{3, 20}}));
  l.merge(7, 45);  // a larger count is a change
  EXPECT_EQ(l.given_up_since(after_merge), (Entries{{7, 45}}));
  EXPECT_EQ(l.given_up_since(0), (Entries{{3, 20}, {7, 45}}));
  EXPECT_EQ(l.given_up_count(), 2u);
}

// These two pass teammates' changes on (`relay`, as on a radio with a range), so merge() stands
// for any change.
TEST(GiveUpSharing, AChangeTravelsInWindowMessagesAndTheWholeSetNowAndThen) {
  GiveUpLedger l;
  GiveUpSharing share(/*window=*/2, /*full_every=*/6, /*relay=*/true);
  l.merge(1, 10);
  EXPECT_EQ(share.next(l), (Entries{{1, 10}}));  // message 0: whole
  l.merge(2, 10);
  EXPECT_EQ(share.next(l), (Entries{{1, 10}, {2, 10}}));  // message 1: still whole (no window yet)
  EXPECT_EQ(share.next(l), (Entries{{2, 10}}));           // message 2: what changed since message 0
  EXPECT_EQ(share.next(l), (Entries{}));                  // message 3: key 2 has been in two
  l.merge(3, 10);
  EXPECT_EQ(share.next(l), (Entries{{3, 10}}));  // message 4
  EXPECT_EQ(share.next(l), (Entries{{3, 10}}));  // message 5
  EXPECT_EQ(share.next(l), (Entries{{1, 10}, {2, 10}, {3, 10}}));  // message 6: whole
  EXPECT_EQ(share.next(l), (Entries{}));
}

TEST(GiveUpSharing, OnRequestTheNextMessageCarriesTheWholeSetOnce) {
  GiveUpLedger l;
  GiveUpSharing share(/*window=*/1, /*full_every=*/1000);
  l.merge(1, 10);
  l.merge(2, 10);
  share.next(l);
  EXPECT_EQ(share.next(l), (Entries{}));
  share.whole_set_next();  // a teammate came back from a silence
  EXPECT_EQ(share.next(l), (Entries{{1, 10}, {2, 10}}));
  EXPECT_EQ(share.next(l), (Entries{}));
}

// has_news says whether next() would carry something the last window messages did not all
// carry: a message may be skipped (SolutionGate) only when it would not.
TEST(GiveUpSharing, NewsUntilAChangeHasTravelledInWindowMessages) {
  GiveUpLedger l;
  GiveUpSharing share(/*window=*/2, /*full_every=*/1000, /*relay=*/true);
  EXPECT_FALSE(share.has_news(l));  // nothing given up yet
  l.merge(1, 10);
  EXPECT_TRUE(share.has_news(l));
  share.next(l);
  EXPECT_TRUE(share.has_news(l));  // in one message of two
  share.next(l);
  EXPECT_FALSE(share.has_news(l));  // two messages carried it
  l.merge(1, 10);                   // a repeat changes nothing
  EXPECT_FALSE(share.has_news(l));
  l.merge(2, 10);
  EXPECT_TRUE(share.has_news(l));
  share.next(l);
  share.next(l);
  EXPECT_FALSE(share.has_news(l));
  share.whole_set_next();
  EXPECT_TRUE(share.has_news(l));
}

// Where every teammate hears the source, a teammate's change is not passed on, except in the
// whole set; it is no news either.
TEST(GiveUpSharing, WithoutRelayOnlyOwnChangesTravel) {
  GiveUpLedger l;
  GiveUpSharing share(/*window=*/1, /*full_every=*/1000);
  l.observed(1, {0, 0, 0}, 10);  // own: given up at once (one view)
  EXPECT_EQ(share.next(l), (Entries{{1, 10}}));  // message 0: whole
  l.merge(2, 10);                                // a teammate's
  EXPECT_FALSE(share.has_news(l));
  EXPECT_EQ(share.next(l), (Entries{}));
  l.observed(3, {0, 0, 0}, 10);
  EXPECT_TRUE(share.has_news(l));
  EXPECT_EQ(share.next(l), (Entries{{3, 10}}));
  l.merge(3, 20);  // a teammate raised our target's count: now its change, not ours
  EXPECT_FALSE(share.has_news(l));
  EXPECT_EQ(share.next(l), (Entries{}));
  share.whole_set_next();
  EXPECT_EQ(share.next(l), (Entries{{1, 10}, {2, 10}, {3, 20}}));
}

TEST(GiveUpSharing, TeammatesThatHearEveryMessageEndWithTheSameSetAndStopSending) {
  // Three robots, each giving up its own targets and merging what the others send: the sets
  // agree, and once nothing changes the messages carry nothing but the periodic whole set.
  std::vector<GiveUpLedger> robots(3);
  std::vector<GiveUpSharing> shares(3, GiveUpSharing(3, 40));
  for (int round = 0; round < 30; ++round) {
    for (int r = 0; r < 3; ++r) {
      if (round < 10) robots[r].observed(uint64_t(100 * r + round), {0, 0, 0}, 5 + round);
      const Entries sent = shares[r].next(robots[r]);
      if (round >= 20) {
        EXPECT_TRUE(sent.empty()) << "robot " << r << " round " << round;
      }
      for (int other = 0; other < 3; ++other)
        if (other != r)
          for (const auto& [key, voxels] : sent) robots[other].merge(key, voxels);
    }
  }
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(robots[r].given_up_count(), 30u);
    EXPECT_EQ(robots[r].given_up_since(0), robots[0].given_up_since(0));
  }
}

}  // namespace
}  // namespace hexplore::planning
