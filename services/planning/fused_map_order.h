#pragma once
// Which of its hlmap's fused-map messages planning applies, and when it asks for the whole map.
// Versions count from 1 in each run of hlmap and its start time (the incarnation) orders the
// runs, so a restarted hlmap's snapshot replaces what planning held although its versions are
// smaller (an e2e restart once left planning on the old map with four views no teammate had).

#include <cstdint>

namespace hexplore::planning_service {

class FusedMapOrder {
 public:
  enum class Action { kApply, kDrop, kRequestSnapshot };

  // What to do with an update of hlmap run `incarnation` at `version`.
  Action on_update(uint64_t incarnation, uint64_t version, bool full_snapshot) const {
    if (have_ && incarnation < incarnation_) return Action::kDrop;  // from before hlmap restarted
    const bool same_run = have_ && incarnation == incarnation_;
    if (!full_snapshot) {
      // An increment applies only on top of the version right before it.
      if (same_run && version == version_ + 1) return Action::kApply;
      return !same_run || version > version_ ? Action::kRequestSnapshot : Action::kDrop;
    }
    return same_run && version < version_ ? Action::kDrop : Action::kApply;
  }
  void applied(uint64_t incarnation, uint64_t version) {
    have_ = true;
    incarnation_ = incarnation;
    version_ = version;
  }
  bool have_map() const { return have_; }
  uint64_t version() const { return version_; }

 private:
  bool have_ = false;
  uint64_t incarnation_ = 0;
  uint64_t version_ = 0;
};

}  // namespace hexplore::planning_service
