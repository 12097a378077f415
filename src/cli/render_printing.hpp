// What `render` prints for each scene: its record as the report's lines or as JSON, and a scene's
// own failure. It prints only; when and from which thread is render_batch.hpp's to decide.
#pragma once

#include "cli/render_arguments.hpp"
#include "run/run_record.hpp"

#include <string>

namespace twinraster::cli {

// One scene's record: JSON (one object; several scenes: JSON Lines, one per scene as it finishes)
// or the report's lines (on standard error when the PNG goes to standard output).
void PrintRecord(const RenderArguments& a, const run::RunRecord& record, bool several);

// A scene that failed on its own: the message on standard error, and with --json its record (of
// verdict error), so that every scene has its line.
void PrintFailure(const RenderArguments& a, const std::string& message, const run::RunRecord& record, bool several);

}  // namespace twinraster::cli
