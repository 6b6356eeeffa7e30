#pragma once
// GPU time of each pass of a frame, read a few frames late from a ring of GL_TIME_ELAPSED
// queries so that collecting it never stalls the pipeline (a blocking read after every frame
// lets a GPU idle between frames and drop to its idle clock).
//
// Two corrections for llvmpipe (docs: PLATFORM.md "Timing on llvmpipe"):
// - a glFlush() right after glBeginQuery, so that the query's start is stamped before the pass's
//   draws are binned; without it a query can time only the last tiles of the pass;
// - calibration mode: a glFinish() before and after every pass and a wall clock around it, so
//   that each query can be checked against the time the pass really took.
#include "gl/TimerQuery.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <vector>

namespace penumbra::render {

enum class Pass { Shadow = 0, Opaque, Translucent, Post };
inline constexpr int kPassCount = 4;
const char* toString(Pass pass);  // "shadow", "opaque", "translucent", "post"

struct PassTimes {
    double shadowMs = 0, opaqueMs = 0, translucentMs = 0, postMs = 0;
    double totalMs() const { return shadowMs + opaqueMs + translucentMs + postMs; }
    double& operator[](Pass p);
    double operator[](Pass p) const;
    PassTimes& operator+=(const PassTimes& other) {
        for (int p = 0; p < kPassCount; ++p) (*this)[Pass(p)] += other[Pass(p)];
        return *this;
    }
};

// One finished frame: GPU query times, and (calibration mode only) glFinish wall-clock times.
struct FrameTimes {
    std::uint64_t frame = 0;
    PassTimes gpu;
    PassTimes wall;  // zero unless calibrating
};

class FrameTimer {
public:
    static constexpr int kRingDepth = 6;  // frames whose queries may be in flight at once

    // Calibration measures the cost of an empty glFinish round trip first and subtracts it from
    // every pass's wall time (on llvmpipe about 0.1-0.2 ms: waking the rasteriser threads).
    void setCalibration(bool on);
    double finishOverheadMs() const { return finishOverheadMs_; }
    bool calibrating() const { return calibrate_; }

    void beginFrame(std::uint64_t frame);
    void begin(Pass pass);
    void end(Pass pass);
    void endFrame();

    // Finished frames since the last call, oldest first (non-blocking).
    std::vector<FrameTimes> takeFinished();
    // The newest finished frame's times (non-blocking; zero before any).
    const PassTimes& latest() const { return latest_.gpu; }
    // Blocks until every frame begun so far has its times, then returns the newest.
    const FrameTimes& waitForAll();

private:
    struct Slot {
        std::array<gl::TimerQuery, kPassCount> queries;
        FrameTimes times;
        bool pending = false;
    };
    bool harvest(Slot& slot, bool wait);
    void harvestInOrder(bool wait);

    std::array<Slot, kRingDepth> ring_;
    int current_ = -1;
    std::uint64_t frames_ = 0;
    bool calibrate_ = false;
    double finishOverheadMs_ = 0;
    std::chrono::steady_clock::time_point passStart_;
    FrameTimes latest_;
    std::deque<FrameTimes> finished_;
};

}  // namespace penumbra::render
