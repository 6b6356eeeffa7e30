#pragma once
// Translucent surfaces as the camera sees them (Mátl 2013 ch. 3). Every mode blends
// over the opaque frame with dst * transmittance + colour, transmittance (1 - ρ) per channel:
//   sorted-objects    painter's algorithm by object centre (what Mátl 2013 did)
//   sorted-triangles  painter's algorithm by triangle centre within each object
//   depth-peeling     Everitt 2001: N exact layers front to back, composited in one pass
//   dual-depth-peeling  Bavoil & Myers 2008: the nearest and farthest layer per pass (N/2 passes)
//   weighted          McGuire & Bavoil 2013: one pass, exact transmittance, weighted colour
//   stochastic        Enderton et al. 2010: 4-sample stochastic depth, then visibility-weighted
//                     colour with alpha correction (exact coloured transmittance)
#include "gl/Framebuffer.h"
#include "gl/PassState.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/GpuScene.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace penumbra::render {

// Translucent colour over what is behind it: dst.rgb = src.rgb + dst.rgb * transmittance (the
// second fragment output, per channel). Alpha is kept as it was: it marks the pixels whose
// opaque surface the renderer shaded itself (Renderer::setReceivers).
inline gl::BlendState overTransmittance() {
    return {GL_FUNC_ADD, GL_FUNC_ADD, GL_ONE, GL_SRC1_COLOR, GL_ZERO, GL_ONE};
}

enum class TransparencyMode { SortedObjects, SortedTriangles, DepthPeeling, DualDepthPeeling, WeightedBlended, Stochastic };
const char* toString(TransparencyMode mode);
// Painter's order: the renderer draws the translucent surfaces back to front itself, blended over
// its own colour target; the other modes composite passes of their own onto the float target.
inline bool isSorted(TransparencyMode m) { return m == TransparencyMode::SortedObjects || m == TransparencyMode::SortedTriangles; }

class OrderIndependentTransparency {
public:
    // `lookupShader`: the shadow technique's GLSL (the lighting variants include it);
    // `lightLayout`: the renderer's light-layout defines (render/LightingProgram.h).
    OrderIndependentTransparency(const std::filesystem::path& lookupShader, std::vector<std::string> lightLayout);

    // `prepare` sets camera, light and shadow-lookup state on a lighting program.
    using Prepare = std::function<void(const gl::Program&)>;
    void render(TransparencyMode mode, int peelLayers, const GpuScene& gpu, const std::vector<Draw>& draws,
                const Prepare& prepare, const gl::Framebuffer& hdr, const gl::Texture& opaqueDepth, int width, int height);

private:
    void ensure(int width, int height, int layers);
    void weighted(const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
                  const gl::Texture& opaqueDepth, const gl::Program& program);
    void stochasticDepth(const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
                         const gl::Texture& opaqueDepth);
    void peel(int layers, const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
              const gl::Texture& opaqueDepth);
    void dualPeel(int passes, const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
                  const gl::Texture& opaqueDepth);
    void composite(int mode, int layers, const gl::Framebuffer& hdr, int width, int height);

    // The lighting variant of one mode (TRANSLUCENT_WEIGHTED, ...), built on first use: a mode
    // never used costs no compile.
    const gl::Program& variant(const std::string& define);

    std::filesystem::path lookup_;
    std::vector<std::string> lightLayout_;
    std::map<std::string, gl::Program> variants_;
    gl::Program resolve_;
    gl::VertexArray fullscreen_;
    int width_ = 0, height_ = 0, layers_ = 0;
    gl::Texture accum_, transmit_, depthCopy_, layerColour_, layerTransmit_, peelDepth_[2];
    gl::Framebuffer weightedFbo_;
    gl::Texture stochasticDepth_;  // 4x multisampled
    gl::Framebuffer stochasticFbo_;
    std::vector<gl::Framebuffer> peelFbos_;  // per layer: colour/transmit layer + peel depth (ping-pong)
    gl::Texture dualDepth_[2], backColour_, backTransmit_;  // (-nearest, farthest) ping-pong; back layers
    gl::Framebuffer dualInitFbo_;
    std::vector<gl::Framebuffer> dualFbos_;  // per pass: next depth bounds, front and back layer
};

}  // namespace penumbra::render
