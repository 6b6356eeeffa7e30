#pragma once
// Move-only ownership of one GL object name. Every GL wrapper in this folder is built on it,
// so a GL name is deleted exactly once, when its owner goes away.
#include <epoxy/gl.h>

#include <atomic>
#include <utility>

namespace penumbra::gl {

// GL names alive in this process, all kinds together: the soak test watches it stay flat.
inline std::atomic<long> liveObjects{0};
inline long liveObjectCount() { return liveObjects.load(); }

using DeleteFn = void (*)(GLuint);

template <DeleteFn Delete>
class Object {
public:
    Object() = default;
    explicit Object(GLuint id) : id_(id) {
        if (id_ != 0) ++liveObjects;
    }
    ~Object() { reset(); }
    Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) {
            Delete(id_);
            --liveObjects;
        }
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace detail {
inline void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
inline void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
inline void deleteProgram(GLuint id) { glDeleteProgram(id); }
inline void deleteShader(GLuint id) { glDeleteShader(id); }
inline void deleteSampler(GLuint id) { glDeleteSamplers(1, &id); }
}  // namespace detail

}  // namespace penumbra::gl
