#include "common/transport/request_reply.h"

#include <thread>

#include <zmq_addon.hpp>

#include "common/core/clock.h"
#include "common/core/log.h"
#include "common/transport/socket_util.h"

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
  endpoint_ = detail::bind(socket_, bind_endpoint);
}

Responder::~Responder() { socket_.close(); }

void Responder::add_handler(const std::string& request_type, const std::string& reply_type, Handle handle) {
  handlers_[request_type] = Handler{reply_type, std::move(handle)};
}

void Responder::reply(zmq::message_t& routing_id, const v1::Header& request, std::string_view reply_type,
                      zmq::message_t payload) {
  v1::Header header = make_header(identity_, request.sequence(), reply_type, request.sim_time_ns());
  zmq::message_t header_frame = to_frame(header);
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
  v1::Header header;
  // [routing id][empty][Header][payload]
  if (frames.size() != 4 || frames[1].size() != 0) {
    drop(accounting_, "request/invalid", DropReason::kMalformed,
         "request with " + std::to_string(frames.size()) + " frames, expected [id][empty][header][payload]");
    return;
  }
  if (auto reason = check_envelope(frames[2], frames[3], options_.max_message_bytes, header)) {
    drop(accounting_, "request/invalid", *reason, "request rejected: " + std::string(drop_reason_name(*reason)));
    return;
  }
  const std::string topic = request_topic(header.payload_type());
  auto it = handlers_.find(header.payload_type());
  if (it == handlers_.end()) {
    drop(accounting_, "request/unserved", DropReason::kWrongType,
         "no handler for request type '" + header.payload_type().substr(0, 80) + "'");
    reply(frames[0], header, "", zmq::message_t());
    return;
  }
  if (accounting_)
    accounting_->record_received(topic, header.robot_id(), total_size(frames) - frames[0].size(),
                                 core::wall_time_ns() - header.send_time_ns());
  zmq::message_t reply_payload;
  bool parsed = false;
  try {
    parsed = it->second.handle(header, frames[3].data(), frames[3].size(), reply_payload);
  } catch (const std::exception& e) {
    core::log_once(core::LogLevel::kError, "transport", "handler-threw:" + header.payload_type(),
                   "handler for " + header.payload_type() + " threw: " + e.what());
    reply(frames[0], header, "", zmq::message_t());
    return;
  }
  if (!parsed) {
    drop(accounting_, topic, DropReason::kMalformed, "request payload does not parse as " + header.payload_type());
    reply(frames[0], header, "", zmq::message_t());
    return;
  }
  reply(frames[0], header, it->second.reply_type, std::move(reply_payload));
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
  detail::connect(socket_, connect_endpoint);
}

Requester::~Requester() { socket_.close(); }

void Requester::send_request(std::string_view request_type, const google::protobuf::MessageLite& request,
                             std::string_view reply_type, Complete complete, std::chrono::milliseconds timeout) {
  const uint64_t sequence = next_sequence_++;
  const std::string topic = request_topic(request_type);
  zmq::message_t payload = to_frame(request);
  if (static_cast<int64_t>(payload.size()) > options_.max_message_bytes) {
    drop(accounting_, topic, DropReason::kOversize, "request above max_message_bytes not sent");
    complete(nullptr, nullptr, 0);
    return;
  }
  zmq::message_t header = to_frame(make_header(identity_, sequence, request_type, 0));
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
    complete(nullptr, nullptr, 0);
    return;
  }
  if (accounting_) accounting_->record_sent(topic, peer_, bytes);
  pending_.emplace(sequence, Pending{now_ns() + std::chrono::nanoseconds(timeout).count(),
                                     std::string(reply_type), std::move(complete)});
}

void Requester::handle(std::vector<zmq::message_t>& frames) {
  v1::Header header;
  if (frames.size() != 3 || frames[0].size() != 0) {
    drop(accounting_, "request/invalid", DropReason::kMalformed, "reply with wrong frame layout");
    return;
  }
  auto reason = check_envelope(frames[1], frames[2], options_.max_message_bytes, header);
  if (reason && *reason != DropReason::kMalformed) {
    drop(accounting_, "request/invalid", *reason, "reply rejected: " + std::string(drop_reason_name(*reason)));
    return;
  }
  if (reason && header.payload_type().empty() && header.sequence() != 0) {
    // An empty payload_type is the responder's "not served" answer.
    auto it = pending_.find(header.sequence());
    if (it != pending_.end()) {
      Complete complete = std::move(it->second.complete);
      pending_.erase(it);
      complete(nullptr, nullptr, 0);
    }
    return;
  }
  if (reason) {
    drop(accounting_, "request/invalid", *reason, "reply with unparsable header");
    return;
  }
  auto it = pending_.find(header.sequence());
  if (it == pending_.end()) return;  // late reply to a request that already timed out
  const std::string topic = request_topic(header.payload_type());
  if (header.payload_type() != it->second.reply_type) {
    drop(accounting_, topic, DropReason::kWrongType, "reply of type '" + header.payload_type().substr(0, 80) +
                                                         "' instead of " + it->second.reply_type);
    Complete complete = std::move(it->second.complete);
    pending_.erase(it);
    complete(nullptr, nullptr, 0);
    return;
  }
  if (accounting_)
    accounting_->record_received(topic, header.robot_id(), frames[1].size() + frames[2].size(),
                                 core::wall_time_ns() - header.send_time_ns());
  Complete complete = std::move(it->second.complete);
  pending_.erase(it);
  if (!complete(&header, frames[2].data(), frames[2].size()))
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
    complete(nullptr, nullptr, 0);
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
