// The checks on `render`'s arguments that need no scene and no device, so that a mistake costs
// nothing: which options go together, and what -o names for one scene or several. They throw
// UsageError; they check no path on disk for writing (render_files.hpp's PrepareDestinations does).
#pragma once

#include "cli/render_arguments.hpp"

namespace twinraster::cli {

// The run's typed options (a.run), from the words parsed. --rules book draws on the CPU only, so
// it implies --backend cpu; asking for another is a mistake.
void ResolveOptions(RenderArguments& a);

// The outputs asked for, checked against each other and against the scenes; sets a.directory when
// each scene's files go into a directory, named after it.
void CheckOutput(RenderArguments& a);

}  // namespace twinraster::cli
