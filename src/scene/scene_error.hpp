// The one error a bad scene file produces: which file, where in it (a JSON path or a line and
// column), and what is wrong.
#pragma once

#include <stdexcept>
#include <string>

namespace twinraster {

class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, std::string where, std::string problem)
      : std::runtime_error(file + ": " + where + ": " + problem),
        file_(std::move(file)),
        where_(std::move(where)),
        problem_(std::move(problem)) {}

  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }  // e.g. "instances[1].transform.scale"
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, where_, problem_;
};

}  // namespace twinraster
