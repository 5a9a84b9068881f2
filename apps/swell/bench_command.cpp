// Placeholder until the benchmark lands.
#include "commands.h"
#include "swell/error.h"
#include <cstdio>
namespace swell::app {
int runBench(const BenchOptions&) { std::fprintf(stderr, "swell: the benchmark is not built yet\n"); return kExitFailure; }
}
