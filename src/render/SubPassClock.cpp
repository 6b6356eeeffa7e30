#include "render/SubPassClock.h"

#include "gl/Debug.h"

#include <algorithm>
#include <epoxy/gl.h>
#include <stdexcept>

namespace penumbra::render {

namespace {
SubPassClock* g_clock = nullptr;
}

SubPassClock::SubPassClock(double finishOverheadMs) : finishOverheadMs_(finishOverheadMs) {
    if (g_clock) throw std::logic_error("one SubPassClock at a time");
    g_clock = this;
    gl::setDebugGroupHook(&SubPassClock::onGroup);
}

SubPassClock::~SubPassClock() {
    gl::setDebugGroupHook(nullptr);
    g_clock = nullptr;
}

void SubPassClock::onGroup(const char* openedName) {
    if (!g_clock) return;
    if (openedName) g_clock->open(openedName);
    else g_clock->close();
}

void SubPassClock::finish() {
    glFinish();
    for (Open& o : open_) ++o.finishes;
}

void SubPassClock::open(const char* name) {
    finish();  // what came before the group is not the group's
    const std::string path = open_.empty() ? std::string(name) : open_.back().path + "/" + name;
    open_.push_back({path, Clock::now(), 0});
}

void SubPassClock::close() {
    if (open_.empty()) return;  // a group opened before the clock started
    finish();
    const Open o = open_.back();
    open_.pop_back();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - o.start).count();
    totalMs_[o.path] += std::max(0.0, ms - finishOverheadMs_ * o.finishes);
}

std::map<std::string, double> SubPassClock::perFrame(int frames) const {
    std::map<std::string, double> mean;
    for (const auto& [path, ms] : totalMs_) mean[path] = ms / std::max(1, frames);
    return mean;
}

}  // namespace penumbra::render
