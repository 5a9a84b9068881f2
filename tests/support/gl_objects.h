// Live GL objects of the current context, counted by kind, for tests that
// check that a long run gives back every name it took.
//
// How: glIs* on every name from 1 up to a bound. Before probing, one fresh
// object of each kind is made and deleted: implementations hand out either
// the lowest free name or one above every name in use (Mesa), so the bound,
// the larger of kGlNameProbeMin and the highest fresh name, covers every
// live object either way.
#pragma once

#include <string>

namespace swell::test {

struct GlObjectCounts {
    int textures = 0, buffers = 0, framebuffers = 0, renderbuffers = 0;
    int programs = 0, shaders = 0, vertexArrays = 0, samplers = 0, queries = 0;
    int pipelines = 0, transformFeedbacks = 0;
    // Names probed: 1 .. probedBelow - 1 (not part of the comparison).
    unsigned probedBelow = 0;

    // The same number of objects of every kind.
    bool operator==(const GlObjectCounts& o) const;
    int total() const;
    // "textures 12, buffers 40, ..." for messages.
    std::string str() const;
};

// Names always probed: 1 .. kGlNameProbeMin - 1.
inline constexpr unsigned kGlNameProbeMin = 4096;

// Counts the live objects of the current context. Needs a current GL 4.5 context.
GlObjectCounts countLiveGlObjects();

} // namespace swell::test
