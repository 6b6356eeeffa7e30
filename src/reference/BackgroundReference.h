#pragma once
// The ray-traced reference of one frozen frame, traced on worker threads while the caller goes on
// drawing (the window's reference mode, issue 13). The constructor runs on the GL thread: it
// captures the G-buffer of a private copy of the scene, so editing or animating the live scene
// cannot race the tracer. Then progress() climbs to 1 and ready() turns true.
#include "reference/Comparison.h"

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace penumbra::reference {

class BackgroundReference {
public:
    BackgroundReference(const scene::Scene& scene, int width, int height, float time, int samples);
    ~BackgroundReference();  // waits for the tracer (it stops only between lights once cancelled)
    BackgroundReference(const BackgroundReference&) = delete;
    BackgroundReference& operator=(const BackgroundReference&) = delete;

    double progress() const { return progress_.load(); }  // share traced, 0..1
    bool ready() const { return ready_.load(); }
    void wait();
    int width() const { return width_; }
    int height() const { return height_; }

    // Once ready(): the reference frame (RGBA8 sRGB, top row first), and the heat map of
    // |technique - reference| over it (GL thread: the technique is rendered for it).
    std::vector<std::uint8_t> image() const;
    std::vector<std::uint8_t> heatMap(const std::string& technique, const shadows::ParameterValues& parameters = {});

private:
    scene::Scene scene_;  // the frozen copy the comparison and the tracer read
    int width_, height_;
    std::unique_ptr<Comparison> comparison_;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> ready_{false};
    std::string error_;  // written by the tracer before ready_ turns true
    std::thread tracer_;
};

}  // namespace penumbra::reference
