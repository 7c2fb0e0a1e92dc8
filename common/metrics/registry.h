#pragma once
// Metrics facade: counter, gauge and histogram families with labels. Code records through
// these interfaces; the backend is chosen once per process (Prometheus for services, the
// do-nothing registry for unit tests), as in cartographer's metrics::FamilyFactory.

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hexplore::metrics {

// Label name -> value. Keep values bounded (robot ids, topics, reasons), never per-message.
using Labels = std::map<std::string, std::string>;

// A monotonically increasing value. Thread-safe.
class Counter {
 public:
  virtual ~Counter() = default;
  virtual void increment(double by = 1.0) = 0;
  virtual double value() const = 0;
};

// A value that goes up and down. Thread-safe.
class Gauge {
 public:
  virtual ~Gauge() = default;
  virtual void set(double value) = 0;
  virtual void add(double by) = 0;
  virtual double value() const = 0;
};

// Observations sorted into fixed buckets (upper bounds, ascending). Thread-safe.
class Histogram {
 public:
  virtual ~Histogram() = default;
  virtual void observe(double value) = 0;
  // Number of observations so far (for tests and self-checks).
  virtual uint64_t count() const = 0;
};

// A family hands out one child per label set; the returned pointer stays valid as long as the
// registry lives, so callers cache it instead of looking it up per event.
template <typename Metric>
class Family {
 public:
  virtual ~Family() = default;
  virtual Metric* add(const Labels& labels) = 0;
};

using CounterFamily = Family<Counter>;
using GaugeFamily = Family<Gauge>;
using HistogramFamily = Family<Histogram>;

// Creates (or returns the existing) family by name. Names follow hexplore_<subsystem>_<what>_<unit>.
class Registry {
 public:
  virtual ~Registry() = default;
  virtual CounterFamily* counter_family(const std::string& name, const std::string& help) = 0;
  virtual GaugeFamily* gauge_family(const std::string& name, const std::string& help) = 0;
  virtual HistogramFamily* histogram_family(const std::string& name, const std::string& help,
                                            const std::vector<double>& bucket_bounds) = 0;
};

// A registry whose metrics only keep their values in memory (tests, metrics off).
std::unique_ptr<Registry> make_null_registry();

// Latency buckets in seconds from 50 us to 10 s, roughly x2.5 apart.
std::vector<double> latency_buckets_s();

}  // namespace hexplore::metrics
