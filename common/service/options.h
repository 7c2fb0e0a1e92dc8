#pragma once
// A service's own command-line options: the `--key value` pairs the host passes on
// (ServiceContext::arguments()), read by one set of rules so that every service accepts and
// rejects alike. A number must parse whole, be finite and lie in its range; a flag is true or
// false (also 1/0, yes/no); a choice is one of its words. A bad value throws OptionError, a
// core::ConfigError naming the flag, so the process says which flag is wrong and why and
// exits with 2 (service_main.cc) instead of running on a value nobody meant.

#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>

#include "common/core/config_error.h"

namespace hexplore::service {

class OptionError : public core::ConfigError {
 public:
  // `key` without the dashes; `problem` says what was expected and what came.
  OptionError(const std::string& key, const std::string& problem);
};

class Options {
 public:
  using Arguments = std::map<std::string, std::string>;
  explicit Options(const Arguments& args) : args_(args) {}

  // Every read names a key of the option catalogue (option_catalogue.h); any other key throws
  // std::logic_error, a bug in the service that a test of it shows at once.
  bool has(const std::string& key) const { return find(key) != args_.end(); }
  // --key as a number in [min, max], or `fallback` when absent.
  double number(const std::string& key, double fallback, double min = -std::numeric_limits<double>::max(),
                double max = std::numeric_limits<double>::max()) const;
  // --key as a number > 0, or `fallback` when absent.
  double positive(const std::string& key, double fallback) const;
  // --key as a whole number in [min, max], or `fallback` when absent.
  int integer(const std::string& key, int fallback, int min, int max = std::numeric_limits<int>::max()) const;
  // --key as true/false (1/0, yes/no), or `fallback` when absent.
  bool flag(const std::string& key, bool fallback) const;
  // --key as given, or `fallback` when absent.
  std::string text(const std::string& key, const std::string& fallback = "") const;
  // --key as one of `words`, or `fallback` when absent.
  std::string choice(const std::string& key, const std::string& fallback, std::initializer_list<const char*> words) const;

 private:
  Arguments::const_iterator find(const std::string& key) const;

  const Arguments& args_;
};

// `file_name` in the --trace-dir folder (made if missing), opened for writing; a closed stream
// when --trace-dir is absent. A folder or file that cannot be written throws OptionError.
std::ofstream open_trace_file(const Options& options, const std::string& file_name);

}  // namespace hexplore::service
