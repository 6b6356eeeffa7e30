#include "shadows/pcf/PercentageCloserFilter.h"

#include "gpu/ShaderContract.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>

namespace penumbra::shadows {

PercentageCloserFilter::PercentageCloserFilter(std::string name, Kernel kernel, int taps)
    : name_(std::move(name)), kernel_(kernel), taps_(taps) {
    if (kernel == Kernel::Bilinear) maps_.setFiltering(GL_LINEAR);
    if (kernel == Kernel::Grid || kernel == Kernel::Gaussian) kernelSize_ = taps;
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

std::vector<Parameter> PercentageCloserFilter::declareParameters() {
    std::vector<Parameter> p{
        Parameter::real("radius_texels", radiusTexels_, 0.0f, 16.0f, "filter radius in shadow-map texels"),
        Parameter::real("radius_world", radiusWorld_, 0.0f, 2.0f, "> 0: filter radius in world units instead of texels"),
        Parameter::flag("receiver_plane_bias", receiverPlane_,
                        "extrapolate the receiver's depth along its plane to every tap (Isidoro 2006)")};
    for (Parameter& q : skipAgreeingParameters("skip the taps where depth bounds of the receiver's tile show they all agree"))
        p.push_back(std::move(q));
    if (kernel_ == Kernel::Grid || kernel_ == Kernel::Gaussian)
        p.push_back(Parameter::integer("kernel_size", kernelSize_, 1, 9, "N of the N x N grid"));
    if (kernel_ == Kernel::Poisson || kernel_ == Kernel::Random || kernel_ == Kernel::Rotated || kernel_ == Kernel::Adaptive)
        p.push_back(Parameter::integer("taps", taps_, 4, PoissonDisk::kPoints, "taps per lookup"));
    return p;
}

std::vector<std::string> PercentageCloserFilter::lookupDefines() const {
    std::vector<std::string> defines{"PCF_KERNEL " + std::to_string(static_cast<int>(kernel_))};
    // The bilinear kernel filters the tint too (setFiltering): a translucent receiver weighs the
    // 2 x 2 texels' products with its own layers divided out (tintAt, bilinearThroughOwnLayers).
    if (kernel_ == Kernel::Bilinear) defines.emplace_back("SHADOW_TINT_LINEAR 1");
    return defines;
}

// The farthest tap in any direction (tapReach's along x or y, times the diagonal's sqrt 2; a
// radius in world units is bounded by no count of texels) and its compare's texels.
float PercentageCloserFilter::shadowReachTexels() const {
    if (kernel_ == Kernel::Bilinear) return 2.0f;
    if (radiusWorld_ > 0.0f) return -1.0f;
    return radiusTexels_ * std::sqrt(2.0f) * tapReach() + 2.0f;
}

// How far, along x or y, the kernel's taps reach in units of its radius: tapsAgree() bounds the
// texels within that of the receiver, and bounds over a smaller box are tighter.
float PercentageCloserFilter::tapReach() const {
    const auto& points = poisson_.points();
    const std::size_t taps = static_cast<std::size_t>(std::clamp(taps_, 1, PoissonDisk::kPoints));
    float axis = 0.0f, length = 0.0f;  // over the Poisson taps in use
    for (std::size_t i = 0; i < taps; ++i) {
        axis = std::max({axis, std::abs(points[i].x), std::abs(points[i].y)});
        length = std::max(length, glm::length(points[i]));
    }
    switch (kernel_) {
        case Kernel::Poisson: case Kernel::Dither: return axis;
        case Kernel::Rotated: return length;  // any turn of the disk
        case Kernel::Adaptive: return std::max(axis, 0.7072f);  // the ring probes at 45 degrees (cos, rounded up)
        default: return 1.0f;  // grid corners, unit-disk random and jittered taps
    }
}

void PercentageCloserFilter::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    bindTileBounds(lighting);
    lighting.set("uTapReach", tapReach());
    lighting.set("uKernelSize", kernelSize_);
    lighting.set("uTaps", std::clamp(taps_, 1, PoissonDisk::kPoints));
    lighting.set("uRadiusTexels", radiusTexels_);
    lighting.set("uRadiusWorld", radiusWorld_);
    lighting.set("uReceiverPlane", receiverPlane_ ? 1 : 0);
    poisson_.upload(lighting);
    if (jitter_.id()) jitter_.bind(gpu::kUnitJitter);
}

}  // namespace penumbra::shadows
