#include "common/transport/subscriber.h"

#include <stdexcept>

#include <zmq_addon.hpp>

#include "common/core/clock.h"
#include "common/core/log.h"
#include "common/transport/socket_util.h"
#include "common/transport/topics.h"

namespace hexplore::transport {

struct Subscriber::State {
  State(Context& context, SocketOptions opts, Accounting* acc)
      : options(std::move(opts)), accounting(acc), socket(context.zmq(), zmq::socket_type::sub) {}
  SocketOptions options;
  Accounting* accounting;
  zmq::socket_t socket;
  std::vector<Handler> handlers;
  v1::Header header;
};

Subscriber::Subscriber(Context& context, SocketOptions options, Accounting* accounting)
    : state_(std::make_unique<State>(context, std::move(options), accounting)) {
  state_->options.validate();
  detail::apply_options(state_->socket, state_->options);
}

Subscriber::Subscriber(Subscriber&&) noexcept = default;
Subscriber& Subscriber::operator=(Subscriber&&) noexcept = default;
Subscriber::~Subscriber() = default;

void Subscriber::connect(const std::string& endpoint) { detail::connect(state_->socket, endpoint); }

void Subscriber::add_handler(std::string prefix, const std::string& type, Dispatch dispatch) {
  if (!topics::is_valid_prefix(prefix))
    throw std::invalid_argument("transport: invalid subscription prefix '" + prefix + "'");
  // Subscribe once per distinct prefix; ZeroMQ counts duplicate subscriptions anyway.
  state_->socket.set(zmq::sockopt::subscribe, prefix);
  state_->handlers.push_back(Handler{std::move(prefix), type, std::move(dispatch)});
}

zmq::socket_t* Subscriber::input_socket() { return &state_->socket; }

namespace {

void drop(Accounting* accounting, std::string_view topic, DropReason reason, std::string_view detail) {
  if (accounting) accounting->record_dropped(topic, reason);
  core::log_once(core::LogLevel::kWarn, "transport", "drop:" + std::string(drop_reason_name(reason)),
                 "dropping frame (" + std::string(drop_reason_name(reason)) + ") on topic '" +
                     std::string(topics::topic_label(topic)) + "': " + std::string(detail) +
                     " (further drops of this kind are only counted)");
}

}  // namespace

void Subscriber::handle(std::vector<zmq::message_t>& frames) {
  State& s = *state_;
  const std::string_view topic = frames.empty() ? std::string_view() : frames[0].to_string_view();
  if (frames.size() != 3) {
    drop(s.accounting, topic, DropReason::kMalformed, std::to_string(frames.size()) + " frames instead of 3");
    return;
  }
  if (!topics::is_valid_topic(topic)) {
    drop(s.accounting, topic, DropReason::kMalformed, "invalid topic");
    return;
  }
  if (auto reason = check_envelope(frames[1], frames[2], s.options.max_message_bytes, s.header)) {
    std::string detail;
    switch (*reason) {
      case DropReason::kOversize:
        detail = std::to_string(frames[2].size()) + "-byte payload above max_message_bytes " +
                 std::to_string(s.options.max_message_bytes);
        break;
      case DropReason::kWrongVersion:
        detail = "schema version " + std::to_string(s.header.schema_version()) + ", expected " +
                 std::to_string(current_schema_version());
        break;
      default:
        detail = "unparsable header";
    }
    drop(s.accounting, topic, *reason, detail);
    return;
  }
  const int64_t received_ns = core::wall_time_ns();
  bool type_matched = false;
  bool parse_failed = false;
  for (Handler& h : s.handlers) {
    if (!topics::matches(h.prefix, topic) || h.type != s.header.payload_type()) continue;
    type_matched = true;
    try {
      if (!h.dispatch(topic, s.header, frames[2].data(), frames[2].size())) parse_failed = true;
    } catch (const std::exception& e) {
      // A handler bug or a message it cannot use must not take the service down.
      drop(s.accounting, topic, DropReason::kHandlerError, std::string("handler threw: ") + e.what());
      return;
    }
  }
  if (!type_matched) {
    drop(s.accounting, topic, DropReason::kWrongType, "payload type '" + s.header.payload_type().substr(0, 80) +
                                                          "' has no handler for this topic");
    return;
  }
  if (parse_failed) {
    drop(s.accounting, topic, DropReason::kMalformed, "payload does not parse as " + s.header.payload_type());
    return;
  }
  if (s.accounting) {
    const size_t bytes = frames[0].size() + frames[1].size() + frames[2].size();
    s.accounting->record_received(topic, s.header.robot_id(), bytes, received_ns - s.header.send_time_ns());
  }
}

bool Subscriber::receive_one(std::chrono::milliseconds timeout) {
  zmq::pollitem_t item{static_cast<void*>(state_->socket), 0, ZMQ_POLLIN, 0};
  zmq::poll(&item, 1, timeout);
  if ((item.revents & ZMQ_POLLIN) == 0) return false;
  return drain(1) == 1;
}

}  // namespace hexplore::transport
