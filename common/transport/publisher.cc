#include "common/transport/publisher.h"

#include "common/core/clock.h"
#include "common/core/log.h"
#include "common/transport/socket_util.h"
#include "common/transport/topics.h"

namespace hexplore::transport {

Publisher::Publisher(Context& context, Identity identity, const std::string& bind_endpoint, SocketOptions options,
                     Accounting* accounting)
    : identity_(std::move(identity)),
      options_(std::move(options)),
      accounting_(accounting),
      socket_(context.zmq(), zmq::socket_type::pub),
      rng_(options_.faults.seed) {
  options_.validate();
  detail::apply_options(socket_, options_);
  bind(bind_endpoint);
  header_ = make_header(identity_, 0, "", 0);
}

Publisher::~Publisher() {
  flush_delayed();
  socket_.close();
}

void Publisher::bind(const std::string& endpoint) { endpoints_.push_back(detail::bind(socket_, endpoint)); }

uint64_t Publisher::last_sequence(std::string_view topic) const {
  auto it = sequences_.find(topic);
  return it == sequences_.end() ? 0 : it->second;
}

bool Publisher::publish_message(std::string_view topic, std::string_view payload_type,
                                const google::protobuf::MessageLite& message, int64_t sim_time_ns) {
  // A topic already in the sequence map was validated when it was first published.
  auto it = sequences_.find(topic);
  if (it == sequences_.end() && !topics::is_valid_topic(topic)) {
    if (accounting_) accounting_->record_dropped(topic, DropReason::kMalformed);
    core::log_once(core::LogLevel::kError, "transport", "publish-invalid-topic:" + std::string(topics::topic_label(topic)),
                   "refusing to publish on invalid topic '" + std::string(topic).substr(0, 64) + "'");
    return false;
  }
  const size_t payload_size = message.ByteSizeLong();
  if (static_cast<int64_t>(payload_size) > options_.max_message_bytes) {
    if (accounting_) accounting_->record_dropped(topic, DropReason::kOversize);
    core::log_once(core::LogLevel::kError, "transport", "publish-oversize:" + std::string(topic),
                   "dropping " + std::to_string(payload_size) + "-byte message on " + std::string(topic) +
                       ": above max_message_bytes " + std::to_string(options_.max_message_bytes));
    return false;
  }
  if (it == sequences_.end()) it = sequences_.emplace(std::string(topic), 0).first;
  const uint64_t sequence = ++it->second;
  const bool faulty = options_.faults.active() && options_.faults.applies_to(topic);
  if (faulty && options_.faults.drop_fraction > 0.0 &&
      std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < options_.faults.drop_fraction) {
    if (accounting_) accounting_->record_dropped(topic, DropReason::kFaultInjected);
    return false;
  }
  header_.set_sequence(sequence);
  header_.set_send_time_ns(core::wall_time_ns());
  header_.set_sim_time_ns(sim_time_ns);
  if (header_.payload_type() != payload_type) header_.set_payload_type(std::string(payload_type));
  zmq::message_t header = to_frame(header_);
  zmq::message_t payload(payload_size);
  if (payload_size > 0) message.SerializeWithCachedSizesToArray(static_cast<uint8_t*>(payload.data()));
  if (faulty && options_.faults.delay.count() > 0) {
    delayed_.push_back(Delayed{now_ns() + options_.faults.delay.count(), std::string(topic),
                               std::move(header), std::move(payload)});
    return true;
  }
  return send_frames(topic, header, payload);
}

bool Publisher::send_frames(std::string_view topic, zmq::message_t& header, zmq::message_t& payload) {
  const size_t bytes = topic.size() + header.size() + payload.size();
  try {
    // PUB never blocks: at the high-water mark ZeroMQ drops silently, so these only fail on
    // a closed socket or context.
    socket_.send(zmq::const_buffer(topic.data(), topic.size()), zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    socket_.send(header, zmq::send_flags::sndmore | zmq::send_flags::dontwait);
    socket_.send(payload, zmq::send_flags::dontwait);
  } catch (const zmq::error_t& e) {
    if (accounting_) accounting_->record_dropped(topic, DropReason::kSendFailed);
    core::log_once(core::LogLevel::kWarn, "transport", "publish-failed:" + std::string(topic),
                   "send on " + std::string(topic) + " failed: " + e.what());
    return false;
  }
  if (accounting_) accounting_->record_sent(topic, kBroadcastPeer, bytes);
  return true;
}

std::optional<int64_t> Publisher::next_deadline_ns() const {
  if (delayed_.empty()) return std::nullopt;
  return delayed_.front().due_ns;
}

void Publisher::on_deadline(int64_t now_ns) {
  // The delay is the same for every message, so the queue is in due order.
  while (!delayed_.empty() && delayed_.front().due_ns <= now_ns) {
    Delayed& d = delayed_.front();
    send_frames(d.topic, d.header, d.payload);
    delayed_.pop_front();
  }
}

void Publisher::flush_delayed() {
  while (!delayed_.empty()) {
    Delayed& d = delayed_.front();
    send_frames(d.topic, d.header, d.payload);
    delayed_.pop_front();
  }
}

}  // namespace hexplore::transport
