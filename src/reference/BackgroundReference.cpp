#include "reference/BackgroundReference.h"

#include <stdexcept>

namespace penumbra::reference {

BackgroundReference::BackgroundReference(const scene::Scene& scene, int width, int height, float time, int samples)
    : scene_(scene), width_(width), height_(height), comparison_(std::make_unique<Comparison>(scene_, width, height, time)) {
    tracer_ = std::thread([this, samples] {
        try {
            comparison_->traceReference(samples, false, [this](double share) { progress_.store(share); });
        } catch (const std::exception& e) {  // reported by image(), not lost with the thread
            error_ = e.what();
        }
        progress_.store(1.0);
        ready_.store(true);
    });
}

BackgroundReference::~BackgroundReference() { wait(); }

void BackgroundReference::wait() {
    if (tracer_.joinable()) tracer_.join();
}

std::vector<std::uint8_t> BackgroundReference::image() const {
    if (!ready()) throw std::logic_error("the reference is still being traced");
    if (!error_.empty()) throw std::runtime_error("the reference failed: " + error_);
    return comparison_->shade(comparison_->referenceVisibility());
}

std::vector<std::uint8_t> BackgroundReference::heatMap(const std::string& technique, const shadows::ParameterValues& parameters) {
    if (!ready()) throw std::logic_error("the reference is still being traced");
    if (!error_.empty()) throw std::runtime_error("the reference failed: " + error_);
    return comparison_->heatMap(comparison_->evaluate(technique, 0, 0, parameters));
}

}  // namespace penumbra::reference
