#pragma once
// The Prometheus backend of the metrics facade, plus the HTTP exposer serving /metrics.
// prometheus-cpp stays inside prometheus_registry.cc; nothing else includes it.

#include <memory>
#include <string>

#include "common/metrics/registry.h"

namespace hexplore::metrics {

class PrometheusRegistry : public Registry {
 public:
  PrometheusRegistry();
  ~PrometheusRegistry() override;

  CounterFamily* counter_family(const std::string& name, const std::string& help) override;
  GaugeFamily* gauge_family(const std::string& name, const std::string& help) override;
  HistogramFamily* histogram_family(const std::string& name, const std::string& help,
                                    const std::vector<double>& bucket_bounds) override;

  // Starts serving http://<bind_address>:<port>/metrics (civetweb; stopping it on destruction
  // takes up to 2 s, its poll quantum). port 0 asks the OS for a free port;
  // returns the port actually bound. Throws std::runtime_error naming the address on failure.
  // At most one exposer per registry.
  int expose(int port, const std::string& bind_address = "0.0.0.0");
  // Port being served, 0 when not exposing.
  int exposed_port() const;

  // The text exposition format of everything registered (what /metrics returns).
  std::string serialize() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hexplore::metrics
