#pragma once
// Per-socket traffic accounting: messages and bytes sent/received per topic and peer, drops
// by reason, receive latency per topic. Keeps in-memory totals (for tests and status) and,
// when given the standard families, feeds Prometheus as well.

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

#include "common/metrics/standard_families.h"

namespace hexplore::transport {

// Why a frame was rejected; each is a value of the `reason` label.
enum class DropReason {
  kMalformed = 0,      // wrong frame count, unparsable header or payload, invalid topic
  kWrongVersion = 1,   // header.schema_version is not ours
  kWrongType = 2,      // header.payload_type is not what the handler expects
  kOversize = 3,       // payload larger than SocketOptions::max_message_bytes
  kFaultInjected = 4,  // dropped on purpose by FaultInjection
  kTimeout = 5,        // a request got no reply in time
  kSendFailed = 6,     // ZeroMQ refused the message (would block at the high-water mark)
  kHandlerError = 7,   // the receiving handler threw; the message is counted as lost
  // The radio model (link_model.h):
  kRadioExpired = 8,     // waited longer than max_queue_age_s for the sender's channel
  kRadioLost = 9,        // lost on the way to this receiver
  kRadioOutOfRange = 10, // sender and receiver were farther apart than the range
};
inline constexpr int kDropReasonCount = 11;
std::string_view drop_reason_name(DropReason reason);

// Peer label used for messages sent on a PUB socket (every subscriber gets them).
inline constexpr std::string_view kBroadcastPeer = "broadcast";

class Accounting {
 public:
  struct Totals {
    uint64_t messages = 0;
    uint64_t bytes = 0;
  };

  // `families` may be null (in-memory totals only); it must outlive this object.
  Accounting(std::string robot_id, std::string service, const metrics::TransportFamilies* families = nullptr);

  void record_sent(std::string_view topic, std::string_view peer, size_t bytes);
  // `latency_ns` < 0: the message carried no send time, so no latency sample.
  void record_received(std::string_view topic, std::string_view peer, size_t bytes, int64_t latency_ns);
  void record_dropped(std::string_view topic, DropReason reason);

  // Read-back, thread-safe. Totals per topic summed over peers, and overall.
  Totals sent(std::string_view topic) const;
  Totals received(std::string_view topic) const;
  Totals sent_all() const;
  Totals received_all() const;
  uint64_t dropped(DropReason reason) const;
  uint64_t latency_samples(std::string_view topic) const;

  const std::string& robot_id() const { return robot_id_; }
  const std::string& service() const { return service_; }

 private:
  // Cached metric children of one (topic, peer) pair, created on first use.
  struct Line {
    Totals totals;
    metrics::Counter* messages = nullptr;
    metrics::Counter* bytes = nullptr;
  };
  struct TopicLine {
    uint64_t latency_samples = 0;
    metrics::Histogram* latency = nullptr;
  };
  // topic label -> peer label -> line; std::less<> allows lookups by string_view without allocating.
  using PeerLines = std::map<std::string, Line, std::less<>>;
  using Lines = std::map<std::string, PeerLines, std::less<>>;
  Line& line(Lines& lines, metrics::CounterFamily* messages, metrics::CounterFamily* bytes, std::string_view topic,
             std::string_view peer);
  static Totals sum(const Lines& lines, std::string_view topic);

  std::string robot_id_;
  std::string service_;
  const metrics::TransportFamilies* families_;
  mutable std::mutex mutex_;
  Lines sent_;
  Lines received_;
  std::map<std::string, TopicLine, std::less<>> latency_;
  std::map<std::string, metrics::Counter*, std::less<>> dropped_children_;
  uint64_t dropped_[kDropReasonCount] = {};
};

}  // namespace hexplore::transport
