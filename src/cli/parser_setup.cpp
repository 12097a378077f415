#include "cli/parser_setup.hpp"

#include "base/closest_match.hpp"
#include "cli/version.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>

namespace twinraster::cli {

namespace {

// CLI11's layout, with each positional shown by its name alone: all of twinraster's are
// required, and "SCENE TEXT REQUIRED" says less than the description beside it.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* option) const override {
    return option->get_positional() ? std::string() : CLI::Formatter::make_option_opts(option);
  }
};

std::string Join(const std::vector<std::string>& words) {
  std::string joined;
  for (const std::string& word : words) joined += (joined.empty() ? "" : ", ") + word;
  return joined;
}

bool IsDigits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

void SetUpParser(CLI::App& app) {
  app.set_help_flag("-h,--help", "print this help and exit");
  app.formatter(std::make_shared<HelpFormatter>());
  app.get_formatter()->column_width(28);
  app.get_formatter()->label("SUBCOMMAND", "COMMAND");
  app.get_formatter()->label("Positionals", "Arguments");
  // The last of a repeated option wins, as in most tools (CLI11's default is an error).
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  // One command per run; a second command's name after the first is a stray argument.
  app.require_subcommand(0, 1);
  app.allow_extras();  // stray arguments are named by LeftoverProblem(), with a suggestion
}

CLI::App* AddSubcommand(CLI::App& app, const std::string& name, const std::string& description,
                        const std::string& footer) {
  CLI::App* command = app.add_subcommand(name, description);
  command->group("Commands");
  command->allow_extras();
  // A function, called only when --version is given: it reaches Vulkan to list the devices.
  command->set_version_flag("--version", VersionText, "print the version and exit");
  if (!footer.empty()) command->footer(footer);
  return command;
}

CLI::Option* ExpectIndex(CLI::Option* option) {
  return option->check(CLI::Validator(
      [](std::string& value) -> std::string {
        // Nine digits at most: any index a scene can have, and no overflow in the conversion.
        if (IsDigits(value) && value.size() < 10) return "";
        return "expects a non-negative integer, got \"" + value + "\"";
      },
      "", "index"));
}

CLI::Option* ExpectIntegerIn(CLI::Option* option, long lo, long hi) {
  return option->check(CLI::Validator(
      [lo, hi](std::string& value) -> std::string {
        long n = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), n);
        if (value.empty() || error != std::errc() || end != value.data() + value.size() || n < lo || n > hi) {
          return "expects an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got \"" + value + "\"";
        }
        return "";
      },
      "", "integer range"));
}

CLI::Option* ExpectNumberIn(CLI::Option* option, double lo, double hi, const std::string& expected) {
  return option->check(CLI::Validator(
      [lo, hi, expected](std::string& value) -> std::string {
        double x = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), x);
        // from_chars reads "inf" and "nan", which no bound refuses by itself (nan compares false).
        const bool number = !value.empty() && error == std::errc() && end == value.data() + value.size();
        if (number && std::isfinite(x) && x >= lo && x <= hi) return "";
        return "expects " + expected + ", got \"" + value + "\"";
      },
      "", "number range"));
}

CLI::Option* ExpectOneOf(CLI::Option* option, const std::string& noun, const std::vector<std::string>& choices) {
  return option->check(CLI::Validator(
      [noun, choices](std::string& value) -> std::string {
        if (std::find(choices.begin(), choices.end(), value) != choices.end()) return "";
        const std::string suggestion = ClosestMatch(value, choices);
        return "unknown " + noun + " \"" + value + "\"" +
               (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)") + "; choose from " + Join(choices);
      },
      "", "one of"));
}

}  // namespace twinraster::cli
