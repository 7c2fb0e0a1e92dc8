// The do-nothing backend: metrics keep their values in memory only, so code under test can
// still read them back.
#include <atomic>
#include <mutex>

#include "common/metrics/registry.h"

namespace hexplore::metrics {
namespace {

class MemoryCounter : public Counter {
 public:
  void increment(double by) override {
    double old = value_.load(std::memory_order_relaxed);
    while (!value_.compare_exchange_weak(old, old + by, std::memory_order_relaxed)) {
    }
  }
  double value() const override { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<double> value_{0.0};
};

class MemoryGauge : public Gauge {
 public:
  void set(double value) override { value_.store(value, std::memory_order_relaxed); }
  void add(double by) override {
    double old = value_.load(std::memory_order_relaxed);
    while (!value_.compare_exchange_weak(old, old + by, std::memory_order_relaxed)) {
    }
  }
  double value() const override { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<double> value_{0.0};
};

class MemoryHistogram : public Histogram {
 public:
  void observe(double) override { count_.fetch_add(1, std::memory_order_relaxed); }
  uint64_t count() const override { return count_.load(std::memory_order_relaxed); }

 private:
  std::atomic<uint64_t> count_{0};
};

template <typename Metric, typename Impl>
class MemoryFamily : public Family<Metric> {
 public:
  Metric* add(const Labels& labels) override {
    std::lock_guard lock(mutex_);
    auto& slot = children_[labels];
    if (!slot) slot = std::make_unique<Impl>();
    return slot.get();
  }

 private:
  std::mutex mutex_;
  std::map<Labels, std::unique_ptr<Impl>> children_;
};

class NullRegistry : public Registry {
 public:
  CounterFamily* counter_family(const std::string& name, const std::string&) override {
    return get(counters_, name);
  }
  GaugeFamily* gauge_family(const std::string& name, const std::string&) override { return get(gauges_, name); }
  HistogramFamily* histogram_family(const std::string& name, const std::string&,
                                    const std::vector<double>&) override {
    return get(histograms_, name);
  }

 private:
  template <typename F>
  F* get(std::map<std::string, std::unique_ptr<F>>& families, const std::string& name) {
    std::lock_guard lock(mutex_);
    auto& slot = families[name];
    if (!slot) slot = std::make_unique<F>();
    return slot.get();
  }

  std::mutex mutex_;
  std::map<std::string, std::unique_ptr<MemoryFamily<Counter, MemoryCounter>>> counters_;
  std::map<std::string, std::unique_ptr<MemoryFamily<Gauge, MemoryGauge>>> gauges_;
  std::map<std::string, std::unique_ptr<MemoryFamily<Histogram, MemoryHistogram>>> histograms_;
};

}  // namespace

std::unique_ptr<Registry> make_null_registry() { return std::make_unique<NullRegistry>(); }

std::vector<double> latency_buckets_s() {
  return {50e-6, 100e-6, 250e-6, 500e-6, 1e-3, 2.5e-3, 5e-3, 10e-3, 25e-3, 50e-3, 100e-3, 250e-3, 500e-3, 1.0, 2.5, 10.0};
}

}  // namespace hexplore::metrics
