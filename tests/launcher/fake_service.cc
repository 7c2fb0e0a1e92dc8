// Stands in for a hexplore service in launcher tests. Started as hexplore_<service> (through a
// symlink) with --config FILE [--robot ID]; its name is "<robot>/<service>" or "station".
// Environment (comma-separated names): FAKE_CRASH aborts those after FAKE_DELAY_MS (300),
// FAKE_EXIT=name:code exits with that code after the delay, FAKE_IGNORE_TERM ignores SIGTERM.
// Otherwise it sleeps until SIGTERM/SIGINT and exits 0.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

namespace {

volatile sig_atomic_t g_stop = 0;
void on_stop(int) { g_stop = 1; }

bool listed(const char* variable, const std::string& name, std::string* value = nullptr) {
  const char* text = std::getenv(variable);
  if (text == nullptr) return false;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const auto colon = item.find(':');
    if (item.substr(0, colon) == name) {
      if (value && colon != std::string::npos) *value = item.substr(colon + 1);
      return true;
    }
  }
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  std::string service = argv[0];
  service = service.substr(service.rfind('/') + 1);
  if (service.rfind("hexplore_", 0) == 0) service = service.substr(9);
  std::string robot;
  bool has_config = false;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--robot") == 0) robot = argv[i + 1];
    if (std::strcmp(argv[i], "--config") == 0) has_config = true;
  }
  if (!has_config) {
    std::fprintf(stderr, "fake %s: missing --config\n", service.c_str());
    return 2;
  }
  const std::string name = service == "station" ? "station" : robot + "/" + service;

  struct sigaction sa {};
  sa.sa_handler = listed("FAKE_IGNORE_TERM", name) ? SIG_IGN : on_stop;
  sigaction(SIGTERM, &sa, nullptr);
  sa.sa_handler = on_stop;
  sigaction(SIGINT, &sa, nullptr);

  std::printf("fake %s pid %d started\n", name.c_str(), static_cast<int>(getpid()));
  std::fflush(stdout);
  std::fprintf(stderr, "fake %s says hello on stderr\n", name.c_str());

  const char* delay_text = std::getenv("FAKE_DELAY_MS");
  const int delay_ms = delay_text ? std::atoi(delay_text) : 300;
  std::string exit_code;
  const bool crash = listed("FAKE_CRASH", name);
  const bool exit_early = listed("FAKE_EXIT", name, &exit_code);
  for (int waited = 0; !g_stop; waited += 10) {
    usleep(10 * 1000);
    if ((crash || exit_early) && waited >= delay_ms) {
      if (crash) std::abort();
      std::printf("fake %s exiting with %s\n", name.c_str(), exit_code.c_str());
      return std::atoi(exit_code.c_str());
    }
  }
  std::printf("fake %s stopping\n", name.c_str());
  return 0;
}
