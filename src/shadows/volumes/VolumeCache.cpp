#include "shadows/volumes/VolumeCache.h"

#include "gl/Object.h"

#include <algorithm>

namespace penumbra::shadows {

namespace {

constexpr GLsizei kStride = 5 * sizeof(float);  // volume.geom's gWorld (vec4) and gNudge

// Runs `draw` inside a query of `target` and returns its count (waits for it: once per capture).
GLuint64 counted(GLenum target, const std::function<void()>& draw) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    const gl::Object<gl::detail::deleteQuery> query(id);
    glBeginQuery(target, id);
    draw();
    glEndQuery(target);
    GLuint64 n = 0;
    glGetQueryObjectui64v(id, GL_QUERY_RESULT, &n);
    return n;
}

}  // namespace

void VolumeCache::reset(std::size_t lights, std::size_t objects) {
    lights_ = lights;
    objects_ = objects;
    entries_.clear();
    entries_.resize(lights * objects);
}

void VolumeCache::fit(std::size_t lights, std::size_t objects) {
    if (lights != lights_ || objects != objects_) reset(lights, objects);
}

VolumeCache::Entry* VolumeCache::still(std::size_t light, std::size_t object, const Key& key) {
    const std::size_t i = light * objects_ + object;
    if (object >= objects_ || i >= entries_.size()) return nullptr;
    Entry& e = entries_[i];
    if (e.key == key) return &e;
    e.key = key;
    for (Capture* c : {&e.sides, &e.caps}) {
        c->buffer = gl::Buffer();
        c->vertices = -1;
    }
    return nullptr;
}

void VolumeCache::capture(Capture& capture, const std::function<void()>& draw) {
    glEnable(GL_RASTERIZER_DISCARD);
    // Strips come out as separate triangles; the first run only counts them, to size the buffer.
    const GLuint64 triangles = counted(GL_PRIMITIVES_GENERATED, draw);
    capture.buffer = gl::Buffer(static_cast<std::size_t>(std::max<GLuint64>(triangles, 1)) * 3 * kStride, nullptr, 0);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, capture.buffer.id());
    const GLuint64 written = counted(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, [&] {
        glBeginTransformFeedback(GL_TRIANGLES);
        draw();
        glEndTransformFeedback();
    });
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glDisable(GL_RASTERIZER_DISCARD);
    capture.vertices = static_cast<int>(written * 3);
    glVertexArrayVertexBuffer(capture.vao.id(), 0, capture.buffer.id(), 0, kStride);
    capture.vao.attribute(0, 0, 4, 0);
    capture.vao.attribute(1, 0, 1, 4 * sizeof(float));
}

void VolumeCache::draw(const Capture& capture) {
    if (capture.vertices <= 0) return;
    capture.vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, capture.vertices);
}

std::size_t VolumeCache::memoryBytes() const {
    std::size_t bytes = 0;
    for (const Entry& e : entries_) bytes += e.sides.buffer.size() + e.caps.buffer.size();
    return bytes;
}

}  // namespace penumbra::shadows
