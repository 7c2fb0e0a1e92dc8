#pragma once
// A ServiceStatus with the given name/value pairs, as a service reports them (tests of what the
// station records from statuses).

#include <initializer_list>
#include <string>
#include <utility>

#include "hexplore/v1/status.pb.h"

namespace hexplore::evaluation::testing {

inline v1::ServiceStatus status(std::initializer_list<std::pair<std::string, double>> values) {
  v1::ServiceStatus s;
  for (const auto& [name, value] : values) {
    auto* v = s.add_values();
    v->set_name(name);
    v->set_value(value);
  }
  return s;
}

}  // namespace hexplore::evaluation::testing
