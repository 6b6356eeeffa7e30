#include "shadows/cssm/ColoredStochasticShadowMap.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "shadows/common/MapRegion.h"
#include "util/Digest.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace penumbra::shadows {

// log2 of a tile's side (4 or 8): the colour map's mip level that holds the tiles' counts
// (tiles.frag), and the bits of caster.frag's dither period.
static int tileLevel(int side) { return std::countr_zero(static_cast<unsigned>(side)); }

ColoredStochasticShadowMap::ColoredStochasticShadowMap(Variant variant)
    : variant_(variant), fp16_(variant == Variant::Rgb) {
    copy_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/cssm/copy.frag"});
    tiles_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/cssm/tiles.frag"});
    nearestLayer_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/cssm/nearest_layer.frag"});
    buildCasters();
}

// The variant's ξ per channel and the ξ kind are compiled in (caster.frag): as uniforms, llvmpipe
// drew all four ξ, stratified and white alike, for every fragment. Measured on the glass scene,
// where the flying ball's texels are redrawn every frame (three alternated rounds): cssm2's shadow
// pass 4.7-5.2 -> 2.9-3.8 ms, 10.0-12.6 -> 6.0-8.4 ms with its spot made a point light; pictures
// byte-identical. Rebuilt when the `xi` parameter changes. Untextured materials without an alpha
// test get a build that samples no texture (see DrawPrograms; glass scene, the moving ball's redo:
// ~0.2 ms per caster draw of ~2.3).
void ColoredStochasticShadowMap::buildCasters() {
    const gl::ProgramDesc textured{.vertex = "src/shadows/common/glsl/caster.vert",
                                   .fragment = "src/shadows/cssm/caster.frag",
                                   .defines = {std::string("CSSM_INDEPENDENT_CHANNELS ") + (variant_ == Variant::PerChannel ? "1" : "0"),
                                               "CSSM_XI " + std::to_string(xi_), "CASTER_OBJECT_HASH"}};
    gl::ProgramDesc plain = textured;
    plain.defines.insert(plain.defines.end(), {"MATERIAL_UNTEXTURED 1", "MATERIAL_NO_ALPHA_TEST 1"});
    casters_.emplace(plain, textured, /*coverageFromTexture=*/true);
    castersXi_ = xi_;
}

std::vector<Parameter> ColoredStochasticShadowMap::declareParameters() {
    // Labels in the order of CssmFilter.h and of the kRandom* codes.
    return {Parameter::choice("filter", filter_, {"pcf9", "poisson16", "poisson20", "random30", "cross13", "box16", "box64"},
                              "reconstruction filter of the lookup: the thesis's (Mátl 2013 §5.3), or a 4x4 / 8x8 texel box "
                              "matched to the stratified xi"),
            Parameter::choice("xi", xi_, {"white", "stratified"},
                              "how casters draw xi: independent per fragment, or stratified: every threshold stratum once per 4x4 (8x8) tile"),
            Parameter::flag("separate_opaque", separateOpaque_,
                            "opaque occlusion from the depth map (a hard test), the coloured map for translucent layers "
                            "only; off: the thesis's combined map"),
            Parameter::flag("coverage", coverage_,
                            "box filters: average the transmittance over the texels a translucent layer covers, and place "
                            "the coloured edge by the receiver's own texels (as sharp as the plain map's)"),
            Parameter::flag("nearest_layer", decideByNearestLayer_,
                            "box filters with coverage: decide a receiver just behind the nearest translucent layer (a "
                            "pane's back face) from per-tile statistics of that layer, instead of counting its tile "
                            "texel by texel"),
            Parameter::flag("tint_behind_all", tintBehindAll_,
                            "box filters with coverage: a receiver behind every translucent layer around it takes the "
                            "transmittance product of a deterministic tint map (exact, noise-free); the stochastic counts "
                            "remain for receivers between layers, where a product of every layer would be wrong"),
            Parameter::real("radius_texels", radiusTexels_, 0.0f, 8.0f,
                            "Poisson / random filter radius; 0: automatic, so that taps land on distinct texels"),
            Parameter::choice("rng", generator_, {"pcg", "sin-fract"}, "per-fragment random number generator"),
            Parameter::flag("fp16", fp16_, "RGBA16F colour map (else RGBA32F)")};
}

void ColoredStochasticShadowMap::ensure(std::size_t i, const DepthAndTintMaps::LightMaps& depth) {
    if (maps_.size() <= i) maps_.resize(i + 1);
    LightMap& m = maps_[i];
    const GLenum format = fp16_ ? GL_RGBA16F : GL_RGBA32F;
    const int side = usesTiles() ? tileSide() : 0;
    if (m.resolution == depth.resolution && m.cube == depth.cube && m.format == format && m.tileSide == side) return;
    m = LightMap{};
    m.resolution = depth.resolution;
    m.cube = depth.cube;
    m.format = format;
    const int res = depth.resolution;
    // With tiles, their statistics live in the colour map's mip level log2(side) (tiles.frag).
    const int levels = side > 0 ? tileLevel(side) + 1 : 1;  // resolutions are at least 16 texels (SceneFile)
    m.colour = m.cube ? gl::Texture::createCube(format, res, levels) : gl::Texture::create2D(format, res, res, levels);
    // Stochastic texels must not be averaged by the sampler; the lookup picks its level explicitly.
    m.colour.setFilter(levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST, GL_NEAREST);
    // New storage holds whatever the driver left there (NVIDIA: earlier allocations' bytes;
    // llvmpipe: zeros). The levels between 0 and the statistics are never drawn: zero them once,
    // so that the map is the same texel for texel on every driver (ShadowReuse compares every level).
    for (int level = 1; level < levels; ++level) glClearTexImage(m.colour.id(), level, GL_RGBA, GL_FLOAT, nullptr);
    for (int f = 0; f < (m.cube ? 6 : 1); ++f) {
        m.depthFaces.push_back(gl::Texture::view2D(depth.depth, GL_DEPTH_COMPONENT32F, f));
        gl::Framebuffer fb;
        if (m.cube) {
            fb.attachLayer(GL_COLOR_ATTACHMENT0, m.colour, f);
            fb.attachLayer(GL_DEPTH_ATTACHMENT, depth.depth, f);
        } else {
            fb.attach(GL_COLOR_ATTACHMENT0, m.colour);
            fb.attach(GL_DEPTH_ATTACHMENT, depth.depth);
        }
        fb.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        fb.checkComplete("coloured stochastic shadow map");
        m.targets.push_back(std::move(fb));
        m.dirty.emplace_back(0, 0, res, res);  // new storage holds anything
        m.holds.push_back(0);
    }
    if (side == 0) return;
    m.tileSide = side;
    for (int f = 0; f < (m.cube ? 6 : 1); ++f) {
        // Level 0 alone as the tiles passes' input: they write levels log2(side) (tiles.frag) and,
        // on 2D maps, log2(side) - 1 (tiles.frag's nearest-layer counts and nearest_layer.frag's
        // planes) of the same texture.
        m.colourFaces.push_back(gl::Texture::view2D(m.colour, format, f, 0));
        const int level = tileLevel(side);
        if (m.cube) {
            m.tileTargets.push_back(gl::Framebuffer::colourOnly(m.colour, f, "coloured stochastic shadow map tiles", level));
            continue;
        }
        gl::Framebuffer tiles;  // the two levels differ in size: tiles.frag draws their common N x N corner
        tiles.attach(GL_COLOR_ATTACHMENT0, m.colour, level);
        tiles.attach(GL_COLOR_ATTACHMENT1, m.colour, level - 1);
        tiles.setDrawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
        tiles.checkComplete("coloured stochastic shadow map tiles");
        m.tileTargets.push_back(std::move(tiles));
        m.nearestLayerTargets.push_back(
            gl::Framebuffer::colourOnly(m.colour, -1, "coloured stochastic shadow map nearest layer", level - 1));
    }
}

bool ColoredStochasticShadowMap::usesTiles() const {
    return coverage_ && separateOpaque_ && (filter_ == gpu::kCssmBox16 || filter_ == gpu::kCssmBox64);
}

int ColoredStochasticShadowMap::tileSide() const { return filter_ == gpu::kCssmBox64 ? 8 : 4; }

// Tile statistics of face `face` (tiles.frag) over the tiles that `rect` (texels) touches. With
// `whole`, every other tile is cleared to zeros, what tiles.frag and nearest_layer.frag make of a
// tile no translucent layer covers; without, the other tiles are kept.
void ColoredStochasticShadowMap::renderTiles(LightMap& m, std::size_t face, const TexelRect& rect, bool whole) {
    const gl::DebugGroup group("tiles");
    const float zero[4] = {0, 0, 0, 0};
    if (whole) {
        glClearNamedFramebufferfv(m.tileTargets[face].id(), GL_COLOR, 0, zero);
        if (!m.cube) glClearNamedFramebufferfv(m.nearestLayerTargets[face].id(), GL_COLOR, 0, zero);  // no covered texels
    }
    if (isEmpty(rect)) return;
    const glm::ivec2 first = glm::ivec2(rect.x, rect.y) / m.tileSide;
    const glm::ivec2 last = (glm::ivec2(rect.z, rect.w) + m.tileSide - 1) / m.tileSide;
    const gl::ScopedPassState state(gl::PassState::fullscreen());
    m.tileTargets[face].bind();
    const int level = tileLevel(m.tileSide);
    glViewport(0, 0, m.resolution >> level, m.resolution >> level);
    glEnable(GL_SCISSOR_TEST);
    glScissor(first.x, first.y, last.x - first.x, last.y - first.y);
    tiles_.use();
    tiles_.set("uSide", m.tileSide);
    m.colourFaces[face].bind(0);
    fullscreenVao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (!m.cube && decideByNearestLayer_) {  // the planes, beside the counts (nearest_layer.frag)
        m.nearestLayerTargets[face].bind();
        const int tiles = m.resolution >> level;
        glViewport(0, 0, 2 * tiles, 2 * tiles);
        nearestLayer_.use();
        nearestLayer_.set("uSide", m.tileSide);
        for (const glm::ivec2 offset : {glm::ivec2(tiles, 0), glm::ivec2(0, tiles)}) {  // alpha's plane, the gaps' plane
            glScissor(offset.x + first.x, offset.y + first.y, last.x - first.x, last.y - first.y);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glDisable(GL_SCISSOR_TEST);
}

// Only the stratified ξ is the same every frame (white ξ is seeded by the frame index), and only
// a map of translucent layers alone depends on the opaque depth just where those layers are (the
// combined map copies all of it).
std::uint64_t ColoredStochasticShadowMap::colourKey(std::size_t light, std::size_t face) const {
    const std::uint64_t translucent = depth_.maps(light).translucentKeys[face];
    if (translucent == 0 || xi_ != gpu::kXiStratified || !separateOpaque_) return 0;
    return util::Digest().add(translucent, generator_, tileSide(), decideByNearestLayer_).value();
}

void ColoredStochasticShadowMap::renderMaps(const ShadowFrame& frame) {
    if (depth_.withTint() != tintBehindAll()) {  // the depth maps are made again: the colour maps' targets hold the old ones
        depth_.setWithTint(tintBehindAll());
        maps_.clear();
    }
    if (castersXi_ != xi_) buildCasters();
    casters_->set("uRandomGenerator", generator_);
    // The dither period matches the tile: log2 of its side.
    casters_->set("uDitherBits", tileLevel(tileSide()));
    casters_->set("uFrameSeed", static_cast<int>(frame.frameIndex));
    // 1. opaque casters' depth (and the tint maps: the product of the layers' transmittance);
    // 2. the colour maps over it. A map of translucent layers alone is drawn face by face inside
    // depth_'s pass, which tests them against the still casters' depth where no layer can lie in
    // front of an animated caster (DepthAndTintMaps::render): the animated casters' motion then
    // leaves the map as it is. The combined map copies the whole opaque depth: after it.
    if (separateOpaque_) {
        depth_.render(frame, -1, [&](std::size_t light, std::size_t face) { renderColour(frame, light, face); });
        return;
    }
    depth_.render(frame);
    for (std::size_t i = 0; i < depth_.slots().size(); ++i)
        if (depth_.slots().shadowed(i))
            for (std::size_t f = 0; f < (depth_.maps(i).cube ? 6u : 1u); ++f) renderColour(frame, i, f);
}

void ColoredStochasticShadowMap::renderColour(const ShadowFrame& frame, std::size_t i, std::size_t f) {
    gl::DebugGroup group(name().c_str());
    ensure(i, depth_.maps(i));
    LightMap& m = maps_[i];
    const LightSpace& ls = (*frame.lightSpaces)[i];
    const auto setDepthRange = [&](const auto& p) {
        p.set("uPerspective", ls.perspective ? 1 : 0);
        p.set("uNear", ls.near);
        p.set("uFar", ls.far);
    };
    setDepthRange(copy_);
    setDepthRange(*casters_);
    casters_->set("uTestOffset", DepthAndTintMaps::translucentTestOffset((*frame.lights)[i]));
    // Drawn with the same key last frame: the colour map and its tiles are as drawn except
    // where animated casters were or are (DepthAndTintMaps::translucentRedo).
    const std::uint64_t key = colourKey(i, f);
    const bool kept = key != 0 && key == m.holds[f];
    m.holds[f] = key;
    const TexelRect redo = kept ? depth_.maps(i).translucentRedo[f] : TexelRect(0);
    if (kept && isEmpty(redo)) return;
    const CasterSelection translucent{Casters::Translucent, ls.viewProj[f], static_cast<int>(i), Motion::Any, ls.viewProj[f]};
    const scene::Bounds casters = frame.casterBounds(translucent);
    glViewport(0, 0, m.resolution, m.resolution);
    m.targets[f].bind();
    const TexelRect rect = texelRect(casters, ls.viewProj[f], m.resolution);
    if (kept) {  // drawn again in `redo` below, by the same draws (ξ hashes gl_PrimitiveID)
        clearColourIn(m.targets[f].id(), redo, glm::vec4(1.0f));
        m.dirty[f] = unite(m.dirty[f], rect);
    } else if (separateOpaque_) {  // translucent layers only: start from "nothing occludes"
        clearColourIn(m.targets[f].id(), m.dirty[f], glm::vec4(1.0f));  // white where it may hold anything
        m.dirty[f] = rect;
    } else {  // 1 (white) where nothing opaque is: the opaque depth copied into every channel
        const gl::ScopedPassState state(gl::PassState::fullscreen());
        m.dirty[f] = TexelRect(0, 0, m.resolution, m.resolution);
        copy_.use();
        depthSampler_.bind(0);
        m.depthFaces[f].bind(0);
        fullscreenVao_.bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        gl::Sampler::unbind(0);
    }
    if (!casters.empty()) {  // translucent casters in front of the opaque depth (tested, not written), MIN-blended per channel
        gl::PassState casterPass = gl::PassState::depthOnly().withBlend(gl::BlendState::of(GL_MIN, GL_ONE, GL_ONE));
        casterPass.depthWrite = false;
        const ScopedScissor scissor(redo, kept);
        const gl::ScopedPassState state(casterPass);
        frame.drawCasters(*casters_, translucent);
    }
    if (m.tileSide > 0) renderTiles(m, f, kept ? redo : rect, !kept);
}

std::vector<std::string> ColoredStochasticShadowMap::lookupDefines() const {
    return {"CSSM_FILTER " + std::to_string(filter_), std::string("CSSM_SEPARATE_OPAQUE ") + (separateOpaque_ ? "1" : "0"),
            std::string("CSSM_COVERAGE ") + (coverage_ ? "1" : "0"),
            std::string("CSSM_TINT_BEHIND_ALL ") + (tintBehindAll() ? "1" : "0")};
}

// The Poisson and random filters' radius in texels: the parameter, or by default about n texels
// under the disk, r = 1.5 sqrt(n / pi), so that the taps land on distinct texels.
float ColoredStochasticShadowMap::tapRadiusTexels() const {
    if (radiusTexels_ > 0.0f) return radiusTexels_;
    const int taps = filter_ == gpu::kCssmPoisson16 ? 16 : filter_ == gpu::kCssmPoisson20 ? 20 : 30;
    return 1.5f * std::sqrt(static_cast<float>(taps) / std::numbers::pi_v<float>);
}

// How far from the receiver's texel a layer can change its lookup. The tap filters: the widest
// they read, plus the texel a tap lands in and the bilinear tint's (cross13: 7 texels and a jitter
// of at most one). The box filters with coverage read up to two tiles of 8 texels away, but their
// answer is exactly 1 unless a layer lies in front of the receiver at its own 2 x 2 texels
// (ownCoverage, colouredByTint's `own`; a translucent receiver's division by its own layers reads
// those 2 x 2 alone): the bilinear tint's 2 texels decide where colour can fall at all. Their
// farther reads weigh only where a nearer layer tints already, except at a translucent receiver's
// rim, where the whole lookup counts its own tile's texels and so spreads another layer's shadow
// up to 7 texels onto it; with this reach the split gives such pixels the builds for one side,
// which leave it out. Measured (llvmpipe): with 18 texels, the glass scene's cssm2 translucent
// pass was 0.46 of its opaque pass in four alternated runs, with 2 texels 0.42; 417 pixels of the
// translucent-receivers visibility of TintReachTranslucent's scene moved by 1/255, 408 of them
// towards the reference (TintReachTranslucent, the reference test).
// A receiver's plane extrapolated to a tap beyond the light's far plane used to read the cleared
// map as a layer in front (belowClearedDepth in lookup.glsl), which is why the tap filters once
// opted out: the whole lookup, not the untinted one, was wrong there. Without the separate opaque
// map the colour map holds the opaque casters too, so every receiver reads it: no split.
float ColoredStochasticShadowMap::tintReachTexels() const {
    if (!separateOpaque_) return -1.0f;
    if (usesTiles()) return 2.0f;
    switch (filter_) {
        case gpu::kCssmPcf9: return 1.0f + 2.0f;
        case gpu::kCssmCross13: return 8.0f + 2.0f;
        case gpu::kCssmBox16: return 4.0f + 2.0f;
        case gpu::kCssmBox64: return 8.0f + 2.0f;
        default: return tapRadiusTexels() + 2.0f;
    }
}

void ColoredStochasticShadowMap::bindLookup(const gl::Program& lighting) const {
    depth_.bind();
    for (std::size_t i = 0; i < depth_.slots().size() && i < maps_.size(); ++i) {
        if (!depth_.slots().shadowed(i) || !maps_[i].colour.id()) continue;
        maps_[i].colour.bind(static_cast<GLuint>(depth_.slots().rawUnit(i)));
    }
    lighting.set("uRadiusTexels", tapRadiusTexels());
    lighting.set("uTileSide", tileSide());
    lighting.set("uNearestLayer", decideByNearestLayer_ ? 1 : 0);
    lighting.set("uStorageEpsilon", fp16_ ? 1.0f / 1024.0f : 0.0f);
    poisson_.upload(lighting);
}

std::size_t ColoredStochasticShadowMap::memoryBytes() const {
    std::size_t total = depth_.memoryBytes();
    for (const auto& m : maps_) total += m.colour.memoryBytes();
    return total;
}

std::vector<DebugView> ColoredStochasticShadowMap::debugViews() const {
    std::vector<DebugView> views;
    for (std::size_t i = 0; i < maps_.size(); ++i) {
        if (!maps_[i].colour.id() || maps_[i].cube) continue;
        views.push_back({"light " + std::to_string(i) + " opaque depth", depth_.maps(i).depth.id(), GL_TEXTURE_2D, true, 0});
        views.push_back({"light " + std::to_string(i) + " CSSM", maps_[i].colour.id(), GL_TEXTURE_2D, false, 0});
    }
    return views;
}

}  // namespace penumbra::shadows
