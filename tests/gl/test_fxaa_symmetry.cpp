// The FXAA filter (shaders/fxaa.frag) treats left and right, and up and
// down, alike: filtering a mirrored image gives the mirror of the filtered
// image. It reads the pixel's diagonal neighbours by integer offsets and
// estimates the edge's direction from them, so a neighbour read from the wrong
// side, or the wrong texel at the image's edges, turns some of the edge's
// smoothing the other way and breaks the symmetry.
#include "support/gl_test.h"

#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/gpu/bindings.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace {

class FxaaSymmetry : public swell::test::GlTest {};

constexpr int kFxaaSymmetryWidth = 64, kFxaaSymmetryHeight = 48;

using FxaaImage = std::vector<std::uint8_t>; // RGBA8, rows bottom to top

// Hard-edged shapes at every slant, none of them symmetric: a disc, a shallow
// and a steep edge, and a bright block touching the image's corner.
FxaaImage testImage()
{
    FxaaImage image(size_t(kFxaaSymmetryWidth * kFxaaSymmetryHeight * 4));
    for (int y = 0; y < kFxaaSymmetryHeight; ++y)
        for (int x = 0; x < kFxaaSymmetryWidth; ++x) {
            const bool disc = (x - 20) * (x - 20) + (y - 30) * (y - 30) < 11 * 11;
            const bool shallow = y < 0.3 * x - 2.0;
            const bool steep = x > 44 && y > 2.7 * (x - 44);
            const bool corner = x > 56 && y > 40;
            std::uint8_t* p = &image[size_t((y * kFxaaSymmetryWidth + x) * 4)];
            p[0] = disc || corner ? 230 : 20;
            p[1] = shallow ? 200 : 40;
            p[2] = steep ? 250 : 60;
            p[3] = 255;
        }
    return image;
}

FxaaImage mirrored(const FxaaImage& image, bool horizontal)
{
    FxaaImage out(image.size());
    for (int y = 0; y < kFxaaSymmetryHeight; ++y)
        for (int x = 0; x < kFxaaSymmetryWidth; ++x) {
            const int sx = horizontal ? kFxaaSymmetryWidth - 1 - x : x, sy = horizontal ? y : kFxaaSymmetryHeight - 1 - y;
            std::copy_n(&image[size_t((sy * kFxaaSymmetryWidth + sx) * 4)], 4, &out[size_t((y * kFxaaSymmetryWidth + x) * 4)]);
        }
    return out;
}

// The image as fxaa.frag filters it, at the same size (as MainTarget::present draws it).
FxaaImage filtered(const FxaaImage& image)
{
    const swell::gl::Program program = swell::gl::buildProgram(
        swell::gl::ShaderSources::embedded(), {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "fxaa.frag"}});
    swell::gl::Texture source = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(source.id(), 1, GL_RGBA8, kFxaaSymmetryWidth, kFxaaSymmetryHeight);
    glTextureSubImage2D(source.id(), 0, 0, 0, kFxaaSymmetryWidth, kFxaaSymmetryHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    // The main pass's colour target's sampling (render/render_target.cpp).
    glTextureParameteri(source.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(source.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(source.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(source.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    swell::gl::Texture color = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(color.id(), 1, GL_RGBA8, kFxaaSymmetryWidth, kFxaaSymmetryHeight);
    swell::gl::Framebuffer target = swell::gl::Framebuffer::create();
    glNamedFramebufferTexture(target.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    swell::gl::VertexArray vao = swell::gl::VertexArray::create();

    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, kFxaaSymmetryWidth, kFxaaSymmetryHeight);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(program.id());
    glBindTextureUnit(SWELL_UNIT_POST_SOURCE, source.id());
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    FxaaImage out(image.size());
    glReadPixels(0, 0, kFxaaSymmetryWidth, kFxaaSymmetryHeight, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    glBindVertexArray(0);
    glUseProgram(0);
    glBindTextureUnit(SWELL_UNIT_POST_SOURCE, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return out;
}

int fxaaSymmetryLargestDifference(const FxaaImage& a, const FxaaImage& b)
{
    int worst = 0;
    for (size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
    return worst;
}

// Filtered pixels may differ from the mirror's by the rounding of the
// filtered lookups along the edge: llvmpipe weighs two texels with 8-bit
// weights, and the mirrored weights 1 - w round on the other side, one
// level at most for each of the averaged lookups.
constexpr int kRoundingLevels = 2;

TEST_F(FxaaSymmetry, FilteringAMirroredImageGivesTheMirroredResult)
{
    const FxaaImage image = testImage();
    const FxaaImage once = filtered(image);
    // Not vacuous: the filter changed the edges.
    int changed = 0;
    for (size_t i = 0; i < image.size(); i += 4)
        changed += fxaaSymmetryLargestDifference(FxaaImage(image.begin() + long(i), image.begin() + long(i) + 3),
                                     FxaaImage(once.begin() + long(i), once.begin() + long(i) + 3)) > 8;
    EXPECT_GT(changed, 100);
    for (const bool horizontal : {true, false}) {
        SCOPED_TRACE(horizontal ? "left-right mirror" : "up-down mirror");
        EXPECT_LE(fxaaSymmetryLargestDifference(filtered(mirrored(image, horizontal)), mirrored(once, horizontal)),
                  kRoundingLevels);
    }
}

} // namespace
