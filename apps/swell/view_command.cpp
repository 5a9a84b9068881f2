// `swell view`: the interactive viewer, whose parts live in viewer/. Turns its
// errors into exit codes: bad input 2, anything else 1.
#include "commands.h"
#include "viewer/viewer.h"
#include "viewer/window.h"

#include "swell/error.h"

#include <cstdio>
#include <exception>

namespace swell::app {

int runView(const ViewOptions& options)
{
    return viewer::run(options);
}

bool displayAvailable() { return viewer::displayUsable(); }

} // namespace swell::app
