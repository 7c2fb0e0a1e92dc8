// hexplore_launch as a real process over fake services: prefixed output, clean shutdown on a
// signal, SIGKILL after the grace period, crash reports, the station ending the launch, and a
// clear error for a missing executable.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr const char* kTeam = R"(species:
  - builtin: SLUGCAT
  - builtin: MR1000
robots:
  - id: r1
    species: SLUGCAT
  - id: r2
    species: MR1000
)";

// One launcher run with its stdout+stderr in a file.
class Launch {
 public:
  Launch(std::vector<std::string> args, std::vector<std::pair<std::string, std::string>> env = {}) {
    dir_ = fs::temp_directory_path() / ("hexplore_launch_test_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter_++));
    fs::create_directories(dir_);
    config_ = (dir_ / "team.yaml").string();
    std::ofstream(config_) << kTeam;
    output_ = (dir_ / "output.txt").string();
    args.insert(args.begin(), {LAUNCHER_EXE, "--config", config_});
    pid_ = ::fork();
    if (pid_ == 0) {
      for (const auto& [k, v] : env) ::setenv(k.c_str(), v.c_str(), 1);
      FILE* f = std::fopen(output_.c_str(), "w");
      ::dup2(fileno(f), 1);
      ::dup2(fileno(f), 2);
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
  }
  ~Launch() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string output() const {
    std::ifstream in(output_);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  size_t count(const std::string& text) const {
    const std::string out = output();
    size_t n = 0;
    for (size_t at = out.find(text); at != std::string::npos; at = out.find(text, at + 1)) ++n;
    return n;
  }
  bool wait_for(const std::string& text, size_t times = 1, std::chrono::milliseconds limit = 10s) const {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
      if (count(text) >= times) return true;
      std::this_thread::sleep_for(20ms);
    }
    return false;
  }
  // Exit status of the launcher, or -1 when it is still running after `limit`.
  int wait_exit(std::chrono::milliseconds limit = 15s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      std::this_thread::sleep_for(20ms);
    }
    return -1;
  }
  void signal(int sig) { ::kill(pid_, sig); }
  // Pids the fake services reported.
  std::vector<pid_t> child_pids() const {
    std::vector<pid_t> pids;
    const std::string out = output();
    const std::regex re("fake \\S+ pid (\\d+) started");
    for (auto it = std::sregex_iterator(out.begin(), out.end(), re); it != std::sregex_iterator(); ++it)
      pids.push_back(std::stoi((*it)[1]));
    return pids;
  }
  const fs::path& dir() const { return dir_; }

 private:
  static inline int counter_ = 0;
  fs::path dir_;
  std::string config_;
  std::string output_;
  pid_t pid_ = -1;
  bool exited_ = false;
};

bool gone(pid_t pid) { return ::kill(pid, 0) != 0 && errno == ESRCH; }

TEST(Launcher, StartsEveryServiceOfEveryRobotWithPrefixedOutputAndStopsCleanlyOnSigint) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--services", "sim,mapping,hlmap,planning,safety"});
  ASSERT_TRUE(launch.wait_for("started\n", 10)) << launch.output();
  EXPECT_EQ(launch.count("[r1/sim] fake r1/sim pid"), 1u);
  EXPECT_EQ(launch.count("[r2/safety] fake r2/safety pid"), 1u);
  EXPECT_EQ(launch.count("[r2/hlmap] fake r2/hlmap says hello on stderr"), 1u);
  const auto pids = launch.child_pids();
  ASSERT_EQ(pids.size(), 10u);
  launch.signal(SIGINT);
  EXPECT_EQ(launch.wait_exit(), 0) << launch.output();
  EXPECT_EQ(launch.count("stopping\n"), 10u) << launch.output();
  for (pid_t pid : pids) EXPECT_TRUE(gone(pid)) << pid;
}

TEST(Launcher, StationEndsTheLaunchWithItsExitCode) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR}, {{"FAKE_EXIT", "station:3"}, {"FAKE_DELAY_MS", "500"}});
  EXPECT_EQ(launch.wait_exit(), 3) << launch.output();
  EXPECT_EQ(launch.count("fake station pid"), 1u);
  EXPECT_NE(launch.output().find("station (pid"), std::string::npos);
  EXPECT_NE(launch.output().find("exited with status 3: mission over"), std::string::npos) << launch.output();
  EXPECT_EQ(launch.count("stopping\n"), 10u) << launch.output();
}

TEST(Launcher, CrashIsReportedByNameAndSignal) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--services", "sim,mapping"}, {{"FAKE_CRASH", "r2/mapping"}});
  ASSERT_TRUE(launch.wait_for("error: r2/mapping (pid")) << launch.output();
  EXPECT_NE(launch.output().find("killed by signal 6"), std::string::npos) << launch.output();
  // Without --exit-on-failure the rest keeps running until stopped; the failure sets the code.
  std::this_thread::sleep_for(200ms);
  EXPECT_EQ(launch.wait_exit(100ms), -1);
  launch.signal(SIGTERM);
  EXPECT_EQ(launch.wait_exit(), 1) << launch.output();
}

TEST(Launcher, ExitOnFailureStopsEverything) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--services", "sim,mapping", "--exit-on-failure"},
                {{"FAKE_EXIT", "r1/sim:4"}});
  EXPECT_EQ(launch.wait_exit(), 1) << launch.output();
  EXPECT_NE(launch.output().find("error: r1/sim (pid"), std::string::npos);
  EXPECT_NE(launch.output().find("exited with status 4 unexpectedly"), std::string::npos) << launch.output();
  EXPECT_EQ(launch.count("stopping\n"), 3u) << launch.output();
}

TEST(Launcher, ProcessIgnoringSigtermIsKilledAfterTheGracePeriod) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--services", "sim", "--grace-s", "0.5"},
                {{"FAKE_IGNORE_TERM", "r1/sim"}});
  ASSERT_TRUE(launch.wait_for("started\n", 2)) << launch.output();
  const auto pids = launch.child_pids();
  launch.signal(SIGTERM);
  EXPECT_EQ(launch.wait_exit(), 0) << launch.output();
  EXPECT_NE(launch.output().find("r1/sim (pid"), std::string::npos);
  EXPECT_NE(launch.output().find("sending SIGKILL"), std::string::npos) << launch.output();
  for (pid_t pid : pids) EXPECT_TRUE(gone(pid));
}

TEST(Launcher, MissingExecutableIsNamedAndNothingStarts) {
  Launch launch({"--bin-dir", PARTIAL_BIN_DIR});
  EXPECT_EQ(launch.wait_exit(), 2);
  EXPECT_NE(launch.output().find("missing executable hexplore_planning (for r1/planning)"), std::string::npos)
      << launch.output();
  EXPECT_EQ(launch.count("started"), 0u);
}

TEST(Launcher, LogDirGetsOneFilePerProcess) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--services", "sim,safety", "--robots", "r2", "--log-dir", "logs"});
  ASSERT_TRUE(launch.wait_for("started r2/safety")) << launch.output();
  std::this_thread::sleep_for(300ms);
  launch.signal(SIGINT);
  EXPECT_EQ(launch.wait_exit(), 0) << launch.output();
  // The launcher ran in the test's working folder; logs/ is relative to it.
  std::ifstream log("logs/r2-safety.log");
  std::stringstream s;
  s << log.rdbuf();
  EXPECT_NE(s.str().find("fake r2/safety pid"), std::string::npos);
  EXPECT_NE(s.str().find("says hello on stderr"), std::string::npos);
  EXPECT_EQ(launch.count("[r2/safety]"), 0u);
  std::error_code ec;
  fs::remove_all("logs", ec);
}

TEST(Launcher, FastModeRunsOneComposedProcessThatHoldsTheStation) {
  // The station is inside the composed process (inproc reaches no other process), so the
  // composed process's exit ends the launch with its code.
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--compose"}, {{"FAKE_EXIT", "r2/team:5"}});
  EXPECT_EQ(launch.wait_exit(), 5) << launch.output();
  EXPECT_NE(launch.output().find("started team (pid"), std::string::npos) << launch.output();
  EXPECT_EQ(launch.count("fake r2/team pid"), 1u);  // the fake names itself by its last --robot
  EXPECT_EQ(launch.count("started\n"), 1u);
  EXPECT_EQ(launch.count("started station"), 0u);
  EXPECT_EQ(launch.count("started r1/"), 0u);
}

TEST(Launcher, FastModeWithoutStationEndsWithTheComposedProcess) {
  Launch launch({"--bin-dir", FAKE_BIN_DIR, "--compose", "--services", "sim"}, {{"FAKE_EXIT", "r2/team:0"}});
  EXPECT_EQ(launch.wait_exit(), 0) << launch.output();
  EXPECT_NE(launch.output().find("team (pid"), std::string::npos);
  Launch missing({"--bin-dir", FAKE_BIN_DIR, "--compose", "hexplore_nothing"});
  EXPECT_EQ(missing.wait_exit(), 2);
  EXPECT_NE(missing.output().find("missing executable hexplore_nothing (fast mode"), std::string::npos)
      << missing.output();
}

TEST(Launcher, BadArgumentsAreExplained) {
  Launch unknown_robot({"--bin-dir", FAKE_BIN_DIR, "--robots", "r9"});
  EXPECT_EQ(unknown_robot.wait_exit(), 2);
  EXPECT_NE(unknown_robot.output().find("unknown robot 'r9'"), std::string::npos) << unknown_robot.output();
  Launch unknown_service({"--bin-dir", FAKE_BIN_DIR, "--services", "radio"});
  EXPECT_EQ(unknown_service.wait_exit(), 2);
  EXPECT_NE(unknown_service.output().find("unknown service 'radio'"), std::string::npos);
}

}  // namespace
