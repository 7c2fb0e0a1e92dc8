#pragma once
// Typed publisher on a PUB socket: publish(topic, message) sends [topic][header][payload] with
// the compact header filled (identity, per-topic sequence from 1, sim time, schema version,
// payload type; wall send time on robot-local topics). Team topics travel under their wire
// codes, with compact payloads (SocketOptions::codecs) and compression, and through the radio
// model when the socket has one. Not thread-safe: use it from one thread at a time (the loop
// thread).

#include <cstdint>
#include <deque>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <unordered_map>

#include <google/protobuf/message.h>
#include <zmq.hpp>

#include "common/transport/accounting.h"
#include "common/transport/context.h"
#include "common/transport/envelope.h"
#include "common/transport/pollable.h"
#include "common/transport/socket_options.h"

namespace hexplore::transport {

class Publisher : public Pollable {
 public:
  // Binds `bind_endpoint` (tcp://*:port, tcp://127.0.0.1:* for an ephemeral port, ipc://, inproc://).
  // `accounting` may be null; it must outlive the publisher. Throws std::runtime_error naming
  // the endpoint when binding fails.
  Publisher(Context& context, Identity identity, const std::string& bind_endpoint, SocketOptions options = {},
            Accounting* accounting = nullptr);
  // Sends delayed (fault-injected) messages at once, then closes; ZeroMQ keeps flushing
  // queued messages for up to linger_ms while the Context is being destroyed.
  ~Publisher() override;
  Publisher(const Publisher&) = delete;
  Publisher& operator=(const Publisher&) = delete;

  // Binds one more endpoint (e.g. tcp beside inproc).
  void bind(const std::string& endpoint);

  // Returns false when the message was not sent: invalid topic, oversize, dropped by fault
  // injection, or refused by ZeroMQ. A delayed message returns true (it is queued), and so
  // does one handed to the radio (which may still expire it, counted as radio_expired).
  template <typename M>
  bool publish(std::string_view topic, const M& message, int64_t sim_time_ns = 0) {
    return publish_message(topic, type_name<M>(), message, sim_time_ns);
  }
  bool publish_message(std::string_view topic, std::string_view payload_type,
                       const google::protobuf::MessageLite& message, int64_t sim_time_ns);

  // Resolved endpoints (an ephemeral "*" port replaced by the bound one), in bind order.
  const std::vector<std::string>& endpoints() const { return endpoints_; }
  const std::string& endpoint() const { return endpoints_.front(); }
  const Identity& identity() const { return identity_; }
  // Last sequence number used on `topic` (0 before the first message).
  uint64_t last_sequence(std::string_view topic) const;
  size_t delayed_count() const { return delayed_.size(); }
  // Sends every delayed message now, whether due or not.
  void flush_delayed();

  // Pollable: delayed messages are sent by the loop when due.
  zmq::socket_t* input_socket() override { return nullptr; }
  zmq::socket_t* socket() override { return &socket_; }
  std::optional<int64_t> next_deadline_ns() const override;
  void on_deadline(int64_t now_ns) override;

 protected:
  const char* role() const override { return "publisher"; }

 private:
  struct Delayed {
    int64_t due_ns;
    std::string topic;
    zmq::message_t header;
    zmq::message_t payload;
  };
  bool send_frames(std::string_view topic, zmq::message_t& header, zmq::message_t& payload);
  // Queues a message for `due_ns`, keeping the queue in due order.
  void delay(Delayed d);
  // Hands a team message to the radio, which schedules (or expires) it.
  void submit_to_radio(Delayed d);

  // Lets the sequence map be searched with a string_view (no allocation per publish).
  struct TopicHash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
  };

  Identity identity_;
  SocketOptions options_;
  Accounting* accounting_;
  zmq::socket_t socket_;
  std::vector<std::string> endpoints_;
  std::unordered_map<std::string, uint64_t, TopicHash, std::equal_to<>> sequences_;
  v1::Header header_;  // identity fields set once; per-message fields overwritten on each publish
  std::deque<Delayed> delayed_;
  std::mt19937_64 rng_;
  std::string payload_buffer_;
  std::string header_buffer_;
  std::optional<uint32_t> radio_slot_;  // this robot's slot when its team messages go on the radio
  uint64_t radio_order_ = 0;
};

}  // namespace hexplore::transport
