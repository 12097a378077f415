// A small command-line parser: positional arguments, --flags and --options with a value; anything
// unknown or malformed is a UsageError.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace twinraster {

class CommandLine {
 public:
  // `flags` take no value (--json); `options` take one (--instance 1, or --instance=1).
  CommandLine(const std::vector<std::string>& args, const std::vector<std::string>& flags,
              const std::vector<std::string>& options);

  bool Flag(const std::string& name) const;
  std::optional<std::string> Option(const std::string& name) const;
  std::optional<std::size_t> Index(const std::string& name) const;  // a non-negative integer option
  const std::vector<std::string>& Positional() const { return positional_; }
  // Exactly one positional argument per name; a missing one is named in the error message.
  void ExpectPositional(const std::vector<std::string>& names) const;

 private:
  std::vector<std::string> positional_;
  std::vector<std::string> flags_set_;
  std::vector<std::pair<std::string, std::string>> options_set_;
};

}  // namespace twinraster
