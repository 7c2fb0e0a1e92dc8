#pragma once
// Which given-up targets one team solution carries. The given-up set only grows (a target's
// voxel count only rises), so teammates merge whatever arrives, in any order, any number of
// times; it need not travel whole every round. Sending it whole did: on the multi-building
// mission it reached about 1,000 targets per robot, and the exploration-route category grew
// to 0.27-0.46 KB/s per robot against the paper's 0.016 (stop 37, issue 14).
//
// A message carries what changed in the ledger since the message `window` messages before it,
// so a change travels in `window` consecutive messages (a teammate misses it only when all of
// them are lost: 10^-3 at 10 % loss with three). The whole set goes when the owner asks for it
// (whole_set_next: a teammate came back from a silence, or its planner restarted) and every
// `full_every`-th message, for what loss took all the same.
// With a radio range shorter than the site (`relay`), changes that arrived from a teammate are
// passed on like one's own: that is how they reach robots the source cannot. Without one every
// teammate hears the source itself, and passing them on multiplied the given-up traffic by the
// team's size (a robot that was silent still gets the whole set when it is heard again).

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "common/planning/give_up_ledger.h"

namespace hexplore::planning {

class GiveUpSharing {
 public:
  explicit GiveUpSharing(int window = 3, int full_every = 100, bool relay = false);

  // The (key, voxel count) entries of the next message, by key; call once per message sent.
  std::vector<std::pair<uint64_t, int>> next(const GiveUpLedger& ledger);
  // The next message carries the whole set.
  void whole_set_next() { whole_next_ = true; }
  // Whether the next message has given-up targets to carry that the last `window` did not all
  // carry (a change newer than the oldest of them), or the whole set was asked for.
  bool has_news(const GiveUpLedger& ledger) const;

 private:
  int window_;
  int full_every_;
  bool relay_;
  uint64_t messages_ = 0;
  bool whole_next_ = false;
  std::deque<uint64_t> sent_at_;  // the ledger's revision at each of the last `window` messages
};

}  // namespace hexplore::planning
