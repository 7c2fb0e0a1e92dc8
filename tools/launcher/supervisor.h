#pragma once
// Runs a set of child processes and watches them: their output lines are prefixed with the
// process name (or go to one log file each), a stop signal is forwarded to all of them with a
// grace period before SIGKILL, and a process that ends on its own is reported by name with its
// exit status or signal. The station's exit ends the whole launch (the mission is over), and so
// does the composed team process of fast mode when there is no station.

#include <sys/types.h>

#include <string>
#include <vector>

#include "tools/launcher/launch_plan.h"

namespace hexplore::launcher {

struct SupervisorOptions {
  std::string log_dir;          // "" = prefix child lines onto this process's stdout/stderr
  bool exit_on_failure = false; // stop everything when any process ends unexpectedly
  double grace_s = 5.0;         // SIGTERM -> SIGKILL delay at shutdown
};

// "exited with status 3", "killed by signal 11 (Segmentation fault)".
std::string describe_wait_status(int status);

class Supervisor {
 public:
  // Blocks SIGINT, SIGTERM, SIGHUP and SIGCHLD in the calling thread (they are read through a
  // signalfd); call before any other thread exists.
  explicit Supervisor(SupervisorOptions options);
  ~Supervisor();
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  // Starts every process (in its own process group, so a terminal's Ctrl-C reaches only the
  // launcher, which then stops the children in order). Throws std::runtime_error naming the
  // process and the cause when one cannot be started; those already started keep running
  // until run() or the destructor stops them.
  void start(const std::vector<ProcessSpec>& processes);

  // Watches until a launch-ending process (station) exits, a stop signal arrives, every process
  // has ended, or (with exit_on_failure) one fails; then stops the rest. Returns the launcher's
  // exit code: that process's when it ended the launch, else 0 when nothing failed, 1 otherwise.
  int run();

 private:
  struct Child;
  struct Stream;
  void log(const std::string& line);
  void handle_signal_fd();
  void reap();
  void on_child_exit(Child& child, int status);
  void begin_shutdown(const std::string& why);
  // SIGKILL to every process still running; `why` completes the log line.
  void kill_remaining(const std::string& why);
  void read_stream(Stream& stream, bool final);
  size_t living() const;

  SupervisorOptions options_;
  int signal_fd_ = -1;
  std::vector<Child*> children_;
  std::vector<Stream*> streams_;
  bool shutting_down_ = false;
  bool killed_ = false;
  double shutdown_started_s_ = 0.0;
  double kill_deadline_s_ = 0.0;
  bool station_ended_ = false;  // a process that ends the launch (station, fast-mode team) ended
  int station_code_ = 0;
  int failures_ = 0;
};

}  // namespace hexplore::launcher
