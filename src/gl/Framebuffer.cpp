#include "gl/Framebuffer.h"

#include <stdexcept>
#include <vector>

namespace penumbra::gl {

Framebuffer::Framebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    object_ = Object<detail::deleteFramebuffer>(id);
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int level) {
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::attachLayer(GLenum attachment, const Texture& texture, int layer, int level) {
    glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(std::initializer_list<GLenum> buffers) {
    std::vector<GLenum> list(buffers);
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(list.size()), list.data());
}

void Framebuffer::setNoColor() {
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
    glNamedFramebufferReadBuffer(id(), GL_NONE);
}

void Framebuffer::checkComplete(const std::string& what) const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(what + ": framebuffer incomplete (status 0x" +
                                 std::to_string(status) + ")");
}

Framebuffer Framebuffer::colourAndDepth(const Texture& colour, const Texture& depth, const std::string& what) {
    Framebuffer f;
    f.attach(GL_COLOR_ATTACHMENT0, colour);
    f.attach(GL_DEPTH_ATTACHMENT, depth);
    f.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    f.checkComplete(what);
    return f;
}

Framebuffer Framebuffer::colourOnly(const Texture& colour, int layer, const std::string& what, int level) {
    Framebuffer f;
    if (layer >= 0) f.attachLayer(GL_COLOR_ATTACHMENT0, colour, layer, level);
    else f.attach(GL_COLOR_ATTACHMENT0, colour, level);
    f.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    f.checkComplete(what);
    return f;
}

void Framebuffer::beginDepthPass(int width, int height) const {
    bind();
    glViewport(0, 0, width, height);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(id(), GL_DEPTH, 0, &farDepth);
}

}  // namespace penumbra::gl
