#pragma once
// Shadow volumes of still casters under still lights, kept across frames. A volume depends on its
// caster, the caster's transform and the light, not on the camera: the geometry shader's output
// (volume.geom: silhouettes found and extruded, caps) is captured once in world space by
// transform feedback and drawn again each frame with a bare vertex shader (volume_kept.vert).
// Only the stencil count is redone, as the camera moves. Doom 3 kept the volumes of static lights
// and static geometry the same way (precomputed at map compile time). A caster or light that
// moved since the last frame is drawn through the geometry shader as before; one that then holds
// still for a frame is captured.
#include "gl/Buffer.h"
#include "gl/VertexArray.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace penumbra::shadows {

class VolumeCache {
public:
    // What a volume is made of: equal keys, equal volumes.
    struct Key {
        glm::mat4 model{0.0f};
        glm::vec4 light{0.0f}, farPlane{0.0f};
        float extrusion = 0.0f;
        bool operator==(const Key&) const = default;
    };
    // One capture: the triangles volume.geom emitted for one `uEmit` (sides, or caps).
    struct Capture {
        gl::Buffer buffer;
        gl::VertexArray vao;
        int vertices = -1;  // -1: not captured yet
    };
    struct Entry {
        Key key;
        Capture sides, caps;
    };

    // Forget everything (a new scene) and hold `lights` x `objects` entries.
    void reset(std::size_t lights, std::size_t objects);
    // reset() if the counts differ from what it holds.
    void fit(std::size_t lights, std::size_t objects);
    // The entry of `object` under `light` if its volume is the one it held last frame (`key`
    // equal); otherwise nullptr, and the entry starts over from `key`.
    Entry* still(std::size_t light, std::size_t object, const Key& key);
    // Captures what `draw` makes the bound volume program emit (its uniforms set by the caller)
    // into `capture`, with the rasteriser off. `mostTriangles`: at most how many it can emit
    // (6 per triangle drawn for sides, 2 for caps): the capture goes to a scratch buffer that
    // size, then what was written is copied into a buffer of its own, exactly as large.
    void capture(Capture& capture, std::size_t mostTriangles, const std::function<void()>& draw);
    // Lets the scratch buffer go: call once a frame's captures are done (a still scene captures
    // once, so holding the room would only cost memory).
    void releaseScratch() { scratch_ = gl::Buffer(); }
    // Draws a capture with volume_kept.vert's program bound.
    static void draw(const Capture& capture);
    std::size_t memoryBytes() const;

private:
    std::size_t lights_ = 0, objects_ = 0;
    gl::Buffer scratch_;  // room for this frame's largest capture so far
    std::vector<Entry> entries_;  // light-major
};

}  // namespace penumbra::shadows
