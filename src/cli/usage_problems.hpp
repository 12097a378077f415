// What is wrong with a command line, as one line: an argument nothing took (with the closest
// valid command or option), a missing argument, or one of CLI11's errors reworded.
#pragma once

#include <string>

namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace twinraster::cli {

// The first argument no option or positional of `app` took, described ("unknown option --backnd
// (did you mean --backend?)", "unexpected argument b.json"; at the top level, `unknown command
// "rendr" (did you mean "render"?)`); "" when every argument was taken.
std::string LeftoverProblem(const CLI::App& app);

// "missing SCENE" for the first required positional of `app` not given; "" when all are.
std::string MissingArgumentProblem(const CLI::App& app);

// CLI11's error as one line in twinraster's words ("--runs: ...", "option --threads needs a value").
std::string ParseErrorProblem(const CLI::ParseError& error);

}  // namespace twinraster::cli
