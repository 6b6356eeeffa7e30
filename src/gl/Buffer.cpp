#include "gl/Buffer.h"

namespace penumbra::gl {

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags) : bytes_(bytes) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    object_ = Object<detail::deleteBuffer>(id);
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), data, flags);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

}  // namespace penumbra::gl
