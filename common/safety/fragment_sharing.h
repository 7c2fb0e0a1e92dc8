#pragma once
// Path fragments on a slow radio. A robot shares its fragment when it changed, not at its
// decision rate: receivers advance the last fragment they heard along its path at its speed
// (advance_fragment), so a robot driving its approved path needs no new message until the
// prediction would be wrong — it stopped or started, yields to someone else, its path or speed
// changed, or the heartbeat (eta_c) is due. What teammates believe thus stays within
// `tolerance_m` of what the robot itself shares, up to the radio's latency and losses: a change
// is sent twice, and the heartbeat repairs the rest.

#include <optional>

#include "common/safety/fragment.h"

namespace hexplore::safety {

struct SharingOptions {
  double heartbeat_s = 1.0;           // a fragment at least this often (paper eta_c)
  // A fragment sent because something changed goes out once more this much later: a lost
  // "I stopped" would otherwise leave teammates advancing a standing robot until the heartbeat.
  double repeat_after_s = 0.2;
  double tolerance_m = 0.15;          // prediction error that makes a new fragment due
  double speed_tolerance_mps = 0.05;  // speed change that makes a new fragment due
  double eta_p_m = 2.0;               // fragments this long (less 5 cm) were cut there

  // Throws std::invalid_argument naming the bad field.
  void validate() const;
};

// The fragment `age_s` after it was shared: a moving robot advanced along its path at its
// speed, never past the end of a path that ends there (its approved path stops it), while the
// path of a fragment cut at eta_p goes on straight for as far as it was used up (the resolver's
// own assumption about cut fragments), so the horizon receivers see stays eta_p. The body box
// moves with the robot, and trail_m keeps the way it was believed to have come. Stationary
// fragments and ages <= 0 are returned as they are.
Fragment advance_fragment(const Fragment& fragment, double age_s, double eta_p_m);

class FragmentSchedule {
 public:
  explicit FragmentSchedule(SharingOptions options = {});

  // Whether `current` (this robot's fragment now) must be shared at `now_s`.
  bool due(double now_s, const Fragment& current) const;
  void sent(double now_s, const Fragment& fragment);
  const SharingOptions& options() const { return options_; }

 private:
  // Whether `current` differs from what teammates predict from the last one sent.
  bool changed(double now_s, const Fragment& current) const;

  SharingOptions options_;
  std::optional<Fragment> last_;
  double last_s_ = 0.0;
  bool repeat_ = false;  // the last one was a change: send it again after repeat_after_s
};

}  // namespace hexplore::safety
