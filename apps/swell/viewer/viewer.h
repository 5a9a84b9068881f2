// `swell view`: the interactive viewer. One window, one scene, a fly camera
// and a panel; see docs/VIEWER.md for the controls.
#pragma once

#include "commands.h"

namespace swell::app::viewer {

// Runs the viewer until its window closes, or for options.exitAfterFrames
// frames. Returns kExitOk; throws swell::InputError for bad options or a bad
// scene file, swell::Error when no window or context can be had.
int run(const ViewOptions& options);

} // namespace swell::app::viewer
