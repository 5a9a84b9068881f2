// Counting live GL objects (support/gl_objects.h).
#include "support/gl_objects.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <algorithm>

namespace swell::test {

bool GlObjectCounts::operator==(const GlObjectCounts& o) const
{
    return textures == o.textures && buffers == o.buffers && framebuffers == o.framebuffers &&
           renderbuffers == o.renderbuffers && programs == o.programs && shaders == o.shaders &&
           vertexArrays == o.vertexArrays && samplers == o.samplers && queries == o.queries &&
           pipelines == o.pipelines && transformFeedbacks == o.transformFeedbacks;
}

int GlObjectCounts::total() const
{
    return textures + buffers + framebuffers + renderbuffers + programs + shaders + vertexArrays + samplers + queries +
           pipelines + transformFeedbacks;
}

std::string GlObjectCounts::str() const
{
    return fmt::format("textures {}, buffers {}, framebuffers {}, renderbuffers {}, programs {}, shaders {}, "
                       "vertex arrays {}, samplers {}, queries {}, pipelines {}, transform feedbacks {} "
                       "(names 1..{} probed)",
                       textures, buffers, framebuffers, renderbuffers, programs, shaders, vertexArrays, samplers,
                       queries, pipelines, transformFeedbacks, probedBelow - 1);
}

namespace {

// The highest name among fresh objects of every kind, made and deleted here.
GLuint highestFreshName()
{
    GLuint n[9] = {};
    glCreateTextures(GL_TEXTURE_2D, 1, &n[0]);
    glCreateBuffers(1, &n[1]);
    glCreateFramebuffers(1, &n[2]);
    glCreateRenderbuffers(1, &n[3]);
    glCreateVertexArrays(1, &n[4]);
    glCreateSamplers(1, &n[5]);
    glCreateQueries(GL_TIME_ELAPSED, 1, &n[6]);
    glCreateProgramPipelines(1, &n[7]);
    glCreateTransformFeedbacks(1, &n[8]);
    const GLuint program = glCreateProgram();
    const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
    GLuint highest = std::max(program, shader);
    for (GLuint name : n)
        highest = std::max(highest, name);
    glDeleteTextures(1, &n[0]);
    glDeleteBuffers(1, &n[1]);
    glDeleteFramebuffers(1, &n[2]);
    glDeleteRenderbuffers(1, &n[3]);
    glDeleteVertexArrays(1, &n[4]);
    glDeleteSamplers(1, &n[5]);
    glDeleteQueries(1, &n[6]);
    glDeleteProgramPipelines(1, &n[7]);
    glDeleteTransformFeedbacks(1, &n[8]);
    glDeleteProgram(program);
    glDeleteShader(shader);
    return highest;
}

} // namespace

GlObjectCounts countLiveGlObjects()
{
    GlObjectCounts c;
    c.probedBelow = std::max(kGlNameProbeMin, highestFreshName() + 1);
    for (GLuint name = 1; name < c.probedBelow; ++name) {
        c.textures += glIsTexture(name);
        c.buffers += glIsBuffer(name);
        c.framebuffers += glIsFramebuffer(name);
        c.renderbuffers += glIsRenderbuffer(name);
        // Programs and shaders share one namespace; each name is one or the other.
        c.programs += glIsProgram(name);
        c.shaders += glIsShader(name);
        c.vertexArrays += glIsVertexArray(name);
        c.samplers += glIsSampler(name);
        c.queries += glIsQuery(name);
        c.pipelines += glIsProgramPipeline(name);
        c.transformFeedbacks += glIsTransformFeedback(name);
    }
    return c;
}

} // namespace swell::test
