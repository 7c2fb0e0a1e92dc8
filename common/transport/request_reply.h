#pragma once
// Request/reply over ROUTER (Responder, binds) and DEALER (Requester, connects). Wire:
// [routing id][empty][Header][payload]; the reply header echoes the request's sequence so
// replies match requests, and an empty payload_type in a reply means "not served".
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
                [handler = std::move(handler), request = Req()](const v1::Header& header, const void* data,
                                                                size_t size, zmq::message_t& reply_out) mutable {
                  request.Clear();
                  if (!request.ParseFromArray(data, static_cast<int>(size))) return false;
                  const Rep reply = handler(Received<Req>{request_topic(type_name<Req>()), header, request});
                  reply_out = to_frame(reply);
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
  using Handle = std::function<bool(const v1::Header&, const void*, size_t, zmq::message_t&)>;
  void add_handler(const std::string& request_type, const std::string& reply_type, Handle handle);
  void reply(zmq::message_t& routing_id, const v1::Header& request, std::string_view reply_type,
             zmq::message_t payload);

  struct Handler {
    std::string reply_type;
    Handle handle;
  };
  Identity identity_;
  SocketOptions options_;
  Accounting* accounting_;
  zmq::socket_t socket_;
  std::string endpoint_;
  std::unordered_map<std::string, Handler> handlers_;
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
                 [on_reply = std::move(on_reply)](const v1::Header* header, const void* data, size_t size) {
                   if (header == nullptr) {
                     on_reply(nullptr);
                     return true;
                   }
                   Rep reply;
                   if (!reply.ParseFromArray(data, static_cast<int>(size))) {
                     on_reply(nullptr);
                     return false;
                   }
                   const std::string topic = request_topic(type_name<Rep>());
                   const Received<Rep> received{topic, *header, reply};
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
  // header == nullptr: failed (time-out or not served). Returns false when the reply was unparsable.
  using Complete = std::function<bool(const v1::Header*, const void*, size_t)>;
  void send_request(std::string_view request_type, const google::protobuf::MessageLite& request,
                    std::string_view reply_type, Complete complete, std::chrono::milliseconds timeout);
  void wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout);

  struct Pending {
    int64_t deadline_ns;
    std::string reply_type;
    Complete complete;
  };
  Identity identity_;
  SocketOptions options_;
  Accounting* accounting_;
  zmq::socket_t socket_;
  std::string peer_;
  uint64_t next_sequence_ = 1;
  std::map<uint64_t, Pending> pending_;
};

}  // namespace hexplore::transport
