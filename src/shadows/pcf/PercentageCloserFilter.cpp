#include "shadows/pcf/PercentageCloserFilter.h"

#include "render/Bindings.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>

namespace penumbra::shadows {

namespace {

// Bridson 2007 in the square [-1,1]^2 restricted to the unit disk.
std::vector<glm::vec2> bridson(float r, std::mt19937& rng) {
    const int k = 30;
    const float cell = r / std::sqrt(2.0f);
    const int n = static_cast<int>(std::ceil(2.0f / cell));
    std::vector<int> grid(static_cast<std::size_t>(n * n), -1);
    std::vector<glm::vec2> points, active;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto cellOf = [&](glm::vec2 p) {
        return glm::ivec2(std::clamp(static_cast<int>((p.x + 1) / cell), 0, n - 1),
                          std::clamp(static_cast<int>((p.y + 1) / cell), 0, n - 1));
    };
    auto fits = [&](glm::vec2 p) {
        if (glm::length(p) > 1.0f) return false;
        const glm::ivec2 c = cellOf(p);
        for (int y = std::max(0, c.y - 2); y <= std::min(n - 1, c.y + 2); ++y)
            for (int x = std::max(0, c.x - 2); x <= std::min(n - 1, c.x + 2); ++x) {
                const int i = grid[static_cast<std::size_t>(y * n + x)];
                if (i >= 0 && glm::length(points[static_cast<std::size_t>(i)] - p) < r) return false;
            }
        return true;
    };
    auto add = [&](glm::vec2 p) {
        const glm::ivec2 c = cellOf(p);
        grid[static_cast<std::size_t>(c.y * n + c.x)] = static_cast<int>(points.size());
        points.push_back(p);
        active.push_back(p);
    };
    add({0.0f, 0.0f});
    while (!active.empty()) {
        const std::size_t pick = static_cast<std::size_t>(unit(rng) * static_cast<float>(active.size())) % active.size();
        const glm::vec2 base = active[pick];
        bool found = false;
        for (int t = 0; t < k && !found; ++t) {
            const float a = unit(rng) * glm::two_pi<float>(), d = r * (1.0f + unit(rng));
            const glm::vec2 p = base + d * glm::vec2(std::cos(a), std::sin(a));
            if (fits(p)) {
                add(p);
                found = true;
            }
        }
        if (!found) active.erase(active.begin() + static_cast<long>(pick));
    }
    return points;
}

}  // namespace

std::vector<glm::vec2> poissonDisk(int count, std::uint32_t seed) {
    // The densest packing of `count` disks in the unit disk has spacing ~ sqrt(pi / count)
    // (hexagonal: 0.91 coverage); start there and shrink until enough points fit.
    float r = 1.7f / std::sqrt(static_cast<float>(count));
    for (int attempt = 0; attempt < 200; ++attempt, r *= 0.97f) {
        std::mt19937 rng(seed);
        std::vector<glm::vec2> pts = bridson(r, rng);
        if (static_cast<int>(pts.size()) >= count) {
            pts.resize(static_cast<std::size_t>(count));
            return pts;
        }
    }
    return std::vector<glm::vec2>(static_cast<std::size_t>(count), glm::vec2(0.0f));
}

PercentageCloserFilter::PercentageCloserFilter(std::string name, Kernel kernel, int taps)
    : name_(std::move(name)), kernel_(kernel), taps_(static_cast<float>(taps)), poisson_(poissonDisk(32)) {
    if (kernel == Kernel::Bilinear) maps_.setFiltering(GL_LINEAR);
    if (kernel == Kernel::Grid || kernel == Kernel::Gaussian) kernelSize_ = static_cast<float>(taps);
    if (kernel == Kernel::Jitter) {
        // 32x32 pixels x (taps/2) layers; each layer holds two jittered strata of an
        // sqrt(taps) x sqrt(taps) grid, warped onto the disk by x = sqrt(v) cos 2πu, y = sqrt(v) sin 2πu.
        const int layers = taps / 2, side = static_cast<int>(std::round(std::sqrt(static_cast<float>(taps))));
        std::vector<float> texels(static_cast<std::size_t>(32 * 32 * layers * 4));
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        for (int l = 0; l < layers; ++l)
            for (int p = 0; p < 32 * 32; ++p)
                for (int h = 0; h < 2; ++h) {
                    const int stratum = 2 * l + h;
                    const float u = (static_cast<float>(stratum % side) + unit(rng)) / static_cast<float>(side);
                    const float v = (static_cast<float>(stratum / side) + unit(rng)) / static_cast<float>(side);
                    float* t = &texels[(static_cast<std::size_t>(l) * 32 * 32 + static_cast<std::size_t>(p)) * 4 + 2 * h];
                    t[0] = std::sqrt(v) * std::cos(glm::two_pi<float>() * u);
                    t[1] = std::sqrt(v) * std::sin(glm::two_pi<float>() * u);
                }
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_3D, 1, &id);
        glTextureStorage3D(id, 1, GL_RGBA16F, 32, 32, layers);
        glTextureSubImage3D(id, 0, 0, 0, 0, 32, 32, layers, GL_RGBA, GL_FLOAT, texels.data());
        jitter_ = gl::Texture::adopt(GL_TEXTURE_3D, id, 32, 32, 32u * 32u * static_cast<std::size_t>(layers) * 8u);
        jitter_.setFilter(GL_NEAREST, GL_NEAREST);
    }
}

std::vector<Parameter> PercentageCloserFilter::parameters() {
    std::vector<Parameter> p{{"radius_texels", &radiusTexels_, 0.0f, 16.0f},
                             {"radius_world", &radiusWorld_, 0.0f, 2.0f},
                             {"receiver_plane_bias", &receiverPlane_, 0.0f, 1.0f}};
    if (kernel_ == Kernel::Grid || kernel_ == Kernel::Gaussian) p.push_back({"kernel_size", &kernelSize_, 1.0f, 9.0f});
    if (kernel_ == Kernel::Poisson || kernel_ == Kernel::Random || kernel_ == Kernel::Rotated || kernel_ == Kernel::Adaptive)
        p.push_back({"taps", &taps_, 4.0f, 32.0f});
    return p;
}

void PercentageCloserFilter::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    lighting.set("uKernel", static_cast<int>(kernel_));
    lighting.set("uKernelSize", static_cast<int>(std::lround(kernelSize_)));
    lighting.set("uTaps", std::clamp(static_cast<int>(std::lround(taps_)), 1, 32));
    lighting.set("uRadiusTexels", radiusTexels_);
    lighting.set("uRadiusWorld", radiusWorld_);
    lighting.set("uReceiverPlane", receiverPlane_ > 0.5f ? 1 : 0);
    glProgramUniform2fv(lighting.id(), lighting.location("uPoisson[0]"), static_cast<GLsizei>(poisson_.size()),
                        &poisson_[0].x);
    if (jitter_.id()) jitter_.bind(render::kUnitJitter);
}

}  // namespace penumbra::shadows
