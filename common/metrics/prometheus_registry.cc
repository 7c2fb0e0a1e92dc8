// prometheus-cpp backend: every facade family wraps a prometheus::Family registered in one
// prometheus::Registry, which the civetweb-based Exposer serves on /metrics.
#include "common/metrics/prometheus_registry.h"

#include <atomic>
#include <mutex>
#include <stdexcept>

#include <prometheus/counter.h>
#include <prometheus/exposer.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>
#include <prometheus/text_serializer.h>

namespace hexplore::metrics {
namespace {

class PromCounter : public Counter {
 public:
  explicit PromCounter(prometheus::Counter& c) : c_(c) {}
  void increment(double by) override { c_.Increment(by); }
  double value() const override { return c_.Value(); }

 private:
  prometheus::Counter& c_;
};

class PromGauge : public Gauge {
 public:
  explicit PromGauge(prometheus::Gauge& g) : g_(g) {}
  void set(double value) override { g_.Set(value); }
  void add(double by) override { g_.Increment(by); }
  double value() const override { return g_.Value(); }

 private:
  prometheus::Gauge& g_;
};

class PromHistogram : public Histogram {
 public:
  explicit PromHistogram(prometheus::Histogram& h) : h_(h) {}
  void observe(double value) override {
    h_.Observe(value);
    count_.fetch_add(1, std::memory_order_relaxed);
  }
  uint64_t count() const override { return count_.load(std::memory_order_relaxed); }

 private:
  prometheus::Histogram& h_;
  std::atomic<uint64_t> count_{0};
};

// Children are created once per label set and cached, so add() is cheap after the first call.
template <typename Metric, typename Wrapper, typename PromMetric, typename MakeChild>
class PromFamily : public Family<Metric> {
 public:
  PromFamily(prometheus::Family<PromMetric>& family, MakeChild make) : family_(family), make_(std::move(make)) {}
  Metric* add(const Labels& labels) override {
    std::lock_guard lock(mutex_);
    auto& slot = children_[labels];
    if (!slot) slot = std::make_unique<Wrapper>(make_(family_, prometheus::Labels(labels.begin(), labels.end())));
    return slot.get();
  }

 private:
  prometheus::Family<PromMetric>& family_;
  MakeChild make_;
  std::mutex mutex_;
  std::map<Labels, std::unique_ptr<Wrapper>> children_;
};

}  // namespace

struct PrometheusRegistry::Impl {
  std::shared_ptr<prometheus::Registry> registry = std::make_shared<prometheus::Registry>();
  std::unique_ptr<prometheus::Exposer> exposer;
  int port = 0;
  std::mutex mutex;
  std::map<std::string, std::unique_ptr<CounterFamily>> counters;
  std::map<std::string, std::unique_ptr<GaugeFamily>> gauges;
  std::map<std::string, std::unique_ptr<HistogramFamily>> histograms;
};

PrometheusRegistry::PrometheusRegistry() : impl_(std::make_unique<Impl>()) {}
PrometheusRegistry::~PrometheusRegistry() = default;

CounterFamily* PrometheusRegistry::counter_family(const std::string& name, const std::string& help) {
  std::lock_guard lock(impl_->mutex);
  auto& slot = impl_->counters[name];
  if (!slot) {
    auto& family = prometheus::BuildCounter().Name(name).Help(help).Register(*impl_->registry);
    auto make = [](prometheus::Family<prometheus::Counter>& f, const prometheus::Labels& l) -> prometheus::Counter& {
      return f.Add(l);
    };
    slot = std::make_unique<PromFamily<Counter, PromCounter, prometheus::Counter, decltype(make)>>(family, make);
  }
  return slot.get();
}

GaugeFamily* PrometheusRegistry::gauge_family(const std::string& name, const std::string& help) {
  std::lock_guard lock(impl_->mutex);
  auto& slot = impl_->gauges[name];
  if (!slot) {
    auto& family = prometheus::BuildGauge().Name(name).Help(help).Register(*impl_->registry);
    auto make = [](prometheus::Family<prometheus::Gauge>& f, const prometheus::Labels& l) -> prometheus::Gauge& {
      return f.Add(l);
    };
    slot = std::make_unique<PromFamily<Gauge, PromGauge, prometheus::Gauge, decltype(make)>>(family, make);
  }
  return slot.get();
}

HistogramFamily* PrometheusRegistry::histogram_family(const std::string& name, const std::string& help,
                                                      const std::vector<double>& bucket_bounds) {
  std::lock_guard lock(impl_->mutex);
  auto& slot = impl_->histograms[name];
  if (!slot) {
    auto& family = prometheus::BuildHistogram().Name(name).Help(help).Register(*impl_->registry);
    auto make = [bucket_bounds](prometheus::Family<prometheus::Histogram>& f,
                                const prometheus::Labels& l) -> prometheus::Histogram& {
      return f.Add(l, prometheus::Histogram::BucketBoundaries(bucket_bounds));
    };
    slot = std::make_unique<PromFamily<Histogram, PromHistogram, prometheus::Histogram, decltype(make)>>(family, make);
  }
  return slot.get();
}

int PrometheusRegistry::expose(int port, const std::string& bind_address) {
  std::lock_guard lock(impl_->mutex);
  if (impl_->exposer) throw std::runtime_error("metrics: exposer already running on port " + std::to_string(impl_->port));
  const std::string address = bind_address + ":" + std::to_string(port);
  try {
    impl_->exposer = std::make_unique<prometheus::Exposer>(address, 1);
  } catch (const std::exception& e) {
    throw std::runtime_error("metrics: cannot serve /metrics on " + address + ": " + e.what());
  }
  impl_->exposer->RegisterCollectable(impl_->registry);
  const auto ports = impl_->exposer->GetListeningPorts();
  impl_->port = ports.empty() ? port : ports.front();
  return impl_->port;
}

int PrometheusRegistry::exposed_port() const { return impl_->port; }

std::string PrometheusRegistry::serialize() const {
  return prometheus::TextSerializer().Serialize(impl_->registry->Collect());
}

}  // namespace hexplore::metrics
