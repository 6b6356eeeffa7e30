#include "gl/Sampler.h"

namespace penumbra::gl {

Sampler::Sampler(GLenum minFilter, GLenum magFilter, bool depthCompare) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    object_ = Object<detail::deleteSampler>(id);
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, depthCompare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace penumbra::gl
