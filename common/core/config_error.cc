#include "common/core/config_error.h"

namespace hexplore::core {
namespace {

std::string format(const std::string& file, const std::string& key, const std::string& problem, int line) {
  std::string where = file.empty() ? std::string("<config>") : file;
  if (line > 0) where += ":" + std::to_string(line);
  return where + ": " + (key.empty() ? std::string() : "'" + key + "': ") + problem;
}

}  // namespace

ConfigError::ConfigError(std::string file, std::string key, std::string problem, int line)
    : std::runtime_error(format(file, key, problem, line)),
      file_(std::move(file)),
      key_(std::move(key)),
      problem_(std::move(problem)),
      line_(line) {}

}  // namespace hexplore::core
