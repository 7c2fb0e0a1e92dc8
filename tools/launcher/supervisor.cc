#include "tools/launcher/supervisor.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string_view>

namespace hexplore::launcher {
namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

sigset_t handled_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  sigaddset(&set, SIGCHLD);
  return set;
}

void write_all(int fd, const std::string& text) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return;
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
}

}  // namespace

std::string describe_wait_status(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    std::string text = "killed by signal " + std::to_string(sig);
    if (const char* name = ::strsignal(sig)) text += std::string(" (") + name + ")";
    if (WCOREDUMP(status)) text += ", core dumped";
    return text;
  }
  return "ended with wait status " + std::to_string(status);
}

struct Supervisor::Child {
  ProcessSpec spec;
  pid_t pid = -1;
  bool running = false;
  bool expected_exit = false;  // stopped by us
  int status = 0;
};

// One output pipe of a child; lines are assembled here and written with the child's prefix.
struct Supervisor::Stream {
  Child* child;
  int fd;
  int out_fd;  // 1 or 2
  std::string pending;
  bool open = true;  // false after end of file (the fd is closed then)
};

Supervisor::Supervisor(SupervisorOptions options) : options_(std::move(options)) {
  sigset_t set = handled_signals();
  if (::sigprocmask(SIG_BLOCK, &set, nullptr) != 0) throw std::runtime_error(std::string("sigprocmask: ") + std::strerror(errno));
  signal_fd_ = ::signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK);
  if (signal_fd_ < 0) throw std::runtime_error(std::string("signalfd: ") + std::strerror(errno));
  if (!options_.log_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options_.log_dir, ec);
    if (ec) throw std::runtime_error("cannot create log folder " + options_.log_dir + ": " + ec.message());
  }
}

Supervisor::~Supervisor() {
  // A launch that failed half-way must not leave processes behind.
  for (Child* c : children_) {
    if (c->running) {
      ::kill(-c->pid, SIGKILL);
      ::waitpid(c->pid, nullptr, 0);
    }
  }
  for (Stream* s : streams_) {
    if (s->open) ::close(s->fd);
    delete s;
  }
  for (Child* c : children_) delete c;
  if (signal_fd_ >= 0) ::close(signal_fd_);
}

void Supervisor::log(const std::string& line) { write_all(1, "[launch] " + line + "\n"); }

void Supervisor::start(const std::vector<ProcessSpec>& processes) {
  for (const ProcessSpec& spec : processes) {
    int out[2] = {-1, -1};
    int err[2] = {-1, -1};
    int exec_report[2] = {-1, -1};  // closes on a successful exec; carries errno otherwise
    int log_fd = -1;
    // The station's output is the mission's progress display: it always goes to the terminal.
    if (options_.log_dir.empty() || spec.is_station) {
      if (::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0)
        throw std::runtime_error("cannot start " + spec.name + ": pipe: " + std::strerror(errno));
    } else {
      std::string file = spec.name;
      for (char& ch : file) {
        if (ch == '/') ch = '-';
      }
      const std::string path = (std::filesystem::path(options_.log_dir) / (file + ".log")).string();
      log_fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
      if (log_fd < 0) throw std::runtime_error("cannot start " + spec.name + ": open " + path + ": " + std::strerror(errno));
    }
    if (::pipe2(exec_report, O_CLOEXEC) != 0)
      throw std::runtime_error("cannot start " + spec.name + ": pipe: " + std::strerror(errno));

    std::vector<std::string> args{spec.executable};
    args.insert(args.end(), spec.arguments.begin(), spec.arguments.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot start " + spec.name + ": fork: " + std::strerror(errno));
    if (pid == 0) {
      // Child: own process group, default signal handling, output to the pipes or the log file.
      ::setpgid(0, 0);
      sigset_t none;
      sigemptyset(&none);
      ::sigprocmask(SIG_SETMASK, &none, nullptr);
      ::dup2(log_fd >= 0 ? log_fd : out[1], 1);
      ::dup2(log_fd >= 0 ? log_fd : err[1], 2);
      ::execv(argv[0], argv.data());
      const int e = errno;
      (void)!::write(exec_report[1], &e, sizeof e);
      ::_exit(127);
    }
    ::setpgid(pid, pid);  // also from the parent, so kill(-pid) works even before the child runs
    ::close(exec_report[1]);
    int exec_errno = 0;
    ssize_t n;
    do {
      n = ::read(exec_report[0], &exec_errno, sizeof exec_errno);
    } while (n < 0 && errno == EINTR);
    ::close(exec_report[0]);

    auto* child = new Child{spec, pid, true, false, 0};
    children_.push_back(child);
    if (log_fd >= 0) {
      ::close(log_fd);
    } else {
      ::close(out[1]);
      ::close(err[1]);
      for (auto [fd, target] : {std::pair{out[0], 1}, std::pair{err[0], 2}}) {
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
        streams_.push_back(new Stream{child, fd, target, {}});
      }
    }
    if (n == static_cast<ssize_t>(sizeof exec_errno)) {
      ::waitpid(pid, nullptr, 0);
      child->running = false;
      throw std::runtime_error("cannot start " + spec.name + ": exec " + spec.executable + ": " + std::strerror(exec_errno));
    }
    log("started " + spec.name + " (pid " + std::to_string(pid) + "): " + spec.executable);
  }
}

size_t Supervisor::living() const {
  size_t n = 0;
  for (const Child* c : children_) n += c->running ? 1 : 0;
  return n;
}

void Supervisor::read_stream(Stream& s, bool final) {
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(s.fd, buffer, sizeof buffer);
    if (n > 0) {
      s.pending.append(buffer, static_cast<size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) {
      s.open = false;
      ::close(s.fd);
      s.fd = -1;
    }
    break;
  }
  // A line that already names the process (the station's "[station] t=...") keeps one prefix.
  const std::string prefix = "[" + s.child->spec.name + "] ";
  auto prefixed = [&prefix](std::string_view line) {
    return line.substr(0, prefix.size()) == prefix ? std::string(line) : prefix + std::string(line);
  };
  size_t start = 0;
  std::string out;
  for (size_t nl; (nl = s.pending.find('\n', start)) != std::string::npos; start = nl + 1)
    out += prefixed(std::string_view(s.pending).substr(start, nl - start)) + "\n";
  s.pending.erase(0, start);
  if (final && !s.pending.empty()) {
    out += prefixed(s.pending) + "\n";
    s.pending.clear();
  }
  if (!out.empty()) write_all(s.out_fd, out);
}

void Supervisor::on_child_exit(Child& child, int status) {
  child.running = false;
  child.status = status;
  const std::string what = child.spec.name + " (pid " + std::to_string(child.pid) + ") " + describe_wait_status(status);
  if (child.spec.ends_launch && !shutting_down_) {
    station_ended_ = true;
    station_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    log(what + (child.spec.is_station ? ": mission over, stopping the team" : ": stopping the rest"));
    begin_shutdown(child.spec.name + " ended");
    return;
  }
  if (shutting_down_ && child.expected_exit) {
    const bool clean = (WIFEXITED(status) && WEXITSTATUS(status) == 0) ||
                       (WIFSIGNALED(status) && (WTERMSIG(status) == SIGTERM || WTERMSIG(status) == SIGINT));
    if (!clean && !(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL && killed_)) {
      ++failures_;
      log("error: " + what + " while stopping");
    } else {
      log("stopped " + what);
    }
    return;
  }
  ++failures_;
  log("error: " + what + " unexpectedly");
  if (options_.exit_on_failure && !shutting_down_) begin_shutdown("--exit-on-failure: " + child.spec.name + " failed");
}

void Supervisor::reap() {
  for (;;) {
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, WNOHANG);
    if (pid <= 0) return;
    for (Child* c : children_) {
      if (c->pid == pid && c->running) on_child_exit(*c, status);
    }
  }
}

void Supervisor::begin_shutdown(const std::string& why) {
  if (shutting_down_) return;
  shutting_down_ = true;
  log("stopping " + std::to_string(living()) + " process(es): " + why);
  for (Child* c : children_) {
    c->expected_exit = true;
    if (c->running) ::kill(-c->pid, SIGTERM);
  }
  shutdown_started_s_ = now_s();
  kill_deadline_s_ = shutdown_started_s_ + options_.grace_s;
}

void Supervisor::kill_remaining(const std::string& why) {
  killed_ = true;
  for (Child* c : children_) {
    if (!c->running) continue;
    log(c->spec.name + " (pid " + std::to_string(c->pid) + ")" + why + ": sending SIGKILL");
    ::kill(-c->pid, SIGKILL);
  }
}

void Supervisor::handle_signal_fd() {
  signalfd_siginfo info;
  while (::read(signal_fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
    const int sig = static_cast<int>(info.ssi_signo);
    if (sig == SIGCHLD) continue;  // reaped below
    if (shutting_down_) {
      // A repeat within a second is the same request delivered twice (e.g. by `timeout` to
      // the child and then its process group); a later one means "now".
      if (!killed_ && now_s() - shutdown_started_s_ >= 1.0) {
        log(std::string("received ") + ::strsignal(sig) + " again: killing what is left");
        kill_remaining("");
      }
    } else {
      begin_shutdown(std::string("received ") + ::strsignal(sig));
    }
  }
  reap();
}

int Supervisor::run() {
  reap();
  for (;;) {
    if (living() == 0) break;
    std::vector<pollfd> fds{{signal_fd_, POLLIN, 0}};
    std::vector<Stream*> polled;
    for (Stream* s : streams_) {
      if (!s->open) continue;
      fds.push_back({s->fd, POLLIN, 0});
      polled.push_back(s);
    }
    int timeout_ms = -1;
    if (shutting_down_ && !killed_) timeout_ms = std::max(0, static_cast<int>((kill_deadline_s_ - now_s()) * 1000.0) + 1);
    if (killed_) timeout_ms = 1000;
    const int ready = ::poll(fds.data(), fds.size(), timeout_ms);
    if (ready < 0 && errno != EINTR) throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    for (size_t i = 1; i < fds.size(); ++i) {
      if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) read_stream(*polled[i - 1], false);
    }
    if (fds[0].revents & POLLIN) handle_signal_fd();
    reap();
    if (shutting_down_ && !killed_ && now_s() >= kill_deadline_s_ && living() > 0) {
      char grace[32];
      std::snprintf(grace, sizeof grace, "%g", options_.grace_s);
      kill_remaining(std::string(" did not stop within ") + grace + " s");
    }
    if (!shutting_down_ && living() == 0) break;
  }
  for (Stream* s : streams_) {
    if (s->open) read_stream(*s, true);
  }
  if (!shutting_down_) log("every process has ended");
  if (failures_ > 0) log(std::to_string(failures_) + " process(es) failed during this launch (see the errors above)");
  if (station_ended_) return station_code_;
  return failures_ == 0 ? 0 : 1;
}

}  // namespace hexplore::launcher
