#pragma once
// The team radio as the simulation models it (team file transport.radio): every robot has one
// broadcast transmitter of limited capacity shared by all its services; what it sends reaches
// each teammate after a latency unless that receiver loses it or is out of range (M-TARE's
// communication model: beyond the range, no link at all).
//
//   transmitter  a serial channel of bandwidth_bytes_per_s per robot: a message starts when
//                the ones queued before it are out and occupies bytes / bandwidth seconds. A
//                message that would wait longer than max_queue_age_s is dropped (counted as
//                radio_expired on its topic), never silently lost.
//   delivery     start + bytes / bandwidth + latency_s.
//   receivers    loss: each (message, receiving robot) is lost with probability `loss`, drawn
//                from a hash of both so that every service of the receiver agrees; range: the
//                two robots' true positions (PositionBoard, written by the sims) must be within
//                range_m when the message is handled; outages: neither robot may be cut off
//                (a partition) at that moment.
//
// Only team topics between robots go through it: robot-local topics stay on the robot, and the
// station, the experiment's recorder, hears and is heard directly. Request/reply between
// robots (map repairs) sees loss and range, not the channel's capacity.
//
// Reproducible in lockstep: what a robot's services submit during one step is ordered by
// (robot, service, submission) and scheduled by commit() at the end of the step, so the order
// in which their threads ran never matters. Outside lockstep, submit() schedules at once.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/core/team_config.h"
#include "common/transport/roster.h"

namespace hexplore::transport {

// True robot positions over time, for the range check. Written by each robot's sim, read by
// every receiver. A reader asks for the position before its own time, which in lockstep was
// written in an earlier step: the answer does not depend on thread timing.
class PositionBoard {
 public:
  void update(uint32_t slot, int64_t time_ns, const Eigen::Vector3d& position);
  // Latest position stamped before `time_ns`; nullopt while none is known.
  std::optional<Eigen::Vector3d> before(uint32_t slot, int64_t time_ns) const;

 private:
  struct Sample {
    int64_t time_ns;
    Eigen::Vector3d position;
  };
  static constexpr size_t kHistory = 8;
  mutable std::mutex mutex_;
  std::map<uint32_t, std::vector<Sample>> samples_;  // ring of the last kHistory per slot
};

// Why a radio message did not arrive (see DropReason::kRadio*).
enum class RadioVerdict { kDelivered, kLost, kOutOfRange };

class RadioMedium {
 public:
  // A message waiting for the channel: `send` puts it on the socket at `due_ns` (on the
  // publisher's own loop), `expire` counts it as dropped.
  struct Submission {
    uint32_t sender_slot = 0;
    uint32_t service = 0;   // orders one robot's services within a step
    uint64_t order = 0;     // submission order within one publisher
    int64_t submit_ns = 0;
    size_t bytes = 0;
    std::function<void(int64_t due_ns)> schedule;
    std::function<void()> expire;
  };

  // `lockstep`: submissions wait for commit(); else they are scheduled as they come.
  RadioMedium(core::RadioConfig config, std::shared_ptr<const Roster> roster, uint64_t seed, bool lockstep);

  const core::RadioConfig& config() const { return config_; }
  const Roster& roster() const { return *roster_; }
  // Whether the range is modelled: it needs the true position of every robot, which only a
  // process that simulates the whole team has (ServiceHost decides).
  void enable_range(bool enabled) { range_enabled_ = enabled && config_.range_m > 0.0; }
  bool range_enabled() const { return range_enabled_; }
  // Whether the outages (partitions, in sim seconds) are modelled: they need a clock that is sim
  // time at every receiver, which lockstep has (ServiceHost decides).
  void enable_outages(bool enabled) { outages_enabled_ = enabled && !outages_.empty(); }
  PositionBoard& positions() { return positions_; }

  void submit(Submission submission);
  // Lockstep: schedules every submission of the step that ends now, in a fixed order.
  void commit();

  // Whether a message from `sender_slot` (sequence `sequence` on wire topic code or name
  // `topic`) reaches robot `receiver_slot`, handled at `now_ns` on the shared clock.
  RadioVerdict receive(uint32_t sender_slot, uint32_t receiver_slot, std::string_view topic, uint64_t sequence,
                       int64_t now_ns) const;

 private:
  void schedule(Submission& s);

  core::RadioConfig config_;
  std::shared_ptr<const Roster> roster_;
  uint64_t seed_;
  bool lockstep_;
  bool range_enabled_ = false;
  bool outages_enabled_ = false;
  struct Outage {
    uint32_t slot;
    int64_t from_ns, to_ns;
  };
  std::vector<Outage> outages_;  // config_.outages by roster slot
  bool cut_off(uint32_t slot, int64_t now_ns) const;
  PositionBoard positions_;
  std::mutex mutex_;
  std::vector<Submission> pending_;     // lockstep: this step's submissions
  std::map<uint32_t, int64_t> free_at_ns_;  // per sender slot: when its channel is free again
};

}  // namespace hexplore::transport
