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

void VolumeCache::capture(Capture& capture, std::size_t mostTriangles, const std::function<void()>& draw) {
    const std::size_t room = std::max<std::size_t>(mostTriangles, 1) * 3 * kStride;
    if (scratch_.size() < room) scratch_ = gl::Buffer(room, nullptr, 0);
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, scratch_.id(), 0, static_cast<GLsizeiptr>(room));
    // Strips are written as separate triangles, and counted so.
    const GLuint64 written = counted(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, [&] {
        glBeginTransformFeedback(GL_TRIANGLES);
        draw();
        glEndTransformFeedback();
    });
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glDisable(GL_RASTERIZER_DISCARD);
    const std::size_t bytes = static_cast<std::size_t>(written) * 3 * kStride;
    capture.buffer = gl::Buffer(std::max<std::size_t>(bytes, kStride), nullptr, 0);
    if (bytes > 0) glCopyNamedBufferSubData(scratch_.id(), capture.buffer.id(), 0, 0, static_cast<GLsizeiptr>(bytes));
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
    std::size_t bytes = scratch_.size();
    for (const Entry& e : entries_) bytes += e.sides.buffer.size() + e.caps.buffer.size();
    return bytes;
}

}  // namespace penumbra::shadows
