#include "common/transport/publisher.h"

#include <algorithm>

#include "common/core/clock.h"
#include "common/core/endpoints.h"
#include "common/core/log.h"
#include "common/transport/payload_samples.h"
#include "common/transport/payload_wire.h"
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
  detail::guard_server(context, socket_, options_);
  bind(bind_endpoint);
  header_ = make_header(identity_, 0, "", 0);
  // The station is the experiment's recorder, not a robot on the radio.
  if (options_.radio && identity_.robot_id != core::kStationId) {
    radio_slot_ = options_.radio->roster().slot(identity_.robot_id);
    if (!radio_slot_)
      throw std::invalid_argument("transport: publisher '" + identity_.robot_id + "' is not on the radio's roster");
  }
}

Publisher::~Publisher() {
  flush_delayed();
  socket_.close();
}

void Publisher::bind(const std::string& endpoint) { endpoints_.push_back(detail::bind(socket_, endpoint, options_)); }

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
  const bool team = topics::is_team_topic(topic);
  const uint16_t type = type_id(payload_type);
  if (header_.payload_type() != payload_type) {
    header_.set_payload_type(std::string(payload_type));
    remember_type_name(payload_type);
  }
  uint8_t payload_flags = 0;
  zmq::message_t payload;
  if (team) {
    payload_flags = encode_payload(message, type, team, options_, payload_buffer_);
    sample_team_payload(message, type, payload_type, options_);
    payload = zmq::message_t(payload_buffer_.data(), payload_buffer_.size());
  } else {
    // Robot-local payloads (scans are hundreds of kilobytes) go straight into the frame.
    payload = zmq::message_t(payload_size);
    if (payload_size > 0) message.SerializeWithCachedSizesToArray(static_cast<uint8_t*>(payload.data()));
  }
  header_.set_sequence(sequence);
  // The radio carries sim time only; the wall time feeds robot-local latency histograms.
  header_.set_send_time_ns(team ? 0 : core::wall_time_ns());
  header_.set_sim_time_ns(sim_time_ns);
  header_buffer_.clear();
  // Roster slots on the radio only: everything else stays readable by any tool or test.
  encode_header(header_, team ? options_.roster.get() : nullptr, payload_flags, !team, header_buffer_);
  zmq::message_t header(header_buffer_.data(), header_buffer_.size());
  const bool on_radio = team && radio_slot_;
  const bool delayed = faulty && options_.faults.delay.count() > 0;
  if (!on_radio && !delayed) return send_frames(topic, header, payload);
  Delayed d{now_ns() + (delayed ? options_.faults.delay.count() : 0), std::string(topic), std::move(header),
            std::move(payload)};
  if (on_radio) submit_to_radio(std::move(d));
  else delay(std::move(d));
  return true;
}

void Publisher::delay(Delayed d) {
  // Due times from the radio and from fault injection interleave: keep the queue sorted.
  auto at = std::upper_bound(delayed_.begin(), delayed_.end(), d.due_ns,
                             [](int64_t due, const Delayed& x) { return due < x.due_ns; });
  delayed_.insert(at, std::move(d));
}

void Publisher::submit_to_radio(Delayed d) {
  RadioMedium::Submission s;
  s.sender_slot = *radio_slot_;
  s.service = static_cast<uint32_t>(core::service_from_name(identity_.service).value_or(core::ServiceKind::kStation));
  s.order = ++radio_order_;
  s.submit_ns = d.due_ns;
  s.bytes = topics::wire_topic(d.topic).size() + d.header.size() + d.payload.size();
  auto shared = std::make_shared<Delayed>(std::move(d));
  s.schedule = [this, shared](int64_t due_ns) {
    shared->due_ns = due_ns;
    delay(std::move(*shared));
  };
  s.expire = [this, shared] {
    if (accounting_) accounting_->record_dropped(shared->topic, DropReason::kRadioExpired);
  };
  options_.radio->submit(std::move(s));
}

bool Publisher::send_frames(std::string_view topic, zmq::message_t& header, zmq::message_t& payload) {
  const std::string_view wire = topics::wire_topic(topic);
  const size_t bytes = wire.size() + header.size() + payload.size();
  try {
    // PUB never blocks: at the high-water mark ZeroMQ drops silently, so these only fail on
    // a closed socket or context.
    socket_.send(zmq::const_buffer(wire.data(), wire.size()), zmq::send_flags::sndmore | zmq::send_flags::dontwait);
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
  // delay() keeps the queue in due order.
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
