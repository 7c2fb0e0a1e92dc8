#include "common/evaluation/report_script.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

extern char** environ;

namespace hexplore::evaluation {

std::string report_script_path(const std::string& name) {
#ifdef HEXPLORE_REPORT_DIR
  return std::string(HEXPLORE_REPORT_DIR) + "/" + name;
#else
  return "tools/report/" + name;
#endif
}

std::optional<std::string> run_report_script(const std::string& script, const std::string& folder) {
  if (!std::filesystem::exists(script)) return script + " not found";
  std::string python = "python3";
  if (const char* env = std::getenv("HEXPLORE_PYTHON"); env && *env) python = env;
  else if (std::filesystem::exists("/usr/bin/python3")) python = "/usr/bin/python3";
  std::vector<std::string> argv = {python, script, folder};
  std::vector<char*> raw;
  for (auto& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, raw.data(), environ) != 0)
    return "python3 is not installed (apt-get install python3 python3-matplotlib)";
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return "could not wait for " + script;
  if (!WIFEXITED(status)) return script + " was killed by signal " + std::to_string(WTERMSIG(status));
  if (WEXITSTATUS(status) != 0) return script + " exited with status " + std::to_string(WEXITSTATUS(status));
  return std::nullopt;
}

}  // namespace hexplore::evaluation
