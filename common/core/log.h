#pragma once
// Minimal thread-safe logging to stderr: "<time> <level> <component>: message".
// log_once() reports a recurring problem (a malformed frame kind, say) a single time per key.

#include <sstream>
#include <string>
#include <string_view>

namespace hexplore::core {

enum class LogLevel { kDebug = 0, kInfo = 1, kWarn = 2, kError = 3 };

void set_log_level(LogLevel level);
LogLevel log_level();
// Parses "debug" | "info" | "warn" | "error"; returns false for anything else.
bool parse_log_level(std::string_view text, LogLevel& out);

void log(LogLevel level, std::string_view component, std::string_view message);
// Logs only the first time `key` is seen in this process; returns whether it logged.
bool log_once(LogLevel level, std::string_view component, const std::string& key, std::string_view message);

// Stream-style helper: LogLine(LogLevel::kInfo, "hlmap") << "fused " << n << " supervoxels";
class LogLine {
 public:
  LogLine(LogLevel level, std::string_view component) : level_(level), component_(component) {}
  ~LogLine() { log(level_, component_, stream_.str()); }
  template <typename T>
  LogLine& operator<<(const T& value) {
    stream_ << value;
    return *this;
  }

 private:
  LogLevel level_;
  std::string component_;
  std::ostringstream stream_;
};

}  // namespace hexplore::core
