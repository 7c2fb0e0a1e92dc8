#pragma once
// The one exception type for bad configuration: it names the file, the key and the problem,
// so a user can fix the file without reading code.

#include <stdexcept>
#include <string>

namespace hexplore::core {

class ConfigError : public std::runtime_error {
 public:
  // `line` is 1-based; 0 when unknown.
  ConfigError(std::string file, std::string key, std::string problem, int line = 0);

  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& problem() const { return problem_; }
  int line() const { return line_; }

 private:
  std::string file_;
  std::string key_;
  std::string problem_;
  int line_;
};

}  // namespace hexplore::core
