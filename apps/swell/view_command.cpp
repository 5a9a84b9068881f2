// Placeholder until the viewer lands: reports that no viewer is built.
#include "commands.h"
#include "swell/error.h"
#include <cstdio>
namespace swell::app {
bool displayAvailable() { return false; }
int runView(const ViewOptions&) { std::fprintf(stderr, "swell: the viewer is not built yet\n"); return kExitFailure; }
}
