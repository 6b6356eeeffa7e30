#pragma once
// Translucent surfaces as the camera sees them (SPEC §4 end, seed 000 ch. 3). Every mode blends
// over the opaque frame with dst * transmittance + colour, transmittance (1 - ρ) per channel:
//   sorted-objects    painter's algorithm by object centre (what seed 000 did)
//   sorted-triangles  painter's algorithm by triangle centre within each object
//   depth-peeling     Everitt 2001: N exact layers front to back, composited in one pass
//   weighted          McGuire & Bavoil 2013: one pass, exact transmittance, weighted colour
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/GpuScene.h"

#include <functional>
#include <string>
#include <vector>

namespace penumbra::render {

enum class TransparencyMode { SortedObjects, SortedTriangles, DepthPeeling, WeightedBlended };
const char* toString(TransparencyMode mode);
// Throws std::invalid_argument listing the names.
TransparencyMode transparencyFromString(const std::string& name);

class OrderIndependentTransparency {
public:
    // `lookupShader`: the shadow technique's GLSL (the lighting variants include it).
    explicit OrderIndependentTransparency(const std::filesystem::path& lookupShader);

    // `prepare` sets camera, light and shadow-lookup state on a lighting program.
    using Prepare = std::function<void(const gl::Program&)>;
    void render(TransparencyMode mode, int peelLayers, const GpuScene& gpu, const std::vector<Draw>& draws,
                const Prepare& prepare, const gl::Framebuffer& hdr, const gl::Texture& opaqueDepth, int width, int height);

private:
    void ensure(int width, int height, int layers);
    void weighted(const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
                  const gl::Texture& opaqueDepth);
    void peel(int layers, const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
              const gl::Texture& opaqueDepth);
    void composite(int mode, int layers, const gl::Framebuffer& hdr, int width, int height);

    gl::Program weightedProgram_, peelProgram_, resolve_;
    gl::VertexArray fullscreen_;
    int width_ = 0, height_ = 0, layers_ = 0;
    gl::Texture accum_, transmit_, depthCopy_, layerColour_, layerTransmit_, peelDepth_[2];
    gl::Framebuffer weightedFbo_;
    std::vector<gl::Framebuffer> peelFbos_;  // per layer: colour/transmit layer + peel depth (ping-pong)
};

}  // namespace penumbra::render
