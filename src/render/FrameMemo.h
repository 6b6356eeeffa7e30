#pragma once
// Values worked out from a frame's inputs, kept across frames for as long as frames ask for them:
// what one frame did not ask for is dropped at the next (nextFrame), so a moving object's old
// entries go while a still one's are worked out once. Keys are util::Digest values of every input
// the value depends on, as the shadow maps' reuse keys are (shadows/common/DepthAndTintMaps).
// Used by the renderer for the world-space cells of tint footprints and lights' reach
// (render/TintReach.h), which depend on objects and lights, not on the camera itself.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace penumbra::render {

template <class Value>
class FrameMemo {
public:
    // The entry for `key`: this frame's or the last one's (then kept for the next), else a new,
    // value-initialised one that the caller fills (`made` says which).
    Value& at(std::uint64_t key, bool& made) {
        if (auto it = current_.find(key); it != current_.end()) {
            made = false;
            return it->second;
        }
        if (auto it = previous_.find(key); it != previous_.end()) {
            made = false;
            Value& kept = current_.emplace(key, std::move(it->second)).first->second;
            previous_.erase(it);
            return kept;
        }
        made = true;
        ++made_;
        return current_[key];
    }
    // Entries the last frame asked for stay one frame more; older ones are dropped.
    void nextFrame() {
        previous_ = std::move(current_);
        current_.clear();
        made_ = 0;
    }
    std::size_t madeThisFrame() const { return made_; }
    std::size_t size() const { return current_.size() + previous_.size(); }

private:
    std::unordered_map<std::uint64_t, Value> current_, previous_;
    std::size_t made_ = 0;
};

}  // namespace penumbra::render
