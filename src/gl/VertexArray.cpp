#include "gl/VertexArray.h"

namespace penumbra::gl {

VertexArray::VertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    object_ = Object<detail::deleteVertexArray>(id);
}

void VertexArray::attribute(GLuint index, GLuint binding, int components, GLuint offset) {
    glEnableVertexArrayAttrib(id(), index);
    glVertexArrayAttribFormat(id(), index, components, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(id(), index, binding);
}

}  // namespace penumbra::gl
