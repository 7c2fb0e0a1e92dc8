#include "common/transport/request_reply.h"

#include <thread>

#include <zmq_addon.hpp>

#include "common/core/clock.h"
#include "common/core/endpoints.h"
#include "common/core/log.h"
#include "common/transport/socket_util.h"
#include "common/transport/topics.h"

namespace hexplore::transport {

std::string request_topic(std::string_view type) { return "request/" + std::string(type); }

namespace {

void drop(Accounting* accounting, std::string_view topic, DropReason reason, const std::string& what) {
  if (accounting) accounting->record_dropped(topic, reason);
  core::log_once(core::LogLevel::kWarn, "transport", "rr-drop:" + std::string(drop_reason_name(reason)),
                 what + " (further drops of this kind are only counted)");
}

size_t total_size(const std::vector<zmq::message_t>& frames) {
  size_t n = 0;
  for (const auto& f : frames) n += f.size();
  return n;
}

// Whether `other` is another robot of the team than `self` (not the station): a reply to it
// crosses the radio.
bool to_teammate(const SocketOptions& options, std::string_view self, std::string_view other) {
  if (!options.roster || self == other || self == core::kStationId || other == core::kStationId) return false;
  return options.roster->slot(self).has_value() && options.roster->slot(other).has_value();
}

}  // namespace

// ---------------------------------------------------------------------------------------------
Responder::Responder(Context& context, Identity identity, const std::string& bind_endpoint, SocketOptions options,
                     Accounting* accounting)
    : identity_(std::move(identity)),
      options_(std::move(options)),
      accounting_(accounting),
      socket_(context.zmq(), zmq::socket_type::router) {
  options_.validate();
  detail::apply_options(socket_, options_);
  detail::guard_server(context, socket_, options_);
  endpoint_ = detail::bind(socket_, bind_endpoint, options_);
}

Responder::~Responder() { socket_.close(); }

void Responder::add_handler(const std::string& request_type, const std::string& reply_type, Handle handle) {
  remember_type_name(request_type);
  remember_type_name(reply_type);
  handlers_[type_id(request_type)] = Handler{request_type, reply_type, std::move(handle)};
}

void Responder::ReplyOut::encode(const google::protobuf::MessageLite& reply) {
  // Payload type ids are of the reply type; encode_payload looks its codec up by it.
  flags = encode_payload(reply, type_id(reply.GetTypeName()), radio, options, bytes);
}

void Responder::reply(zmq::message_t& routing_id, const v1::Header& request, std::string_view reply_type,
                      const ReplyOut* out) {
  v1::Header header = make_header(identity_, request.sequence(), reply_type, request.sim_time_ns());
  // A reply to a teammate is radio traffic (roster slot, compact payload); others go by name.
  const bool radio = out != nullptr && out->radio;
  zmq::message_t header_frame =
      transport::header_frame(header, radio ? options_.roster.get() : nullptr, out ? out->flags : 0, true);
  zmq::message_t payload = out ? zmq::message_t(out->bytes.data(), out->bytes.size()) : zmq::message_t();
  const size_t bytes = header_frame.size() + payload.size();
  try {
    // ROUTER drops replies to peers that are gone or full rather than blocking.
    socket_.send(routing_id, zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    socket_.send(zmq::message_t(), zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    socket_.send(header_frame, zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    socket_.send(payload, zmq::send_flags::dontwait);
  } catch (const zmq::error_t& e) {
    drop(accounting_, request_topic(reply_type.empty() ? "unserved" : reply_type), DropReason::kSendFailed,
         std::string("reply send failed: ") + e.what());
    return;
  }
  if (accounting_)
    accounting_->record_sent(request_topic(reply_type.empty() ? "unserved" : reply_type), request.robot_id(), bytes);
}

void Responder::handle(std::vector<zmq::message_t>& frames) {
  DecodedHeader decoded;
  const v1::Header& header = decoded.header;
  // [routing id][empty][header][payload]
  if (frames.size() != 4 || frames[1].size() != 0) {
    drop(accounting_, "request/invalid", DropReason::kMalformed,
         "request with " + std::to_string(frames.size()) + " frames, expected [id][empty][header][payload]");
    return;
  }
  if (auto reason = check_envelope(frames[2], frames[3], options_.max_message_bytes, options_.roster.get(), decoded)) {
    drop(accounting_, "request/invalid", *reason, "request rejected: " + std::string(drop_reason_name(*reason)));
    return;
  }
  auto it = handlers_.find(decoded.type_id);
  if (it == handlers_.end() || decoded.payload_flags != 0) {
    // Requests always travel as plain protobuf; anything else is not ours to serve.
    drop(accounting_, "request/unserved", DropReason::kWrongType,
         "no handler for request " + type_label(decoded.type_id));
    reply(frames[0], header, "", nullptr);
    return;
  }
  decoded.header.set_payload_type(it->second.request_type);
  const std::string topic = request_topic(header.payload_type());
  const size_t wire_bytes = total_size(frames) - frames[0].size();
  if (accounting_)
    accounting_->record_received(topic, header.robot_id(), wire_bytes,
                                 std::max<int64_t>(0, core::wall_time_ns() - header.send_time_ns()));
  ReplyOut out{options_, to_teammate(options_, identity_.robot_id, header.robot_id()), {}, 0};
  bool parsed = false;
  try {
    // The CURVE guard's name for the peer (ZAP User-Id), on every frame of an authenticated link.
    const char* member = zmq_msg_gets(frames[2].handle(), "User-Id");
    parsed = it->second.handle(header, frames[3].to_string_view(), wire_bytes, member ? member : "", out);
  } catch (const std::exception& e) {
    core::log_once(core::LogLevel::kError, "transport", "handler-threw:" + header.payload_type(),
                   "handler for " + header.payload_type() + " threw: " + e.what());
    reply(frames[0], header, "", nullptr);
    return;
  }
  if (!parsed) {
    drop(accounting_, topic, DropReason::kMalformed, "request payload does not parse as " + header.payload_type());
    reply(frames[0], header, "", nullptr);
    return;
  }
  reply(frames[0], header, it->second.reply_type, &out);
}

// ---------------------------------------------------------------------------------------------
Requester::Requester(Context& context, Identity identity, const std::string& connect_endpoint, SocketOptions options,
                     Accounting* accounting, std::string peer_robot_id)
    : identity_(std::move(identity)),
      options_(std::move(options)),
      accounting_(accounting),
      socket_(context.zmq(), zmq::socket_type::dealer),
      peer_(peer_robot_id.empty() ? "unknown" : std::move(peer_robot_id)) {
  options_.validate();
  detail::apply_options(socket_, options_);
  // A request still queued at close can never be answered: do not let it hold up shutdown.
  socket_.set(zmq::sockopt::linger, 0);
  detail::connect(socket_, connect_endpoint, options_, peer_);
}

Requester::~Requester() { socket_.close(); }

void Requester::send_request(std::string_view request_type, const google::protobuf::MessageLite& request,
                             std::string_view reply_type, Complete complete, std::chrono::milliseconds timeout) {
  const uint64_t sequence = next_sequence_++;
  const std::string topic = request_topic(request_type);
  zmq::message_t payload = to_frame(request);
  if (static_cast<int64_t>(payload.size()) > options_.max_message_bytes) {
    drop(accounting_, topic, DropReason::kOversize, "request above max_message_bytes not sent");
    complete(nullptr);
    return;
  }
  remember_type_name(request_type);
  remember_type_name(reply_type);
  zmq::message_t header = transport::header_frame(make_header(identity_, sequence, request_type, 0), nullptr);
  const size_t bytes = header.size() + payload.size();
  bool sent = false;
  try {
    // DEALER blocks at the high-water mark or with no connected peer; dontwait turns that
    // into an immediate failure instead of stalling the loop.
    sent = socket_.send(zmq::message_t(), zmq::send_flags::sndmore | zmq::send_flags::dontwait).has_value();
    if (sent) {
      socket_.send(header, zmq::send_flags::sndmore);
      socket_.send(payload, zmq::send_flags::none);
    }
  } catch (const zmq::error_t& e) {
    sent = false;
  }
  if (!sent) {
    drop(accounting_, topic, DropReason::kSendFailed, "request " + topic + " could not be sent (no peer or queue full)");
    complete(nullptr);
    return;
  }
  if (accounting_) accounting_->record_sent(topic, peer_, bytes);
  pending_.emplace(sequence, Pending{now_ns() + std::chrono::nanoseconds(timeout).count(),
                                     std::string(reply_type), std::move(complete)});
}

bool Requester::radio_delivers(const v1::Header& reply, std::string_view topic) {
  if (!options_.radio || !to_teammate(options_, identity_.robot_id, reply.robot_id())) return true;
  const Roster& roster = options_.radio->roster();
  const uint32_t self = *roster.slot(identity_.robot_id);
  const uint32_t peer = *roster.slot(reply.robot_id());
  // Both legs: the request out and the reply back.
  RadioVerdict verdict = options_.radio->receive(self, peer, "request", reply.sequence(), now_ns());
  if (verdict == RadioVerdict::kDelivered) verdict = options_.radio->receive(peer, self, topic, reply.sequence(), now_ns());
  if (verdict == RadioVerdict::kDelivered) return true;
  if (accounting_)
    accounting_->record_dropped(topic, verdict == RadioVerdict::kLost ? DropReason::kRadioLost : DropReason::kRadioOutOfRange);
  return false;
}

void Requester::handle(std::vector<zmq::message_t>& frames) {
  DecodedHeader decoded;
  const v1::Header& header = decoded.header;
  if (frames.size() != 3 || frames[0].size() != 0) {
    drop(accounting_, "request/invalid", DropReason::kMalformed, "reply with wrong frame layout");
    return;
  }
  if (auto reason = check_envelope(frames[1], frames[2], options_.max_message_bytes, options_.roster.get(), decoded)) {
    drop(accounting_, "request/invalid", *reason, "reply rejected: " + std::string(drop_reason_name(*reason)));
    return;
  }
  auto it = pending_.find(header.sequence());
  if (it == pending_.end()) return;  // late reply to a request that already timed out
  if (decoded.type_id == 0) {
    // Type id 0 is the responder's "not served" answer.
    Complete complete = std::move(it->second.complete);
    pending_.erase(it);
    complete(nullptr);
    return;
  }
  const std::string topic = request_topic(it->second.reply_type);
  if (decoded.type_id != type_id(it->second.reply_type)) {
    drop(accounting_, topic, DropReason::kWrongType, "reply " + type_label(decoded.type_id) + " instead of " +
                                                         it->second.reply_type);
    Complete complete = std::move(it->second.complete);
    pending_.erase(it);
    complete(nullptr);
    return;
  }
  // A reply lost on the radio leaves the request to time out, as a real loss would.
  if (!radio_delivers(header, topic)) return;
  decoded.header.set_payload_type(it->second.reply_type);
  std::string_view payload;
  if (!unpack_payload(frames[2].to_string_view(), decoded.payload_flags, decoded.type_id, options_, scratch_,
                      payload)) {
    drop(accounting_, topic, DropReason::kMalformed, "compressed reply is corrupt, too large, or of a dictionary this build does not hold");
    return;  // times out
  }
  const size_t wire_bytes = frames[1].size() + frames[2].size();
  if (accounting_)
    accounting_->record_received(topic, header.robot_id(), wire_bytes,
                                 std::max<int64_t>(0, core::wall_time_ns() - header.send_time_ns()));
  Complete complete = std::move(it->second.complete);
  pending_.erase(it);
  const Reply reply{header, wire_bytes, payload, decoded.payload_flags, decoded.type_id, options_};
  if (!complete(&reply))
    drop(accounting_, topic, DropReason::kMalformed, "reply payload does not parse as " + header.payload_type());
}

std::optional<int64_t> Requester::next_deadline_ns() const {
  std::optional<int64_t> earliest;
  for (const auto& [sequence, p] : pending_)
    if (!earliest || p.deadline_ns < *earliest) earliest = p.deadline_ns;
  return earliest;
}

void Requester::on_deadline(int64_t now_ns) {
  for (auto it = pending_.begin(); it != pending_.end();) {
    if (it->second.deadline_ns > now_ns) {
      ++it;
      continue;
    }
    Complete complete = std::move(it->second.complete);
    const std::string topic = request_topic(it->second.reply_type);
    it = pending_.erase(it);
    if (accounting_) accounting_->record_dropped(topic, DropReason::kTimeout);
    complete(nullptr);
  }
}

void Requester::wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const int64_t end_ns = now_ns() + std::chrono::nanoseconds(timeout).count();
  while (!done()) {
    const int64_t now = now_ns();
    on_deadline(now);
    if (done() || now >= end_ns) break;
    int64_t wait_ns = end_ns - now;
    if (auto deadline = next_deadline_ns()) wait_ns = std::min(wait_ns, std::max<int64_t>(0, *deadline - now));
    zmq::pollitem_t item{static_cast<void*>(socket_), 0, ZMQ_POLLIN, 0};
    zmq::poll(&item, 1, std::chrono::milliseconds(wait_ns / 1'000'000 + 1));
    if (item.revents & ZMQ_POLLIN) drain(100);
  }
}

}  // namespace hexplore::transport
