#pragma once
// Runs one of the report scripts of tools/report (matplotlib figures and tables drawn from a
// results folder) with Debian's python3, the interpreter python3-matplotlib installs into (a
// python3 earlier on the PATH, e.g. pyenv's, may lack it); HEXPLORE_PYTHON overrides. A mission
// never fails because its figures could not be drawn: the caller prints what this returns.

#include <optional>
#include <string>

namespace hexplore::evaluation {

// Where the scripts are: tools/report of the source tree this binary was built from.
std::string report_script_path(const std::string& name);

// Runs `python3 script folder` and waits for it. Returns nullopt when it succeeded, else why
// not (script missing, no python3, its exit status) in one line.
std::optional<std::string> run_report_script(const std::string& script, const std::string& folder);

}  // namespace hexplore::evaluation
