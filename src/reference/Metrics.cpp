#include "reference/Metrics.h"

#include "util/Srgb.h"

#include <algorithm>
#include <cmath>

namespace penumbra::reference {

void VisibilityError::add(const std::vector<glm::vec3>& tech, const std::vector<glm::vec3>& ref,
                          const std::vector<bool>& mask) {
    for (std::size_t i = 0; i < ref.size(); ++i) {
        if (!mask[i]) continue;
        const glm::vec3 d = tech[i] - ref[i];
        squared_ += glm::dot(d, d) / 3.0;
        const float worst = glm::max(glm::max(std::abs(d.r), std::abs(d.g)), std::abs(d.b));
        wrong_ += worst > kWrongThreshold;
        ++count_;
        const float chroma = glm::max(glm::max(ref[i].r, ref[i].g), ref[i].b) - glm::min(glm::min(ref[i].r, ref[i].g), ref[i].b);
        if (chroma > kColouredChroma) {
            ++coloured_;
            colourAbs_ += (std::abs(d.r) + std::abs(d.g) + std::abs(d.b)) / 3.0;
        }
    }
}

double VisibilityError::rmse() const { return count_ ? std::sqrt(squared_ / static_cast<double>(count_)) : 0.0; }
double VisibilityError::wrongShare() const { return count_ ? static_cast<double>(wrong_) / static_cast<double>(count_) : 0.0; }
double VisibilityError::colourError() const { return coloured_ ? colourAbs_ / static_cast<double>(coloured_) : 0.0; }

void accumulateMaxError(std::vector<float>& maxError, const std::vector<glm::vec3>& tech, const std::vector<glm::vec3>& ref,
                        const std::vector<bool>& mask) {
    maxError.resize(ref.size(), 0.0f);
    for (std::size_t i = 0; i < ref.size(); ++i) {
        if (!mask[i]) continue;
        const glm::vec3 d = glm::abs(tech[i] - ref[i]);
        maxError[i] = std::max(maxError[i], std::max(std::max(d.r, d.g), d.b));
    }
}

// Rows are flipped here once: inputs are GL order (bottom first), PNGs are top first.
template <class F>
static std::vector<std::uint8_t> encode(int w, int h, F pixel) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 c = glm::clamp(pixel(static_cast<std::size_t>(y) * w + x), 0.0f, 1.0f);
            std::uint8_t* p = &out[(static_cast<std::size_t>(h - 1 - y) * w + x) * 4];
            p[0] = static_cast<std::uint8_t>(std::lround(c.r * 255));
            p[1] = static_cast<std::uint8_t>(std::lround(c.g * 255));
            p[2] = static_cast<std::uint8_t>(std::lround(c.b * 255));
            p[3] = 255;
        }
    return out;
}

std::vector<std::uint8_t> heatMap(const std::vector<float>& e, const std::vector<bool>& compared, int w, int h) {
    return encode(w, h, [&](std::size_t i) {
        if (!compared[i]) return glm::vec3(0.25f);
        const float t = std::clamp(e[i], 0.0f, 1.0f) * 3.0f;  // black -> red -> yellow -> white
        return glm::vec3(std::min(t, 1.0f), std::clamp(t - 1.0f, 0.0f, 1.0f), std::clamp(t - 2.0f, 0.0f, 1.0f));
    });
}

std::vector<std::uint8_t> encodeSrgb(const std::vector<glm::vec3>& lin, int w, int h) {
    return encode(w, h, [&](std::size_t i) { return util::linearToSrgb(lin[i]); });
}

std::vector<std::uint8_t> encodeLinear(const std::vector<glm::vec3>& v, int w, int h) {
    return encode(w, h, [&](std::size_t i) { return v[i]; });
}

std::vector<std::uint8_t> halve(const std::vector<std::uint8_t>& in, int w, int h) {
    const int hw = w / 2, hh = h / 2;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(hw) * hh * 4);
    for (int y = 0; y < hh; ++y)
        for (int x = 0; x < hw; ++x)
            for (int c = 0; c < 4; ++c) {
                int sum = 0;
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx) sum += in[((static_cast<std::size_t>(2 * y + dy) * w) + 2 * x + dx) * 4 + c];
                out[(static_cast<std::size_t>(y) * hw + x) * 4 + c] = static_cast<std::uint8_t>((sum + 2) / 4);
            }
    return out;
}

std::vector<std::uint8_t> montage(const std::vector<const std::vector<std::uint8_t>*>& images, int w, int h, int columns,
                                  int& outW, int& outH) {
    const int gap = 8;
    const int rows = (static_cast<int>(images.size()) + columns - 1) / columns;
    outW = columns * w + (columns - 1) * gap;
    outH = rows * h + (rows - 1) * gap;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(outW) * outH * 4, 255);
    for (std::size_t k = 0; k < images.size(); ++k) {
        const int ox = static_cast<int>(k) % columns * (w + gap), oy = static_cast<int>(k) / columns * (h + gap);
        for (int y = 0; y < h; ++y)
            std::copy_n(&(*images[k])[static_cast<std::size_t>(y) * w * 4], static_cast<std::size_t>(w) * 4,
                        &out[(static_cast<std::size_t>(oy + y) * outW + ox) * 4]);
    }
    return out;
}

}  // namespace penumbra::reference
