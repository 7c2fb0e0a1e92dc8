#pragma once
// Typed subscriber on a SUB socket. on<M>(prefix, handler) subscribes to a topic prefix and
// calls the handler with the parsed message; frames with a bad envelope, a payload type other
// than M or an unparsable payload are counted by reason and dropped. Team messages between
// robots pass the radio model's receiver side (loss, range) when the socket has one. Not
// thread-safe: one thread (the loop thread) receives.

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <zmq.hpp>

#include "common/transport/accounting.h"
#include "common/transport/context.h"
#include "common/transport/envelope.h"
#include "common/transport/payload_wire.h"
#include "common/transport/pollable.h"
#include "common/transport/socket_options.h"
#include "hexplore/v1/header.pb.h"

namespace hexplore::transport {

// A message handed to a handler; valid only during the call.
template <typename M>
struct Received {
  std::string_view topic;
  const v1::Header& header;
  const M& message;
  size_t wire_bytes = 0;  // what it took on the wire: topic, header and payload frames
  // The team member whose key the link proved (CURVE, set on requests a Responder serves);
  // "" on a plain link. Unlike header.robot_id() it cannot be claimed by the sender.
  std::string_view authenticated_member = {};
};

class Subscriber : public Pollable {
 public:
  // `accounting` may be null; it must outlive the subscriber.
  Subscriber(Context& context, SocketOptions options = {}, Accounting* accounting = nullptr);
  // Movable while not registered with an EventLoop (the loop keeps its address).
  Subscriber(Subscriber&&) noexcept;
  Subscriber& operator=(Subscriber&&) noexcept;
  ~Subscriber() override;

  // Connects to a publisher; may be called before that publisher binds (ZeroMQ retries).
  // `peer`: the member the publisher belongs to, whose public key a CURVE client checks.
  void connect(const std::string& endpoint, const std::string& peer = "");

  // Calls `handler` for every message whose topic starts with `topic_prefix` and whose
  // header says payload type M. Several handlers may share a prefix; each message goes to
  // every handler whose prefix matches. A handler that throws std::exception has the message
  // counted as handler_error (the loop goes on). Throws std::invalid_argument on a malformed prefix.
  template <typename M>
  void on(std::string_view topic_prefix, std::function<void(const Received<M>&)> handler) {
    add_handler(std::string(topic_prefix), type_name<M>(),
                [handler = std::move(handler), message = M()](const Delivery& d) mutable {
                  if (!d.parse(message)) return false;
                  handler(Received<M>{d.topic, d.header, message, d.wire_bytes});
                  return true;
                });
  }

  // Waits up to `timeout` for one message and dispatches it; for tools and tests without a loop.
  bool receive_one(std::chrono::milliseconds timeout);

  zmq::socket_t* input_socket() override;
  void handle(std::vector<zmq::message_t>& frames) override;
  int header_frame() const override { return 1; }

 protected:
  const char* role() const override { return "subscriber"; }

 private:
  // One received message as the handlers see it; parse() fills a handler's message from the
  // (already unpacked) payload bytes.
  struct Delivery {
    std::string_view topic;
    const v1::Header& header;
    size_t wire_bytes;
    std::string_view payload;  // decompressed
    uint8_t payload_flags;
    uint16_t type_id;
    const SocketOptions& options;
    bool parse(google::protobuf::MessageLite& message) const {
      return parse_payload(payload, payload_flags, type_id, options, message);
    }
  };
  // Parses the payload into the handler's type and calls it; false when parsing failed.
  using Dispatch = std::function<bool(const Delivery&)>;
  void add_handler(std::string prefix, const std::string& type, Dispatch dispatch);
  // Applies the radio's receiver side; false (counted) when the message does not arrive.
  bool radio_delivers(std::string_view topic, const v1::Header& header);

  struct Handler {
    std::string prefix;
    std::string type;
    uint16_t type_id;
    Dispatch dispatch;
  };
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace hexplore::transport
