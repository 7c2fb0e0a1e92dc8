#include "common/transport/accounting.h"

#include <array>

#include "common/transport/topics.h"

namespace hexplore::transport {

std::string_view drop_reason_name(DropReason reason) {
  static constexpr std::array<std::string_view, kDropReasonCount> kNames = {
      "malformed",    "wrong_version", "wrong_type",    "oversize",   "fault_injected",    "timeout",
      "send_failed",  "handler_error", "radio_expired", "radio_lost", "radio_out_of_range"};
  return kNames[static_cast<size_t>(reason)];
}

Accounting::Accounting(std::string robot_id, std::string service, const metrics::TransportFamilies* families)
    : robot_id_(std::move(robot_id)), service_(std::move(service)), families_(families) {}

Accounting::Line& Accounting::line(Lines& lines, metrics::CounterFamily* messages, metrics::CounterFamily* bytes,
                                   std::string_view topic, std::string_view peer) {
  // Maps hold only label values, so a raw topic or peer that is found is already a valid label;
  // the label functions run only on a miss (first message of a topic, or an invalid one).
  auto by_topic = lines.find(topic);
  if (by_topic == lines.end()) {
    topic = topics::topic_label(topic);
    by_topic = lines.find(topic);
    if (by_topic == lines.end()) by_topic = lines.emplace(std::string(topic), PeerLines{}).first;
  }
  topic = by_topic->first;
  auto by_peer = by_topic->second.find(peer);
  if (by_peer == by_topic->second.end()) {
    peer = topics::peer_label(peer);
    by_peer = by_topic->second.find(peer);
  }
  if (by_peer == by_topic->second.end()) {
    Line fresh;
    if (families_ != nullptr) {
      const metrics::Labels labels = {
          {"robot", robot_id_}, {"service", service_}, {"topic", std::string(topic)}, {"peer", std::string(peer)}};
      fresh.messages = messages->add(labels);
      fresh.bytes = bytes->add(labels);
    }
    by_peer = by_topic->second.emplace(std::string(peer), fresh).first;
  }
  return by_peer->second;
}

void Accounting::record_sent(std::string_view topic, std::string_view peer, size_t bytes) {
  std::lock_guard lock(mutex_);
  Line& l = line(sent_, families_ ? families_->sent_messages : nullptr, families_ ? families_->sent_bytes : nullptr,
                 topic, peer);
  ++l.totals.messages;
  l.totals.bytes += bytes;
  if (l.messages != nullptr) {
    l.messages->increment();
    l.bytes->increment(static_cast<double>(bytes));
  }
}

void Accounting::record_received(std::string_view topic, std::string_view peer, size_t bytes, int64_t latency_ns) {
  std::lock_guard lock(mutex_);
  Line& l = line(received_, families_ ? families_->received_messages : nullptr,
                 families_ ? families_->received_bytes : nullptr, topic, peer);
  ++l.totals.messages;
  l.totals.bytes += bytes;
  if (l.messages != nullptr) {
    l.messages->increment();
    l.bytes->increment(static_cast<double>(bytes));
  }
  if (latency_ns < 0) return;  // no send time to measure against (radio messages)
  auto it = latency_.find(topic);
  const std::string_view label = it == latency_.end() ? topics::topic_label(topic) : topic;
  if (it == latency_.end()) it = latency_.find(label);
  if (it == latency_.end()) {
    TopicLine fresh;
    if (families_ != nullptr)
      fresh.latency = families_->latency->add({{"robot", robot_id_}, {"service", service_}, {"topic", std::string(label)}});
    it = latency_.emplace(std::string(label), fresh).first;
  }
  ++it->second.latency_samples;
  if (it->second.latency != nullptr) it->second.latency->observe(static_cast<double>(latency_ns) * 1e-9);
}

void Accounting::record_dropped(std::string_view topic, DropReason reason) {
  std::lock_guard lock(mutex_);
  ++dropped_[static_cast<size_t>(reason)];
  if (families_ == nullptr) return;
  const std::string_view label = topics::topic_label(topic);
  std::string key(label);
  key.append("\n").append(drop_reason_name(reason));
  auto it = dropped_children_.find(key);
  if (it == dropped_children_.end()) {
    metrics::Counter* child = families_->dropped->add({{"robot", robot_id_},
                                                       {"service", service_},
                                                       {"topic", std::string(label)},
                                                       {"reason", std::string(drop_reason_name(reason))}});
    it = dropped_children_.emplace(std::move(key), child).first;
  }
  it->second->increment();
}

Accounting::Totals Accounting::sum(const Lines& lines, std::string_view topic) {
  Totals total;
  auto add_all = [&total](const PeerLines& peers) {
    for (const auto& [peer, l] : peers) {
      total.messages += l.totals.messages;
      total.bytes += l.totals.bytes;
    }
  };
  if (topic.empty()) {
    for (const auto& [t, peers] : lines) add_all(peers);
  } else if (auto it = lines.find(topic); it != lines.end()) {
    add_all(it->second);
  }
  return total;
}

Accounting::Totals Accounting::sent(std::string_view topic) const {
  std::lock_guard lock(mutex_);
  return topic.empty() ? Totals{} : sum(sent_, topic);
}
Accounting::Totals Accounting::received(std::string_view topic) const {
  std::lock_guard lock(mutex_);
  return topic.empty() ? Totals{} : sum(received_, topic);
}
Accounting::Totals Accounting::sent_all() const {
  std::lock_guard lock(mutex_);
  return sum(sent_, "");
}
Accounting::Totals Accounting::received_all() const {
  std::lock_guard lock(mutex_);
  return sum(received_, "");
}
uint64_t Accounting::dropped(DropReason reason) const {
  std::lock_guard lock(mutex_);
  return dropped_[static_cast<size_t>(reason)];
}
uint64_t Accounting::latency_samples(std::string_view topic) const {
  std::lock_guard lock(mutex_);
  auto it = latency_.find(topic);
  return it == latency_.end() ? 0 : it->second.latency_samples;
}

}  // namespace hexplore::transport
