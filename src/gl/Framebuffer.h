#pragma once
#include "gl/Object.h"
#include "gl/Texture.h"

#include <initializer_list>
#include <string>

namespace penumbra::gl {

// A framebuffer object assembled from textures it does not own.
class Framebuffer {
public:
    Framebuffer();
    // One colour texture (draw buffer 0) and one depth texture, checked complete (`what` names it).
    static Framebuffer colourAndDepth(const Texture& colour, const Texture& depth, const std::string& what);
    // One colour texture as draw buffer 0, checked complete: a whole 2D texture (`layer` < 0) or
    // one layer / cube face of it, at mip level `level`.
    static Framebuffer colourOnly(const Texture& colour, int layer, const std::string& what, int level = 0);
    void attach(GLenum attachment, const Texture& texture, int level = 0);
    void attachLayer(GLenum attachment, const Texture& texture, int layer, int level = 0);
    void setDrawBuffers(std::initializer_list<GLenum> buffers);
    void setNoColor();
    // Throws std::runtime_error naming `what` when the framebuffer is incomplete.
    void checkComplete(const std::string& what) const;
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }
    // Binds, sets the viewport and clears depth to 1: the start of every depth-only pass (shadow
    // maps, camera pre-passes), inside the pass's ScopedPassState (depth writes must be on).
    void beginDepthPass(int width, int height) const;
    GLuint id() const { return object_.id(); }

private:
    Object<detail::deleteFramebuffer> object_;
};

}  // namespace penumbra::gl
