#include "common/service/options.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "common/service/option_catalogue.h"

namespace hexplore::service {
namespace {

std::string quoted(const std::string& value) { return "'" + value + "'"; }

std::string bound(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

OptionError::OptionError(const std::string& key, const std::string& problem)
    : core::ConfigError("command line", "--" + key, problem) {}

Options::Arguments::const_iterator Options::find(const std::string& key) const {
  if (!is_service_option(key))
    throw std::logic_error("a service reads --" + key + ", which is not in common/service/option_catalogue.cc");
  return args_.find(key);
}

double Options::number(const std::string& key, double fallback, double min, double max) const {
  const auto it = find(key);
  if (it == args_.end()) return fallback;
  double v = 0.0;
  size_t used = 0;
  try {
    v = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != it->second.size() || !std::isfinite(v))
    throw OptionError(key, "expects a number, got " + quoted(it->second));
  if (v < min || v > max) {
    const std::string range = max == std::numeric_limits<double>::max() ? ">= " + bound(min)
                              : min == -std::numeric_limits<double>::max()
                                  ? "<= " + bound(max)
                                  : "in [" + bound(min) + ", " + bound(max) + "]";
    throw OptionError(key, "expects a number " + range + ", got " + quoted(it->second));
  }
  return v;
}

double Options::positive(const std::string& key, double fallback) const {
  if (!has(key)) return fallback;
  const double v = number(key, fallback);
  if (!(v > 0.0)) throw OptionError(key, "expects a positive number, got " + quoted(text(key)));
  return v;
}

int Options::integer(const std::string& key, int fallback, int min, int max) const {
  if (!has(key)) return fallback;
  const double v = number(key, fallback, min, max);
  if (v != std::floor(v)) throw OptionError(key, "expects a whole number, got " + quoted(text(key)));
  return static_cast<int>(v);
}

bool Options::flag(const std::string& key, bool fallback) const {
  const auto it = find(key);
  if (it == args_.end()) return fallback;
  const std::string& s = it->second;
  if (s == "true" || s == "1" || s == "yes") return true;
  if (s == "false" || s == "0" || s == "no") return false;
  throw OptionError(key, "expects true or false, got " + quoted(s));
}

std::string Options::text(const std::string& key, const std::string& fallback) const {
  const auto it = find(key);
  return it == args_.end() ? fallback : it->second;
}

std::string Options::choice(const std::string& key, const std::string& fallback,
                            std::initializer_list<const char*> words) const {
  const auto it = find(key);
  if (it == args_.end()) return fallback;
  std::string listed;
  for (const char* w : words) {
    if (it->second == w) return it->second;
    listed += (listed.empty() ? "" : ", ") + std::string(w);
  }
  throw OptionError(key, "expects one of " + listed + ", got " + quoted(it->second));
}

std::ofstream open_trace_file(const Options& options, const std::string& file_name) {
  std::ofstream out;
  const std::string dir = options.text("trace-dir");
  if (dir.empty()) return out;
  std::error_code ignored;  // a failure shows as the open below failing
  std::filesystem::create_directories(dir, ignored);
  const std::string path = dir + "/" + file_name;
  out.open(path);
  if (!out) throw OptionError("trace-dir", "cannot write " + path);
  return out;
}

}  // namespace hexplore::service
