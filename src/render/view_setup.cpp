#include "render/view_setup.h"
#include "render/water_visibility.h"

#include "swell/error.h"

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include <cmath>

namespace swell::detail {

DepthConvention depthConventionOf(DepthMode mode)
{
    DepthConvention c;
    switch (mode) {
    case DepthMode::Standard:
        break;
    case DepthMode::ZeroToOne:
        c.nearNdcZ = 0.0;
        c.ndcScale = 1.0;
        c.ndcOffset = 0.0;
        c.clipDepth = GL_ZERO_TO_ONE;
        break;
    case DepthMode::Reversed:
        c.nearNdcZ = 1.0;
        c.farNdcZ = 0.0;
        c.ndcScale = 1.0;
        c.ndcOffset = 0.0;
        c.cleared = 0.0f;
        c.test = GL_GREATER;
        c.testOrFar = GL_GEQUAL;
        c.clipDepth = GL_ZERO_TO_ONE;
        break;
    }
    return c;
}

void setDepthConvention(FrameUniforms& f, DepthMode mode)
{
    const DepthConvention c = depthConventionOf(mode);
    f.depthNdcScale = float(c.ndcScale);
    f.depthNdcOffset = float(c.ndcOffset);
    f.depthFar = c.cleared;
    f.nearNdcZ = float(c.nearNdcZ);
    f.farNdcZ = float(c.farNdcZ);
}

namespace {

bool finite(const glm::dmat4& m)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]))
                return false;
    return true;
}

// Whether m can be inverted without losing everything to rounding: its
// determinant against the size of its entries (the scale of a product of
// four of them).
bool invertible(const glm::dmat4& m)
{
    double largest = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            largest = std::max(largest, std::abs(m[c][r]));
    const double det = glm::determinant(m);
    return largest > 0.0 && std::isfinite(det) && std::abs(det) > 1e-12 * std::pow(largest, 4.0);
}

} // namespace

void checkView(const View& view)
{
    if (view.viewport.z <= 0 || view.viewport.w <= 0)
        throw Error(fmt::format("the view's viewport is empty: {} x {} pixels", view.viewport.z, view.viewport.w));
    // The view's rotation part (its translation may be kilometres).
    if (!finite(view.view) || !invertible(glm::dmat4(glm::dmat3(view.view))))
        throw Error("the view matrix is not finite or cannot be inverted");
    if (!finite(view.projection) || !invertible(view.projection))
        throw Error("the projection matrix is not finite or cannot be inverted");
    if (view.lodViewpoint_m && !std::isfinite(view.lodViewpoint_m->x + view.lodViewpoint_m->y + view.lodViewpoint_m->z))
        throw Error("the view's LOD viewpoint is not finite");
}

void checkFramebuffer(GLuint framebuffer, bool needsDepth)
{
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error(fmt::format("framebuffer {} is not complete (status 0x{:04x}){}", framebuffer, status,
                                framebuffer == 0 ? ": the context has no default framebuffer" : ""));
    if (!needsDepth)
        return;
    GLint type = GL_NONE;
    if (framebuffer == 0) {
        GLint depthBits = 0;
        glGetNamedFramebufferAttachmentParameteriv(0, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
        type = depthBits > 0 ? GL_FRAMEBUFFER_DEFAULT : GL_NONE;
    } else {
        glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_DEPTH_ATTACHMENT,
                                                   GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    }
    if (type == GL_NONE)
        throw Error(fmt::format("framebuffer {} has no depth buffer: the water is depth-tested against the host's "
                                "scene, so draw() needs one",
                                framebuffer));
}

void checkMotionVectors(GLuint framebuffer, std::uint32_t attachment)
{
    if (framebuffer == 0)
        throw Error("DrawOptions::motionVectors needs a framebuffer object of the host's: framebuffer 0 has no "
                    "attachment to write them into");
    GLint attachments = 0;
    glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &attachments);
    if (attachment < GL_COLOR_ATTACHMENT0 || attachment >= GL_COLOR_ATTACHMENT0 + GLuint(attachments))
        throw Error(fmt::format("DrawOptions::motionVectors 0x{:04x} is not a colour attachment "
                                "(GL_COLOR_ATTACHMENT0 .. GL_COLOR_ATTACHMENT{})",
                                attachment, attachments - 1));
    const GLuint index = attachment - GL_COLOR_ATTACHMENT0;
    GLint type = GL_NONE, component = GL_NONE, green = 0;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_NONE)
        throw Error(fmt::format("framebuffer {} has nothing at GL_COLOR_ATTACHMENT{} (DrawOptions::motionVectors)",
                                framebuffer, index));
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                               &component);
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE, &green);
    if (component != GL_FLOAT || green == 0)
        throw Error(fmt::format("framebuffer {}'s GL_COLOR_ATTACHMENT{} (DrawOptions::motionVectors) must be a float "
                                "format of two channels or more (GL_RG16F, GL_RG32F)",
                                framebuffer, index));
    if (!vertexShadersStoreBuffers())
        throw Error("DrawOptions::motionVectors: this GL's vertex shaders cannot use storage buffers "
                    "(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS is 0), which the water's previous vertices need");
}

} // namespace swell::detail
