#include "common/planning/give_up_sharing.h"

#include <algorithm>

namespace hexplore::planning {

GiveUpSharing::GiveUpSharing(int window, int full_every, bool relay)
    : window_(std::max(1, window)), full_every_(std::max(1, full_every)), relay_(relay) {}

std::vector<std::pair<uint64_t, int>> GiveUpSharing::next(const GiveUpLedger& ledger) {
  const bool whole = whole_next_ || messages_ % uint64_t(full_every_) == 0 || int(sent_at_.size()) < window_;
  whole_next_ = false;
  const uint64_t since = whole ? 0 : sent_at_.front();
  ++messages_;
  sent_at_.push_back(ledger.revision());
  if (int(sent_at_.size()) > window_) sent_at_.pop_front();
  return ledger.given_up_since(since, /*mine_only=*/!whole && !relay_);
}

bool GiveUpSharing::has_news(const GiveUpLedger& ledger) const {
  if (whole_next_) return true;
  if (int(sent_at_.size()) < window_) return ledger.given_up_count() > 0;
  return (relay_ ? ledger.revision() : ledger.own_revision()) > sent_at_.front();
}

}  // namespace hexplore::planning
