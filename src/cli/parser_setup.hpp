// How twinraster declares its commands to CLI11: the settings every command shares, and checks
// on option values whose failures read as one clear line.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace twinraster::cli {

// The settings of the top-level parser: name, help flag and formatter, option policies. Call it
// before adding any command, which inherits them.
void SetUpParser(CLI::App& app);

// A subcommand whose stray arguments are kept for usage_problems.hpp to name (with the closest
// valid option) instead of CLI11's own message.
CLI::App* AddSubcommand(CLI::App& app, const std::string& name, const std::string& description,
                        const std::string& footer);

// The value must be a non-negative integer below a billion ("--vertex: expects ...").
CLI::Option* ExpectIndex(CLI::Option* option);
// The value must be an integer in lo..hi.
CLI::Option* ExpectIntegerIn(CLI::Option* option, long lo, long hi);
// The value must be a finite number in lo..hi; `expected` describes it in the message, which
// quotes the value: --timeout: expects seconds from 0 (no limit) to 1000000, got "-1".
CLI::Option* ExpectNumberIn(CLI::Option* option, double lo, double hi, const std::string& expected);
// The value must be one of `choices`; `noun` names them in the message, which suggests the
// closest: unknown backend "gpuu" (did you mean "gpu"?); choose from gpu, cpu, both.
CLI::Option* ExpectOneOf(CLI::Option* option, const std::string& noun, const std::vector<std::string>& choices);

}  // namespace twinraster::cli
