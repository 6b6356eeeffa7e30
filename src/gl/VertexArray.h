#pragma once
#include "gl/Object.h"

namespace penumbra::gl {

class VertexArray {
public:
    VertexArray();
    GLuint id() const { return object_.id(); }
    void bind() const { glBindVertexArray(id()); }
    // Float attribute `index` read from vertex buffer binding `binding` at `offset` bytes.
    void attribute(GLuint index, GLuint binding, int components, GLuint offset);

private:
    Object<detail::deleteVertexArray> object_;
};

}  // namespace penumbra::gl
