// The contact foam's map and its pass (contact_map.h).
#include "render/contact_map.h"

#include "render/gl_state.h"
#include "render/pass_state.h"
#include "render/scene_world.h"
#include "render/simulation.h"
#include "render/view_frame.h"
#include "swell/gpu/bindings.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace swell::detail {

namespace {

// How far (texels) the shear moves a point at the band's top or at the sea
// level from where it stands, along x and along z: a wall facing x then
// covers 2 texels, one facing z 1.2, and none is drawn more than a texel
// from its place.
constexpr double kShearX_texels = 1.0;
constexpr double kShearZ_texels = 0.6;

// A sea whose height deviation is below this (m) has no waves to wash
// anything (a flat model, a glassy calm): the pass is left out.
constexpr double kLeastWaves_m = 1e-3;

} // namespace

double contactBand_m(double significantHeight_m)
{
    return std::max(kContactBandMin_m, 0.5 * significantHeight_m);
}

double contactTop_m(double significantHeight_m) { return std::max(0.5 * significantHeight_m, 0.01); }

double contactExtent_m(double height_m)
{
    double extent = SWELL_CONTACT_MIN_EXTENT_M;
    while (extent < SWELL_CONTACT_EXTENT_PER_HEIGHT * height_m && extent < SWELL_CONTACT_MAX_EXTENT_M)
        extent *= 2.0;
    return std::min(extent, double(SWELL_CONTACT_MAX_EXTENT_M));
}

ContactPlacement placeContact(glm::dvec3 eye, glm::dvec3 origin, double top_m)
{
    ContactPlacement p;
    p.size_m = contactExtent_m(std::abs(eye.y));
    p.top_m = top_m;
    const double texel_m = p.size_m / SWELL_CONTACT_SIZE;
    const glm::dvec2 at(eye.x, eye.z);
    const glm::dvec2 corner = glm::floor((at - 0.5 * p.size_m) / texel_m) * texel_m;
    p.corner_m = corner - glm::dvec2(origin.x, origin.z);
    // NDC per metre across, and the shear's NDC per metre of height about
    // the band's middle (a texel is 2 / SWELL_CONTACT_SIZE of NDC).
    const double across = 2.0 / p.size_m;
    const double texelNdc = 2.0 / SWELL_CONTACT_SIZE;
    const double shearX = kShearX_texels * texelNdc / (0.5 * top_m);
    const double shearZ = kShearZ_texels * texelNdc / (0.5 * top_m);
    glm::dmat4 m(0.0);
    m[0] = glm::dvec4(across, 0.0, 0.0, 0.0);                // x
    m[1] = glm::dvec4(shearX, shearZ, -2.0 / top_m, 0.0);   // y: near at the top, far at the sea level
    m[2] = glm::dvec4(0.0, across, 0.0, 0.0);                // z
    m[3] = glm::dvec4(-across * p.corner_m.x - 1.0 - shearX * 0.5 * top_m,
                      -across * p.corner_m.y - 1.0 - shearZ * 0.5 * top_m, 1.0, 1.0);
    p.viewProj = m;
    return p;
}

GLuint ContactMap::framebuffer(const gl::ShaderSources& sources)
{
    if (!framebuffer_) {
        auto texture = [](GLenum format) {
            gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D));
            glTextureStorage2D(t.id(), 1, format, SWELL_CONTACT_SIZE, SWELL_CONTACT_SIZE);
            glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            return t;
        };
        depth_ = texture(GL_DEPTH_COMPONENT32F);
        glTextureParameteri(depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        rows_ = texture(GL_R32F);
        distance_ = texture(GL_R32F);
        framebuffer_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
        glNamedFramebufferReadBuffer(framebuffer_.id(), GL_NONE);
    }
    if (!rowsPass_) {
        rowsPass_ = gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "contact_distance.comp"}}, {"SWELL_CONTACT_ROWS 1"});
        columnsPass_ =
            gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "contact_distance.comp"}}, {"SWELL_CONTACT_ROWS 0"});
    }
    return framebuffer_.id();
}

void ContactMap::computeDistance()
{
    const GLuint groups = GLuint((SWELL_CONTACT_SIZE + SWELL_CONTACT_GROUP - 1) / SWELL_CONTACT_GROUP);
    // The rows' distances from the depth the pass drew...
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindTextureUnit(SWELL_UNIT_CONTACT, 0); // never the image written
    glBindTextureUnit(SWELL_UNIT_CONTACT_SOURCE, depth_.id());
    glBindImageTexture(SWELL_IMAGE_CONTACT_OUT, rows_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUseProgram(rowsPass_.id());
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    // ... then the map's from the rows'.
    glBindTextureUnit(SWELL_UNIT_CONTACT_SOURCE, rows_.id());
    glBindImageTexture(SWELL_IMAGE_CONTACT_OUT, distance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glUseProgram(columnsPass_.id());
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindTextureUnit(SWELL_UNIT_CONTACT_SOURCE, 0);
    glBindImageTexture(SWELL_IMAGE_CONTACT_OUT, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    releaseProgramStages();
}

GpuWork ContactMap::distanceWork()
{
    constexpr long long kR32f = 4; // bytes a texel
    GpuWork work;
    work.dispatches = 2;
    work.barriers = 3;
    work.bytesWritten = 2LL * SWELL_CONTACT_SIZE * SWELL_CONTACT_SIZE * kR32f;
    return work;
}

void ContactMap::bind() const { glBindTextureUnit(SWELL_UNIT_CONTACT, distance_.id()); }

namespace {

// Whether any of Swell's world's boxes (relative to the render origin) lies
// in the window and reaches the band from the sea level up to `top_m`.
bool worldInWindow(const FrameUniforms& f, const ContactPlacement& p)
{
    if (f.worldBoxCount < 0)
        return true;
    const glm::dvec2 lo = p.corner_m, hi = p.corner_m + p.size_m;
    for (int i = 0; i < f.worldBoxCount; ++i) {
        const WorldBoxUniform& box = f.worldBoxes[i];
        if (box.max_m.y >= 0.0f && box.min_m.y <= float(p.top_m) && box.max_m.x >= lo.x && box.min_m.x <= hi.x &&
            box.max_m.z >= lo.y && box.min_m.z <= hi.y)
            return true;
    }
    return false;
}

} // namespace

void drawContact(RenderContext& context, ViewFrame& v, SceneWorld* own, PassGeometry* host, const View& view)
{
    FrameUniforms& f = v.base;
    f.contactOn = 0;
    ContactMap& map = context.resources.contact;
    Simulation& simulation = context.simulation;
    const double deviation_m = simulation.model().heightDeviation_m();
    if (!map.enabled() || (own == nullptr && host == nullptr) || !(deviation_m > kLeastWaves_m))
        return;
    const ContactPlacement placement = placeContact(v.eye, v.origin, contactTop_m(4.0 * deviation_m));
    f.contactCorner_m = glm::vec2(placement.corner_m);
    f.contactSize_m = float(placement.size_m);
    f.contactBand_m = float(contactBand_m(4.0 * deviation_m));
    f.contactReach_m = float(placement.size_m * SWELL_CONTACT_REACH_TEXELS / SWELL_CONTACT_SIZE);
    // Swell's world within the window, or any host geometry (its extent is
    // not known). No occlusion query asks whether anything was drawn: the
    // benchmark's own queries of the pass's samples may be running, and
    // reading one back would stall a GPU's pipeline.
    if (host == nullptr && !worldInWindow(f, placement))
        return;

    const ObservedPass observed(context.telemetry, "contact");
    PassState pass;
    pass.slot = PassContact;
    pass.frame = f;
    pass.frame.passViewProj = glm::mat4(placement.viewProj);
    pass.frame.passInvViewProj = glm::mat4(glm::inverse(placement.viewProj));
    pass.frame.clipPlane = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    pass.framebuffer = map.framebuffer(context.resources.sources);
    pass.viewport = glm::ivec4(0, 0, SWELL_CONTACT_SIZE, SWELL_CONTACT_SIZE);
    pass.depth = depthConventionOf(DepthMode::Standard);
    // The window's axes (x right, z up the map) seen from above turn the
    // windings round, as the mirror does.
    pass.mirrored = true;
    pass.begin(context.resources, context.telemetry, glm::vec4(0.0f));
    glFrontFace(GL_CW);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);

    const SeaFrame& sea = simulation.sea();
    PassView pv;
    pv.pass = PassKind::Contact;
    pv.view = glm::translate(glm::dmat4(1.0), -sea.toWorld(v.origin));
    pv.projection = placement.viewProj;
    pv.viewport = pass.viewport;
    pv.depth = DepthMode::Standard;
    pv.eye_m = view.eye_m();

    drawGeometryAs(context, pass, pv, own, host);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glFrontFace(GL_CCW);
    ++context.telemetry.counters.contactMaps;
    map.computeDistance();
    Telemetry::addWork(ContactMap::distanceWork(), context.telemetry.counters.viewsGpu);
    map.bind();
    f.contactOn = 1;
}

} // namespace swell::detail
