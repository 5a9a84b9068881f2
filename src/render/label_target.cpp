#include "render/label_target.h"

#include "swell/error.h"

#include <algorithm>
#include <limits>

namespace swell::detail {

namespace {

gl::Texture makeTexture(glm::ivec2 size, GLenum format)
{
    gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(t.id(), 1, format, size.x, size.y);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

// GL's rows run bottom first; the labels' top first.
template <typename T>
void flipRows(std::vector<T>& rows, glm::ivec2 size, int perPixel)
{
    const std::size_t row = std::size_t(size.x) * std::size_t(perPixel);
    for (int y = 0; y < size.y / 2; ++y)
        std::swap_ranges(rows.begin() + std::ptrdiff_t(std::size_t(y) * row),
                         rows.begin() + std::ptrdiff_t(std::size_t(y + 1) * row),
                         rows.begin() + std::ptrdiff_t(std::size_t(size.y - 1 - y) * row));
}

// Tightly packed rows while it lives (the alignment the caller had is put back).
class PackedRows {
public:
    PackedRows()
    {
        glGetIntegerv(GL_PACK_ALIGNMENT, &alignment_);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
    }
    ~PackedRows() { glPixelStorei(GL_PACK_ALIGNMENT, alignment_); }
    PackedRows(const PackedRows&) = delete;
    PackedRows& operator=(const PackedRows&) = delete;

private:
    GLint alignment_ = 4;
};

} // namespace

std::vector<std::uint16_t> LabelTarget::readClassInstance() const
{
    std::vector<std::uint16_t> classInstance(std::size_t(size_.x) * std::size_t(size_.y) * 2);
    {
        const PackedRows packed;
        glGetTextureImage(classInstance_.id(), 0, GL_RG_INTEGER, GL_UNSIGNED_SHORT,
                          GLsizei(classInstance.size() * sizeof(std::uint16_t)), classInstance.data());
    }
    flipRows(classInstance, size_, 2);
    return classInstance;
}

void LabelTarget::readInstance(std::vector<std::uint16_t>& instance) const
{
    const std::vector<std::uint16_t> classInstance = readClassInstance();
    instance.resize(classInstance.size() / 2);
    for (std::size_t i = 0; i < instance.size(); ++i)
        instance[i] = classInstance[2 * i + 1];
}

void LabelTarget::resize(glm::ivec2 size)
{
    if (size == size_)
        return;
    framebuffer_.reset();
    rangeNormal_.reset();
    classInstance_.reset();
    depth_.reset();
    size_ = size;
    rangeNormal_ = makeTexture(size, GL_RGBA32F);
    classInstance_ = makeTexture(size, GL_RG16UI);
    depth_ = makeTexture(size, GL_DEPTH_COMPONENT32F);
    framebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, rangeNormal_.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, classInstance_.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(framebuffer_.id(), 2, buffers);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("swell::LabelTarget::resize(): framebuffer incomplete");
}

void LabelTarget::clear(float depth) const
{
    const float rangeNormal[4] = {std::numeric_limits<float>::infinity(), 0.0f, 0.0f, 0.0f};
    const GLuint none[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, rangeNormal);
    glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, 1, none);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &depth);
}

void LabelTarget::read(std::vector<float>& range_m, std::vector<glm::vec3>& normal, std::vector<std::uint16_t>& semantic,
                       std::vector<std::uint16_t>& instance) const
{
    const std::size_t pixels = std::size_t(size_.x) * std::size_t(size_.y);
    std::vector<float> rangeNormal(pixels * 4);
    {
        const PackedRows packed;
        glGetTextureImage(rangeNormal_.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rangeNormal.size() * sizeof(float)),
                          rangeNormal.data());
    }
    flipRows(rangeNormal, size_, 4);
    const std::vector<std::uint16_t> classInstance = readClassInstance();
    range_m.resize(pixels);
    normal.resize(pixels);
    semantic.resize(pixels);
    instance.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        range_m[i] = rangeNormal[4 * i];
        normal[i] = glm::vec3(rangeNormal[4 * i + 1], rangeNormal[4 * i + 2], rangeNormal[4 * i + 3]);
        semantic[i] = classInstance[2 * i];
        instance[i] = classInstance[2 * i + 1];
    }
}

} // namespace swell::detail
