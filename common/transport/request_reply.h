#pragma once
// Request/reply over ROUTER (Responder, binds) and DEALER (Requester, connects). Wire:
// [routing id][empty][header][payload]; the reply header echoes the request's sequence so
// replies match requests, and payload type id 0 in a reply means "not served". A reply to
// a teammate (another robot of SocketOptions::roster) crosses the radio: it travels with a
// roster slot, in its compact codec form and compressed like a team message, and the radio
// model's loss and range apply to the round trip.
// Neither is thread-safe: use each from one thread (the loop thread).

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include <zmq.hpp>

#include "common/transport/accounting.h"
#include "common/transport/context.h"
#include "common/transport/envelope.h"
#include "common/transport/payload_wire.h"
#include "common/transport/pollable.h"
#include "common/transport/socket_options.h"
#include "common/transport/subscriber.h"

namespace hexplore::transport {

// Accounting topic label of a request or reply of type `type`: "request/<full type name>".
std::string request_topic(std::string_view type);

class Responder : public Pollable {
 public:
  // Throws std::runtime_error naming the endpoint when binding fails.
  Responder(Context& context, Identity identity, const std::string& bind_endpoint, SocketOptions options = {},
            Accounting* accounting = nullptr);
  ~Responder() override;
  Responder(const Responder&) = delete;
  Responder& operator=(const Responder&) = delete;

  // Serves requests of type Req with a reply of type Rep (one handler per request type).
  template <typename Req, typename Rep>
  void serve(std::function<Rep(const Received<Req>&)> handler) {
    add_handler(type_name<Req>(), type_name<Rep>(),
                [handler = std::move(handler), request = Req()](const v1::Header& header, std::string_view data,
                                                                size_t wire_bytes, std::string_view member,
                                                                ReplyOut& reply_out) mutable {
                  request.Clear();
                  if (!request.ParseFromArray(data.data(), static_cast<int>(data.size()))) return false;
                  const Rep reply =
                      handler(Received<Req>{request_topic(type_name<Req>()), header, request, wire_bytes, member});
                  reply_out.encode(reply);
                  return true;
                });
  }

  const std::string& endpoint() const { return endpoint_; }

  zmq::socket_t* input_socket() override { return &socket_; }
  void handle(std::vector<zmq::message_t>& frames) override;
  int header_frame() const override { return 2; }

 protected:
  const char* role() const override { return "responder"; }

 private:
  // The reply's payload frame and flags, encoded for where it goes.
  struct ReplyOut {
    const SocketOptions& options;
    bool radio;  // to another robot: compact and compressed like a team message
    std::string bytes;
    uint8_t flags = 0;
    void encode(const google::protobuf::MessageLite& reply);
  };
  // (header, payload, wire bytes, authenticated member or "", reply) -> parsed
  using Handle = std::function<bool(const v1::Header&, std::string_view, size_t, std::string_view, ReplyOut&)>;
  void add_handler(const std::string& request_type, const std::string& reply_type, Handle handle);
  void reply(zmq::message_t& routing_id, const v1::Header& request, std::string_view reply_type,
             const ReplyOut* payload);

  struct Handler {
    std::string request_type;
    std::string reply_type;
    Handle handle;
  };
  Identity identity_;
  SocketOptions options_;
  Accounting* accounting_;
  zmq::socket_t socket_;
  std::string endpoint_;
  std::unordered_map<uint16_t, Handler> handlers_;  // by request type id
};

class Requester : public Pollable {
 public:
  // `peer_robot_id` labels the requests this socket sends in the accounting ("" = "unknown").
  Requester(Context& context, Identity identity, const std::string& connect_endpoint, SocketOptions options = {},
            Accounting* accounting = nullptr, std::string peer_robot_id = "");
  ~Requester() override;
  Requester(const Requester&) = delete;
  Requester& operator=(const Requester&) = delete;

  // Sends `request`; `on_reply` is called once, from the loop thread, with the reply, or with
  // nullptr on time-out, an unserved request type or an unparsable reply.
  template <typename Req, typename Rep>
  void request(const Req& request, std::function<void(const Received<Rep>*)> on_reply,
               std::chrono::milliseconds timeout) {
    send_request(type_name<Req>(), request, type_name<Rep>(),
                 [on_reply = std::move(on_reply)](const Reply* r) {
                   if (r == nullptr) {
                     on_reply(nullptr);
                     return true;
                   }
                   Rep reply;
                   if (!r->parse(reply)) {
                     on_reply(nullptr);
                     return false;
                   }
                   const std::string topic = request_topic(type_name<Rep>());
                   const Received<Rep> received{topic, r->header, reply, r->wire_bytes};
                   on_reply(&received);
                   return true;
                 },
                 timeout);
  }

  // Blocking request for tools and tests; do not mix with pending asynchronous requests.
  template <typename Req, typename Rep>
  std::optional<Rep> call(const Req& request_message, std::chrono::milliseconds timeout) {
    std::optional<Rep> result;
    bool done = false;
    request<Req, Rep>(
        request_message,
        [&](const Received<Rep>* reply) {
          done = true;
          if (reply != nullptr) result = reply->message;
        },
        timeout);
    wait_until([&] { return done; }, timeout + std::chrono::milliseconds(100));
    return result;
  }

  size_t pending() const { return pending_.size(); }

  zmq::socket_t* input_socket() override { return &socket_; }
  void handle(std::vector<zmq::message_t>& frames) override;
  int header_frame() const override { return 1; }
  std::optional<int64_t> next_deadline_ns() const override;
  void on_deadline(int64_t now_ns) override;

 protected:
  const char* role() const override { return "requester"; }

 private:
  // A received reply, parsed on demand into the caller's type.
  struct Reply {
    const v1::Header& header;
    size_t wire_bytes;
    std::string_view payload;  // decompressed
    uint8_t flags;
    uint16_t type_id;
    const SocketOptions& options;
    bool parse(google::protobuf::MessageLite& m) const { return parse_payload(payload, flags, type_id, options, m); }
  };
  // nullptr: failed (time-out or not served). Returns false when the reply was unparsable.
  using Complete = std::function<bool(const Reply*)>;
  // Whether the round trip to a robot survives the radio (counted when it does not).
  bool radio_delivers(const v1::Header& reply, std::string_view topic);
  void send_request(std::string_view request_type, const google::protobuf::MessageLite& request,
                    std::string_view reply_type, Complete complete, std::chrono::milliseconds timeout);
  void wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout);

  struct Pending {
    int64_t deadline_ns;
    std::string reply_type;
    Complete complete;
  };
  std::string scratch_;
  Identity identity_;
  SocketOptions options_;
  Accounting* accounting_;
  zmq::socket_t socket_;
  std::string peer_;
  uint64_t next_sequence_ = 1;
  std::map<uint64_t, Pending> pending_;
};

}  // namespace hexplore::transport
