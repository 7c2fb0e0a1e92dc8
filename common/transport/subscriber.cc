#include "common/transport/subscriber.h"

#include <algorithm>
#include <stdexcept>

#include <zmq_addon.hpp>

#include "common/core/clock.h"
#include "common/core/endpoints.h"
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
  DecodedHeader decoded;
  std::string scratch;  // decompressed payloads
  std::optional<uint32_t> radio_slot;  // the receiving robot's slot when the radio applies
};

Subscriber::Subscriber(Context& context, SocketOptions options, Accounting* accounting)
    : state_(std::make_unique<State>(context, std::move(options), accounting)) {
  state_->options.validate();
  detail::apply_options(state_->socket, state_->options);
  const auto& o = state_->options;
  if (o.radio && !o.receiver_robot.empty() && o.receiver_robot != core::kStationId)
    state_->radio_slot = o.radio->roster().slot(o.receiver_robot);
}

Subscriber::Subscriber(Subscriber&&) noexcept = default;
Subscriber& Subscriber::operator=(Subscriber&&) noexcept = default;
Subscriber::~Subscriber() = default;

void Subscriber::connect(const std::string& endpoint, const std::string& peer) {
  detail::connect(state_->socket, endpoint, state_->options, peer);
}

void Subscriber::add_handler(std::string prefix, const std::string& type, Dispatch dispatch) {
  if (!topics::is_valid_prefix(prefix))
    throw std::invalid_argument("transport: invalid subscription prefix '" + prefix + "'");
  // Subscribe once per distinct prefix; ZeroMQ counts duplicate subscriptions anyway. A team
  // prefix also covers the wire codes of the team topics it matches.
  for (const std::string& wire : topics::wire_prefixes(prefix)) state_->socket.set(zmq::sockopt::subscribe, wire);
  remember_type_name(type);
  state_->handlers.push_back(Handler{std::move(prefix), type, type_id(type), std::move(dispatch)});
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

bool Subscriber::radio_delivers(std::string_view topic, const v1::Header& header) {
  State& s = *state_;
  if (!s.radio_slot || !topics::is_team_topic(topic)) return true;
  const auto sender = s.options.radio->roster().slot(header.robot_id());
  // The station and the robot itself are not on the other end of the radio.
  if (!sender || *sender == 0 || *sender == *s.radio_slot) return true;
  switch (s.options.radio->receive(*sender, *s.radio_slot, topic, header.sequence(), now_ns())) {
    case RadioVerdict::kDelivered: return true;
    case RadioVerdict::kLost:
      if (s.accounting) s.accounting->record_dropped(topic, DropReason::kRadioLost);
      return false;
    case RadioVerdict::kOutOfRange:
      if (s.accounting) s.accounting->record_dropped(topic, DropReason::kRadioOutOfRange);
      return false;
  }
  return true;
}

void Subscriber::handle(std::vector<zmq::message_t>& frames) {
  State& s = *state_;
  const std::string_view wire_topic = frames.empty() ? std::string_view() : frames[0].to_string_view();
  const std::optional<std::string_view> named = topics::topic_from_wire(wire_topic);
  const std::string_view topic = named.value_or(std::string_view());
  if (frames.size() != 3) {
    drop(s.accounting, topic, DropReason::kMalformed, std::to_string(frames.size()) + " frames instead of 3");
    return;
  }
  if (!named || !topics::is_valid_topic(topic)) {
    drop(s.accounting, topic, DropReason::kMalformed, "invalid topic");
    return;
  }
  const v1::Header& header = s.decoded.header;
  if (auto reason = check_envelope(frames[1], frames[2], s.options.max_message_bytes, s.options.roster.get(), s.decoded)) {
    std::string detail;
    switch (*reason) {
      case DropReason::kOversize:
        detail = std::to_string(frames[2].size()) + "-byte payload above max_message_bytes " +
                 std::to_string(s.options.max_message_bytes);
        break;
      case DropReason::kWrongVersion:
        detail = "schema version " + std::to_string(header.schema_version()) + ", expected " +
                 std::to_string(current_schema_version());
        break;
      default:
        detail = "unparsable header";
    }
    drop(s.accounting, topic, *reason, detail);
    return;
  }
  if (!radio_delivers(topic, header)) return;
  const int64_t received_ns = core::wall_time_ns();
  const uint16_t type = s.decoded.type_id;
  bool type_matched = false;
  bool parse_failed = false;
  std::string_view payload;
  const size_t wire_bytes = frames[0].size() + frames[1].size() + frames[2].size();
  for (Handler& h : s.handlers) {
    if (!topics::matches(h.prefix, topic) || h.type_id != type) continue;
    if (!type_matched) {
      type_matched = true;
      s.decoded.header.set_payload_type(h.type);
      if (!unpack_payload(frames[2].to_string_view(), s.decoded.payload_flags, type, s.options, s.scratch, payload)) {
        drop(s.accounting, topic, DropReason::kMalformed, "compressed payload is corrupt, too large, or of a dictionary this build does not hold");
        return;
      }
    }
    try {
      const Delivery d{topic, header, wire_bytes, payload, s.decoded.payload_flags, type, s.options};
      if (!h.dispatch(d)) parse_failed = true;
    } catch (const std::exception& e) {
      // A handler bug or a message it cannot use must not take the service down.
      drop(s.accounting, topic, DropReason::kHandlerError, std::string("handler threw: ") + e.what());
      return;
    }
  }
  if (!type_matched) {
    drop(s.accounting, topic, DropReason::kWrongType, "payload " + type_label(type) + " has no handler for this topic");
    return;
  }
  if (parse_failed) {
    drop(s.accounting, topic, DropReason::kMalformed, "payload does not parse as " + header.payload_type());
    return;
  }
  if (s.accounting) {
    // Radio messages carry no wall time: no latency sample for them.
    const int64_t latency_ns = s.decoded.has_wall_time ? std::max<int64_t>(0, received_ns - header.send_time_ns()) : -1;
    s.accounting->record_received(topic, header.robot_id(), wire_bytes, latency_ns);
  }
}

bool Subscriber::receive_one(std::chrono::milliseconds timeout) {
  zmq::pollitem_t item{static_cast<void*>(state_->socket), 0, ZMQ_POLLIN, 0};
  zmq::poll(&item, 1, timeout);
  if ((item.revents & ZMQ_POLLIN) == 0) return false;
  return drain(1) == 1;
}

}  // namespace hexplore::transport
