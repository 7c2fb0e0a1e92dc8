#pragma once
// Test helper: runs a helper executable as a child process with its stdout and stderr on one
// pipe, so a test can wait for the lines it prints (events, not sleeps), signal it and reap it.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexplore::testing {

class ChildProcess {
 public:
  explicit ChildProcess(std::vector<std::string> argv) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      dup2(fds[1], STDOUT_FILENO);
      dup2(fds[1], STDERR_FILENO);
      std::vector<char*> args;
      for (auto& a : argv) args.push_back(a.data());
      args.push_back(nullptr);
      execv(args[0], args.data());
      _exit(127);
    }
    close(fds[1]);
    fd_ = fds[0];
  }
  ~ChildProcess() {
    if (pid_ > 0 && !exit_code_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (fd_ >= 0) close(fd_);
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int sig) { kill(pid_, sig); }

  // Waits for a line containing `needle`; returns the line, or nullopt on timeout/EOF.
  std::optional<std::string> wait_for_line(const std::string& needle, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (true) {
      // Look at complete lines buffered so far, from where the last search stopped.
      for (size_t nl; (nl = buffer_.find('\n', scanned_)) != std::string::npos;) {
        std::string line = buffer_.substr(scanned_, nl - scanned_);
        scanned_ = nl + 1;
        if (line.find(needle) != std::string::npos) return line;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      // Even with no time left, take what is already in the pipe before giving up.
      if (!read_some(std::max(left, std::chrono::milliseconds(0)))) return std::nullopt;
    }
  }

  // Everything printed so far (and whatever arrives within `grace`).
  const std::string& output(std::chrono::milliseconds grace = std::chrono::milliseconds(0)) {
    const auto end = std::chrono::steady_clock::now() + grace;
    while (true) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (!read_some(std::max(left, std::chrono::milliseconds(0)))) break;
    }
    return buffer_;
  }

  // Waits for exit; returns the exit code (128 + signal when killed), nullopt on timeout.
  std::optional<int> wait_exit(std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!exit_code_) {
      int status = 0;
      const pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        break;
      }
      if (std::chrono::steady_clock::now() >= end) return std::nullopt;
      read_some(std::chrono::milliseconds(10));
    }
    output(std::chrono::milliseconds(0));
    return exit_code_;
  }

 private:
  // Reads what is available within `timeout`; false on timeout or EOF.
  bool read_some(std::chrono::milliseconds timeout) {
    if (eof_) return false;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return false;
    char chunk[4096];
    const ssize_t n = read(fd_, chunk, sizeof(chunk));
    if (n <= 0) {
      eof_ = true;
      return false;
    }
    buffer_.append(chunk, static_cast<size_t>(n));
    return true;
  }

  pid_t pid_ = -1;
  int fd_ = -1;
  bool eof_ = false;
  std::string buffer_;
  size_t scanned_ = 0;
  std::optional<int> exit_code_;
};

}  // namespace hexplore::testing
