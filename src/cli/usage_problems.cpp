#include "cli/usage_problems.hpp"

#include "base/closest_match.hpp"

#include <CLI/CLI.hpp>

#include <vector>

namespace twinraster::cli {

namespace {

bool LooksLikeOption(const std::string& argument) { return argument.size() > 1 && argument[0] == '-'; }

std::vector<std::string> OptionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_positional()) continue;
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

std::string UnknownOption(const CLI::App& app, const std::string& argument) {
  const std::string name = argument.substr(0, argument.find('='));  // --backnd=gpu names --backnd
  // Suggesting among one-letter options would be a guess: -x is as close to -o as to -q.
  const std::string suggestion = name.size() > 2 ? ClosestMatch(name, OptionNames(app)) : std::string();
  return "unknown option " + name + (suggestion.empty() ? "" : " (did you mean " + suggestion + "?)");
}

}  // namespace

std::string LeftoverProblem(const CLI::App& app) {
  const std::vector<std::string> left = app.remaining(false);
  if (left.empty()) return "";
  const std::string& first = left.front();
  if (LooksLikeOption(first)) return UnknownOption(app, first);
  if (app.get_parent() != nullptr) return "unexpected argument " + first;
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  const std::string suggestion = ClosestMatch(first, commands);
  return "unknown command \"" + first + "\"" + (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)");
}

std::string MissingArgumentProblem(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_positional() && option->get_required() && option->count() == 0) {
      return "missing " + option->get_name(true, false);
    }
  }
  return "";
}

std::string ParseErrorProblem(const CLI::ParseError& error) {
  const std::string message = error.what();
  // "--threads: 1 required UINT missing": an option given last, without its value.
  if (error.get_name() == "ArgumentMismatch" && message.find(" required ") != std::string::npos &&
      message.find(" missing") != std::string::npos) {
    return "option " + message.substr(0, message.find(':')) + " needs a value";
  }
  // "Could not convert: --json = maybe": a value the option cannot take.
  const std::string prefix = "Could not convert: ";
  if (error.get_name() == "ConversionError" && message.rfind(prefix, 0) == 0 &&
      message.find(" = ") != std::string::npos) {
    const std::size_t equals = message.find(" = ");
    return message.substr(prefix.size(), equals - prefix.size()) + ": cannot take the value \"" +
           message.substr(equals + 3) + "\"";
  }
  return message;
}

}  // namespace twinraster::cli
