#include "render/FrameTimer.h"

#include <algorithm>

namespace penumbra::render {

const char* toString(Pass pass) {
    switch (pass) {
        case Pass::Shadow: return "shadow";
        case Pass::Opaque: return "opaque";
        case Pass::Translucent: return "translucent";
        case Pass::Post: return "post";
    }
    return "?";
}

double& PassTimes::operator[](Pass p) {
    switch (p) {
        case Pass::Shadow: return shadowMs;
        case Pass::Opaque: return opaqueMs;
        case Pass::Translucent: return translucentMs;
        case Pass::Post: break;
    }
    return postMs;
}

double PassTimes::operator[](Pass p) const { return const_cast<PassTimes&>(*this)[p]; }

void FrameTimer::setCalibration(bool on) {
    calibrate_ = on;
    if (!on) return;
    std::vector<double> trips;
    for (int i = 0; i < 21; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        glFlush();
        glFinish();
        trips.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::nth_element(trips.begin(), trips.begin() + 10, trips.end());
    finishOverheadMs_ = trips[10];
}

// Reads a slot's queries once all are available (or, with `wait`, blocks for them).
bool FrameTimer::harvest(Slot& slot, bool wait) {
    if (!slot.pending) return false;
    if (!wait) {
        GLuint available = 0;  // the last query ends last: when it is in, all are
        glGetQueryObjectuiv(slot.queries[kPassCount - 1].id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return false;
    }
    for (int p = 0; p < kPassCount; ++p) slot.times.gpu[static_cast<Pass>(p)] = slot.queries[static_cast<std::size_t>(p)].milliseconds();
    slot.pending = false;
    latest_ = slot.times;
    finished_.push_back(slot.times);
    if (finished_.size() > 4096) finished_.pop_front();  // nobody is collecting: keep memory flat
    return true;
}

void FrameTimer::beginFrame(std::uint64_t frame) {
    // Collect whatever has finished, oldest first, then claim the next slot; it waits only when
    // the GPU is kRingDepth frames behind.
    harvestInOrder(false);
    current_ = (current_ + 1) % kRingDepth;
    Slot& slot = ring_[static_cast<std::size_t>(current_)];
    harvest(slot, true);
    slot.times = FrameTimes{.frame = frame};
    ++frames_;
}

void FrameTimer::begin(Pass pass) {
    if (calibrate_) {
        glFinish();
        passStart_ = std::chrono::steady_clock::now();
    }
    ring_[static_cast<std::size_t>(current_)].queries[static_cast<std::size_t>(pass)].begin();
    glFlush();  // llvmpipe: stamp the start before the pass's draws are binned
}

void FrameTimer::end(Pass pass) {
    Slot& slot = ring_[static_cast<std::size_t>(current_)];
    slot.queries[static_cast<std::size_t>(pass)].end();
    if (calibrate_) {
        glFinish();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - passStart_).count();
        slot.times.wall[pass] = std::max(0.0, ms - finishOverheadMs_);
    }
}

void FrameTimer::endFrame() { ring_[static_cast<std::size_t>(current_)].pending = true; }

// Oldest slot first, stopping at the first still running, so frames come out in order.
void FrameTimer::harvestInOrder(bool wait) {
    for (int i = 1; i <= kRingDepth; ++i) {
        Slot& slot = ring_[static_cast<std::size_t>((current_ + i + kRingDepth) % kRingDepth)];
        if (slot.pending && !harvest(slot, wait)) return;
    }
}

std::vector<FrameTimes> FrameTimer::takeFinished() {
    harvestInOrder(false);
    std::vector<FrameTimes> out(finished_.begin(), finished_.end());
    finished_.clear();
    return out;
}

const FrameTimes& FrameTimer::waitForAll() {
    harvestInOrder(true);
    return latest_;
}

}  // namespace penumbra::render
