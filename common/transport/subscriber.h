#pragma once
// Typed subscriber on a SUB socket. on<M>(prefix, handler) subscribes to a topic prefix and
// calls the handler with the parsed message; frames with a bad envelope, a payload type other
// than M or an unparsable payload are counted by reason and dropped. Not thread-safe: one
// thread (the loop thread) receives.

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
  void connect(const std::string& endpoint);

  // Calls `handler` for every message whose topic starts with `topic_prefix` and whose
  // header says payload type M. Several handlers may share a prefix; each message goes to
  // every handler whose prefix matches. A handler that throws std::exception has the message
  // counted as handler_error (the loop goes on). Throws std::invalid_argument on a malformed prefix.
  template <typename M>
  void on(std::string_view topic_prefix, std::function<void(const Received<M>&)> handler) {
    add_handler(std::string(topic_prefix), type_name<M>(),
                [handler = std::move(handler), message = M()](std::string_view topic, const v1::Header& header,
                                                               const void* data, size_t size) mutable {
                  message.Clear();
                  if (!message.ParseFromArray(data, static_cast<int>(size))) return false;
                  handler(Received<M>{topic, header, message});
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
  // Parses the payload into the handler's type and calls it; false when parsing failed.
  using Dispatch = std::function<bool(std::string_view, const v1::Header&, const void*, size_t)>;
  void add_handler(std::string prefix, const std::string& type, Dispatch dispatch);

  struct Handler {
    std::string prefix;
    std::string type;
    Dispatch dispatch;
  };
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace hexplore::transport
