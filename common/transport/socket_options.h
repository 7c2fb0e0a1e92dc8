#pragma once
// Per-socket settings: ZeroMQ limits set explicitly on every socket, the team's wire context
// (roster, team payload codecs, compression), the radio model, and fault injection for tests
// (drop or delay outgoing messages on chosen topics).

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/core/team_config.h"
#include "common/transport/compression.h"
#include "common/transport/curve_keys.h"
#include "common/transport/link_model.h"
#include "common/transport/payload_codec.h"
#include "common/transport/roster.h"

namespace hexplore::transport {

// Drops a fraction of outgoing messages and/or delays them, on topics starting with one of
// `topic_prefixes` (all topics when empty). Deterministic for a given seed.
struct FaultInjection {
  std::vector<std::string> topic_prefixes;
  double drop_fraction = 0.0;                 // in [0, 1]
  std::chrono::nanoseconds delay{0};          // queued, then sent by the event loop when due
  uint64_t seed = 1;

  bool active() const { return drop_fraction > 0.0 || delay.count() > 0; }
  bool applies_to(std::string_view topic) const;
};

struct SocketOptions {
  int send_high_water_mark = 10000;          // ZMQ_SNDHWM, messages
  int receive_high_water_mark = 10000;       // ZMQ_RCVHWM, messages
  // Payload frames above this are counted as oversize and dropped (on send and on receipt).
  // ZMQ_MAXMSGSIZE is set to twice this (plus 64 KiB): frames beyond that never reach us,
  // ZeroMQ drops the offending connection instead (memory guard, not counted).
  int64_t max_message_bytes = 64 * 1024 * 1024;
  int linger_ms = 1000;                      // ZMQ_LINGER: how long close may flush queued messages
  FaultInjection faults;

  // The team's roster: compact headers name senders by slot. Null: senders go by name.
  std::shared_ptr<const Roster> roster;
  // Compact forms of team payloads (common/radio). Null: team payloads travel as protobuf.
  std::shared_ptr<const CodecTable> codecs;
  // Team payloads of at least this many bytes are zstd-compressed when that makes them
  // smaller (below it the frame overhead eats the gain); 0 = never.
  size_t compress_min_bytes = 96;
  int compress_level = kTeamCompressLevel;
  // The radio model of team traffic between robots; null: an ideal link.
  std::shared_ptr<RadioMedium> radio;
  // The robot this socket belongs to (whose radio receives): the socket's identity for
  // publishers and requesters, this field for subscribers.
  std::string receiver_robot;
  // CURVE on tcp endpoints (null: plain ZeroMQ): binding sockets are servers with this pair,
  // connecting ones clients that check the server's key. ipc and inproc stay within one host
  // (file permissions, one process) and are left plain.
  std::shared_ptr<const CurveCredentials> curve;

  static SocketOptions from_config(const core::TransportConfig& config);
  // Throws std::invalid_argument naming the bad field.
  void validate() const;
};

}  // namespace hexplore::transport
