// The example host's self-check (--check), run by the test suite against
// the installed package: its own cube, drawn by its own shader, mirrored
// by Swell's water; its own wall hiding the water; nothing else of the
// host's frame changed. For a level camera, one rolled 30 degrees,
// reversed-Z, the sea at 100 m, and all three at once.
#pragma once

namespace host {

// Runs every check on the current context (host GL functions loaded),
// prints one line per view, and returns 0 when all hold, else 3.
int runChecks();

} // namespace host
