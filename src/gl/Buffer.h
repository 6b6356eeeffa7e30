#pragma once
#include "gl/Object.h"

#include <cstddef>
#include <span>

namespace penumbra::gl {

// An immutable-storage buffer (glNamedBufferStorage), optionally updatable with SubData.
class Buffer {
public:
    Buffer() = default;
    Buffer(std::size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
    template <class T>
    explicit Buffer(std::span<const T> items, GLbitfield flags = 0)
        : Buffer(items.size_bytes(), items.data(), flags) {}

    void update(std::size_t offset, std::size_t bytes, const void* data);
    void bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }
    GLuint id() const { return object_.id(); }
    std::size_t size() const { return bytes_; }

private:
    Object<detail::deleteBuffer> object_;
    std::size_t bytes_ = 0;
};

}  // namespace penumbra::gl
