#include "shadows/ShadowTechnique.h"
#include "shadows/cascaded/CascadedShadowMap.h"
#include "shadows/cssm/ColoredStochasticShadowMap.h"
#include "shadows/distance/DistanceSoftenedShadows.h"
#include "shadows/hard/HardShadowMap.h"
#include "shadows/moments/MomentShadowMap.h"
#include "shadows/none/NoShadows.h"
#include "shadows/pcf/PercentageCloserFilter.h"
#include "shadows/pcss/PercentageCloserSoftShadows.h"
#include "shadows/planar/PlanarProjectedShadows.h"
#include "shadows/volumes/ShadowVolumes.h"
#include "shadows/warped/WarpedShadowMap.h"

#include <algorithm>
#include <stdexcept>

namespace penumbra::shadows {

static TechniqueInfo pcf(const char* name, const char* description, PercentageCloserFilter::Kernel kernel, int taps) {
    return {name, description, [=] { return std::make_unique<PercentageCloserFilter>(name, kernel, taps); }};
}

static TechniqueInfo moments(const char* name, const char* description, MomentShadowMap::Warp warp) {
    return {name, description, [=] { return std::make_unique<MomentShadowMap>(name, warp); }};
}

const std::vector<TechniqueInfo>& techniqueRegistry() {
    static const std::vector<TechniqueInfo> registry = {
        {"hard", "shadow map (Williams 1978), hardware depth compare, coloured tint from translucent casters",
         [] { return std::make_unique<HardShadowMap>(); }},
        {"none", "no shadows: every light reaches every surface", [] { return std::make_unique<NoShadows>(); }},
        pcf("pcf-grid", "PCF, fixed NxN grid (3x3 = 9 taps)", PercentageCloserFilter::Kernel::Grid, 3),
        pcf("pcf-bilinear", "PCF, hardware bilinear 2x2 (sampler2DShadow + GL_LINEAR)", PercentageCloserFilter::Kernel::Bilinear, 1),
        pcf("pcf-gaussian", "PCF, Gaussian-weighted 5x5 grid", PercentageCloserFilter::Kernel::Gaussian, 5),
        pcf("pcf-poisson16", "PCF, Poisson disk 16 taps (Bridson 2007)", PercentageCloserFilter::Kernel::Poisson, 16),
        pcf("pcf-poisson20", "PCF, Poisson disk 20 taps", PercentageCloserFilter::Kernel::Poisson, 20),
        pcf("pcf-poisson32", "PCF, Poisson disk 32 taps", PercentageCloserFilter::Kernel::Poisson, 32),
        pcf("pcf-random30", "PCF, 30 uniform random taps per pixel", PercentageCloserFilter::Kernel::Random, 30),
        pcf("pcf-jitter", "PCF, jittered grid warped onto a disk, 3D jitter texture (GPU Gems 2 ch.17, OSG SoftShadowMap)",
            PercentageCloserFilter::Kernel::Jitter, 32),
        pcf("pcf-dither", "PCF, two 8-tap offset sets alternating in a checkerboard", PercentageCloserFilter::Kernel::Dither, 16),
        pcf("pcf-rotated", "PCF, 16-tap Poisson disk rotated per pixel (interleaved gradient noise)",
            PercentageCloserFilter::Kernel::Rotated, 16),
        pcf("pcf-adaptive", "PCF, 5-tap edge test, 32-tap Poisson only in the penumbra", PercentageCloserFilter::Kernel::Adaptive, 32),
        {"pcss", "percentage-closer soft shadows (Fernando 2005): blocker search, variable-size penumbra",
         [] { return std::make_unique<PercentageCloserSoftShadows>(); }},
        {"distance", "three 3x3 kernels chosen by caster-receiver distance (Nápravník 2020)",
         [] { return std::make_unique<DistanceSoftenedShadows>(); }},
        moments("vsm", "variance shadow maps (Donnelly & Lauritzen 2006), Gaussian pre-blur, mipmaps, bleeding reduction",
                MomentShadowMap::Warp::Variance),
        moments("esm", "exponential shadow maps (Annen et al. 2008)", MomentShadowMap::Warp::Exponential),
        moments("evsm2", "exponential variance shadow maps, positive warp (2 components)",
                MomentShadowMap::Warp::ExponentialVariance2),
        moments("evsm4", "exponential variance shadow maps, both warps (4 components)",
                MomentShadowMap::Warp::ExponentialVariance4),
        moments("msm", "moment shadow maps, Hamburger 4MSM (Peters & Klein 2015)", MomentShadowMap::Warp::Moments4),
        {"cascaded", "cascaded / parallel-split shadow maps (Zhang et al. 2006) for the sun, stabilised, blended",
         [] { return std::make_unique<CascadedShadowMap>(); }},
        {"lispsm", "light-space perspective shadow maps (Wimmer et al. 2004) for the sun, optimal n, uniform near degenerate angles",
         [] { return std::make_unique<WarpedShadowMap>("lispsm", WarpedShadowMap::Warp::Lispsm, 1, 1); }},
        {"lispsm-tiled", "the screen in cols x rows tiles (default 2x2), each tile's sub-frustum its own LiSPSM (Plachý 2012 §3.5)",
         [] { return std::make_unique<WarpedShadowMap>("lispsm-tiled", WarpedShadowMap::Warp::Lispsm, 2, 2); }},
        {"psm", "perspective shadow maps (Stamminger & Drettakis 2002) for the sun, inverted projection behind the viewer",
         [] { return std::make_unique<WarpedShadowMap>("psm", WarpedShadowMap::Warp::Psm, 1, 1); }},
        {"shadow-volumes", "stencil shadow volumes (Crow 1977): silhouettes from adjacency, z-fail with caps (Carmack) or z-pass",
         [] { return std::make_unique<ShadowVolumes>(); }},
        {"planar", "planar projected shadows (Blinn 1988) onto the largest flat receiver, stencil against spill and double blending",
         [] { return std::make_unique<PlanarProjectedShadows>(); }},
        {"cssm1", "coloured stochastic shadow maps (McGuire & Enderton 2011), one map per channel",
         [] { return std::make_unique<ColoredStochasticShadowMap>(ColoredStochasticShadowMap::Variant::PerChannel); }},
        {"cssm2", "coloured stochastic shadow maps, one RGB pass with MIN blending (Mátl 2013 ch. 5)",
         [] { return std::make_unique<ColoredStochasticShadowMap>(ColoredStochasticShadowMap::Variant::Rgb); }},
    };
    return registry;
}

std::string knownTechniqueNames() {
    std::string names;
    for (const auto& t : techniqueRegistry()) names += (names.empty() ? "" : ", ") + t.name;
    return names;
}

std::vector<Parameter> ShadowTechnique::parameters() {
    std::vector<Parameter> list = declareParameters();
    for (auto& p : list)
        for (const auto& [name, text] : defaults_)
            if (name == p.name) p.defaultText = text;
    return list;
}

void ShadowTechnique::captureDefaults() {
    defaults_.clear();
    for (const auto& p : declareParameters()) defaults_.emplace_back(p.name, p.text());
}

bool isKnownTechnique(const std::string& name) {
    for (const auto& t : techniqueRegistry())
        if (t.name == name) return true;
    return false;
}

std::unique_ptr<ShadowTechnique> createTechnique(const std::string& name) {
    for (const auto& t : techniqueRegistry())
        if (t.name == name) {
            auto technique = t.create();
            technique->captureDefaults();
            return technique;
        }
    throw std::invalid_argument("unknown shadow technique '" + name + "'; known: " + knownTechniqueNames());
}

}  // namespace penumbra::shadows
