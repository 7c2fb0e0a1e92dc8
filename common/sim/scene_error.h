#pragma once
// The one exception type of the simulator's world: a scene or mesh that cannot be used.
// It names the file (or scene) and the problem so a user can fix the input.

#include <stdexcept>
#include <string>

namespace hexplore::sim {

class SceneError : public std::runtime_error {
 public:
  SceneError(std::string source, std::string problem)
      : std::runtime_error(source + ": " + problem), source_(std::move(source)), problem_(std::move(problem)) {}

  const std::string& source() const { return source_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string source_;
  std::string problem_;
};

}  // namespace hexplore::sim
