#include "scene/Animation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penumbra::scene {

Track::Track(std::vector<Keyframe> keys) : keys_(std::move(keys)) {
    for (std::size_t i = 1; i < keys_.size(); ++i)
        if (!(keys_[i].time > keys_[i - 1].time))
            throw std::invalid_argument("keyframe times must increase strictly");
}

glm::vec3 Track::sample(float t) const {
    if (keys_.empty()) return glm::vec3(0.0f);
    if (keys_.size() == 1) return keys_[0].value;
    const float t0 = keys_.front().time, len = duration();
    float local = std::fmod(t - t0, len);
    if (local < 0) local += len;
    local += t0;
    // Segment i covers [key i, key i+1].
    const auto it = std::upper_bound(keys_.begin(), keys_.end(), local,
                                     [](float v, const Keyframe& k) { return v < k.time; });
    const std::size_t n = keys_.size();
    const std::size_t i1 = std::min<std::size_t>(static_cast<std::size_t>(it - keys_.begin()), n - 1);
    const std::size_t i0 = i1 - 1;
    // Neighbours for the spline tangents; a closed loop when first and last keys coincide.
    const bool closed = glm::all(glm::lessThan(glm::abs(keys_.front().value - keys_.back().value), glm::vec3(1e-6f)));
    auto at = [&](long i) -> const glm::vec3& {
        const long last = static_cast<long>(n) - 1;
        if (closed) {  // skip the duplicated key when wrapping
            while (i < 0) i += last;
            while (i > last) i -= last;
        }
        return keys_[static_cast<std::size_t>(std::clamp(i, 0L, last))].value;
    };
    const float span = keys_[i1].time - keys_[i0].time;
    const float s = span > 0 ? (local - keys_[i0].time) / span : 0.0f;
    const glm::vec3 p0 = at(static_cast<long>(i0) - 1), p1 = at(static_cast<long>(i0)),
                    p2 = at(static_cast<long>(i1)), p3 = at(static_cast<long>(i1) + 1);
    const float s2 = s * s, s3 = s2 * s;
    return 0.5f * ((2.0f * p1) + (-p0 + p2) * s + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * s2 +
                   (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * s3);
}

}  // namespace penumbra::scene
