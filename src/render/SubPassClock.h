#pragma once
// The wall-clock time of every gl::DebugGroup of the frames drawn while a clock runs (a pass's
// parts: a light's depth and tint, a moment map's raster, blur and mip levels, CSSM's colour map),
// bounded by glFinish where each group opens and closes, keyed by its path of group names
// ("shadow maps/moments/blur"). The issue-15 "split timer queries per sub-pass": GL_TIME_ELAPSED
// queries cannot nest, and on llvmpipe a query inside a pass times its binning rather than its
// rasterisation (PLATFORM.md), so the groups are timed as bench --calibrate times whole passes.
// Every glFinish drains the pipeline: for calibration runs, not for the frames a bench measures.
#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace penumbra::render {

class SubPassClock {
public:
    // `finishOverheadMs`: an empty glFinish round trip (FrameTimer::finishOverheadMs), taken out
    // of each group once for each glFinish its interval holds. Listens to gl::DebugGroup until
    // destroyed; one clock at a time.
    explicit SubPassClock(double finishOverheadMs);
    ~SubPassClock();
    SubPassClock(const SubPassClock&) = delete;
    SubPassClock& operator=(const SubPassClock&) = delete;

    // Milliseconds per path, summed over every group that had it (a light's groups in every
    // frame), divided by `frames`.
    std::map<std::string, double> perFrame(int frames) const;

private:
    using Clock = std::chrono::steady_clock;
    struct Open {
        std::string path;
        Clock::time_point start;
        int finishes = 0;  // glFinish calls inside the interval, its closing one included
    };
    static void onGroup(const char* openedName);
    void finish();
    void open(const char* name);
    void close();

    double finishOverheadMs_;
    std::vector<Open> open_;
    std::map<std::string, double> totalMs_;
};

}  // namespace penumbra::render
