#pragma once
// Named numbers in a service's status (Service::fill_status): what the station, the launcher
// and the tests read besides the state. One way to add them, so every service's read alike.

#include <string>

#include "hexplore/v1/status.pb.h"

namespace hexplore::service {

class StatusValues {
 public:
  explicit StatusValues(v1::ServiceStatus& status) : status_(status) {}
  // Adds `name` = `value`.
  void operator()(const std::string& name, double value) const {
    v1::StatusValue* v = status_.add_values();
    v->set_name(name);
    v->set_value(value);
  }

 private:
  v1::ServiceStatus& status_;
};

}  // namespace hexplore::service
