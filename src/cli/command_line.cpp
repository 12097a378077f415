#include "cli/command_line.hpp"

#include "base/usage_error.hpp"

#include <algorithm>

namespace twinraster {

namespace {
bool Contains(const std::vector<std::string>& list, const std::string& s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}
}  // namespace

CommandLine::CommandLine(const std::vector<std::string>& args, const std::vector<std::string>& flags,
                         const std::vector<std::string>& options) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() < 2 || arg[0] != '-') {
      positional_.push_back(arg);
      continue;
    }
    std::string name = arg, value;
    const bool has_inline_value = arg.find('=') != std::string::npos;
    if (has_inline_value) name = arg.substr(0, arg.find('=')), value = arg.substr(arg.find('=') + 1);
    if (Contains(flags, name) && !has_inline_value) {
      flags_set_.push_back(name);
    } else if (Contains(options, name)) {
      if (!has_inline_value) {
        if (i + 1 >= args.size()) throw UsageError("option " + name + " needs a value");
        value = args[++i];
      }
      options_set_.emplace_back(name, value);
    } else {
      throw UsageError("unknown option " + arg);
    }
  }
}

bool CommandLine::Flag(const std::string& name) const { return Contains(flags_set_, name); }

std::optional<std::string> CommandLine::Option(const std::string& name) const {
  std::optional<std::string> value;
  for (const auto& [key, v] : options_set_)
    if (key == name) value = v;  // the last one wins, as in most tools
  return value;
}

std::optional<std::size_t> CommandLine::Index(const std::string& name) const {
  const std::optional<std::string> value = Option(name);
  if (!value) return std::nullopt;
  const bool digits = !value->empty() && value->size() < 10 &&
                      std::all_of(value->begin(), value->end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits) throw UsageError(name + " expects a non-negative integer, got \"" + *value + "\"");
  return static_cast<std::size_t>(std::stoul(*value));
}

void CommandLine::ExpectPositional(const std::vector<std::string>& names) const {
  if (positional_.size() < names.size()) throw UsageError("missing " + names[positional_.size()]);
  if (positional_.size() > names.size()) throw UsageError("unexpected argument " + positional_[names.size()]);
}

}  // namespace twinraster
