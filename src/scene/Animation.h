#pragma once
// Looping keyframe trajectories. Positions are interpolated with a centripetal-free uniform
// Catmull-Rom spline (smooth, passes through every key); rotations (Euler degrees) likewise.
#include <glm/glm.hpp>

#include <vector>

namespace penumbra::scene {

struct Keyframe {
    float time;
    glm::vec3 value;
};

class Track {
public:
    Track() = default;
    explicit Track(std::vector<Keyframe> keys);  // keys sorted by time; throws on bad input
    bool empty() const { return keys_.empty(); }
    float duration() const { return keys_.empty() ? 0.0f : keys_.back().time - keys_.front().time; }
    // Value at time t; the track loops over [first key, last key].
    glm::vec3 sample(float t) const;

private:
    std::vector<Keyframe> keys_;
};

struct Animation {
    Track position;
    Track rotationDeg;
    bool empty() const { return position.empty() && rotationDeg.empty(); }
};

}  // namespace penumbra::scene
