#pragma once
#include "gl/Object.h"

namespace penumbra::gl {

// A sampler object: overrides a texture's own filtering while bound to a unit. Used to read
// depth maps as plain values (no hardware comparison) next to their compare lookups.
class Sampler {
public:
    Sampler(GLenum minFilter, GLenum magFilter, bool depthCompare = false);
    GLuint id() const { return object_.id(); }
    void bind(GLuint unit) const { glBindSampler(unit, id()); }
    static void unbind(GLuint unit) { glBindSampler(unit, 0); }

private:
    Object<detail::deleteSampler> object_;
};

}  // namespace penumbra::gl
