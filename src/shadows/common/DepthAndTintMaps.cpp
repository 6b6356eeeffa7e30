#include "shadows/common/DepthAndTintMaps.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "util/Digest.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <span>
#include <utility>

namespace penumbra::shadows {

using scene::Light;

namespace {

gl::Texture mapTexture(GLenum format, int resolution, bool cube) {
    return cube ? gl::Texture::createCube(format, resolution) : gl::Texture::create2D(format, resolution, resolution);
}

// Face `face` of a cube map, or the whole 2D map.
void attachFace(gl::Framebuffer& fb, GLenum attachment, const gl::Texture& map, bool cube, int face) {
    if (cube) fb.attachLayer(attachment, map, face);
    else fb.attach(attachment, map);
}

// The drawn alpha of one face: a view of a cube map's face, or the 2D map.
const gl::Texture& drawnFace(const DepthAndTintMaps::LightMaps& m, std::size_t face) { return m.cube ? m.drawnFaceViews[face] : m.drawn; }

// One depth-only framebuffer per face of `map`.
std::vector<gl::Framebuffer> depthOnlyFaces(const gl::Texture& map, bool cube, const std::string& label) {
    std::vector<gl::Framebuffer> faces;
    for (int f = 0; f < (cube ? 6 : 1); ++f) {
        gl::Framebuffer fb;
        attachFace(fb, GL_DEPTH_ATTACHMENT, map, cube, f);
        fb.setNoColor();
        fb.checkComplete(label);
        faces.push_back(std::move(fb));
    }
    return faces;
}

// The least and greatest window depth of `box`'s corners through `viewProj` (nullopt when one lies
// behind a perspective light's eye, where depth flips).
std::optional<glm::vec2> depthRange(const scene::Bounds& box, const glm::mat4& viewProj) {
    glm::vec2 range(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest());
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec4 clip = viewProj * glm::vec4(corner, 1.0f);
        if (clip.w <= 0.0f) return std::nullopt;
        const float z = 0.5f * clip.z / clip.w + 0.5f;  // window depth (clip z in [-w, w])
        range = {std::min(range.x, z), std::max(range.y, z)};
    }
    return range;
}

// Whether every translucent caster that shares texels with an animated opaque one lies wholly
// behind it, as the light sees them (boxes through `viewProj`, with a margin in window depth of 8
// times the rounding of the tint's alpha there: half floats of 1 - depth). Then no animated
// caster has a translucent layer in front of it, and a tint drawn over the still casters' depth
// alone gives every receiver the light it gets from a tint drawn over every caster's:
// - an animated caster finds the nearest layer of its texels behind it, untinted either way (the
//   layers behind it, which the still depth lets through, sit behind tintBehind's test);
// - a receiver behind one is shadowed by the depth test, whatever the tint there;
// - a soft lookup's tint, read at the receiver's own place, now counts the panes behind the
//   caster's rim where the light that passes the rim meets them (the reference's answer).
// Where a layer may lie in front of an animated caster, the tint must be tested against it too
// (it then holds only the layers in front: the deterministic map's exact answer for it).
bool translucentBehindMoving(std::span<const scene::Bounds> moving, std::span<const scene::Bounds> translucent,
                             const glm::mat4& viewProj, int resolution) {
    const auto margin = [](float depth) { return std::max(1.0f - depth, 1.0f / 1024.0f) / 256.0f; };
    for (const scene::Bounds& m : moving) {
        const TexelRect mTexels = texelRect(m, viewProj, resolution);
        const std::optional<glm::vec2> mDepth = depthRange(m, viewProj);
        for (const scene::Bounds& t : translucent) {
            if (isEmpty(intersection(mTexels, texelRect(t, viewProj, resolution)))) continue;
            const std::optional<glm::vec2> tDepth = depthRange(t, viewProj);
            if (!mDepth || !tDepth || tDepth->x <= mDepth->y + margin(tDepth->x)) return false;
        }
    }
    return true;
}

}  // namespace

DepthAndTintMaps::DepthAndTintMaps(bool withTint, TintAlpha tintAlpha) : withTint_(withTint), tintAlpha_(tintAlpha) {}

void DepthAndTintMaps::setWithTint(bool withTint) {
    if (withTint == withTint_) return;
    withTint_ = withTint;
    maps_.clear();
}

void DepthAndTintMaps::ensure(std::size_t i, int res, bool cube) {
    if (maps_.size() <= i) maps_.resize(i + 1);
    LightMaps& m = maps_[i];
    if (m.resolution == res && m.cube == cube && m.depth.id() != 0) return;
    m = LightMaps{};
    m.resolution = res;
    m.cube = cube;
    m.depth = mapTexture(GL_DEPTH_COMPONENT32F, res, cube);
    // Without tint a 1-texel white map keeps the lookups' "no tint" answer and costs nothing.
    m.tint = mapTexture(GL_RGBA16F, withTint_ ? res : 1, cube);
    if (!withTint_) {
        const float white[4] = {1, 1, 1, 1};
        glClearTexImage(m.tint.id(), 0, GL_RGBA, GL_FLOAT, white);
    }
    m.depth.setDepthCompare(true);
    m.depth.setFilter(filter_, filter_);
    m.tint.setFilter(tintFilter(), tintFilter());
    m.depthFaces = depthOnlyFaces(m.depth, cube, "shadow depth map " + std::to_string(res));
    for (int f = 0; f < (cube ? 6 : 1); ++f) {
        gl::Framebuffer withTint;
        attachFace(withTint, GL_DEPTH_ATTACHMENT, m.depth, cube, f);
        if (withTint_) {
            attachFace(withTint, GL_COLOR_ATTACHMENT0, m.tint, cube, f);
            withTint.setDrawBuffers({GL_COLOR_ATTACHMENT0});
            withTint.checkComplete("shadow tint map " + std::to_string(res));
        }
        m.tintFaces.push_back(std::move(withTint));
        // A new map's contents are undefined until cleared.
        m.tintDirty.push_back(withTint_ ? TexelRect(0, 0, res, res) : TexelRect(0));
    }
    const std::size_t faces = cube ? 6 : 1;
    m.depthHolds.assign(faces, 0);
    m.stillHolds.assign(faces, 0);
    m.translucentKeys.assign(faces, 0);
    m.translucentRedo.assign(faces, TexelRect(0));
    m.translucentMoving.assign(faces, TexelRect(0));
    m.stillKeys.assign(faces, 0);
    m.movingTexels.assign(faces, TexelRect(0));
    m.depthOverStill.assign(faces, 0);
    m.depthMovedIn.assign(faces, TexelRect(0));
    // CSSM's maps (FarthestLayer) are made with theirs, which its translucent receivers read;
    // NearestLayer maps get theirs in scenes with translucent casters (render).
    if (withTint_ && tintAlpha_ == TintAlpha::FarthestLayer) ensureDrawn(m);
}

bool DepthAndTintMaps::ensureDrawn(LightMaps& m) {
    if (m.drawn.id() != 0) return false;
    const int res = m.resolution;
    const float noLayer[2] = {1.0f, 1.0f};  // 1 - the farthest depths where no layer is
    // Full precision: translucent receivers tell their own layer from one just behind it by these
    // depths; half floats of 1 - depth would blur that to 2^-9 of the distance from the far plane
    // (8 cm in a 40 m sun box). A cube map's faces are views of it (bound and drawn per face).
    m.drawn = mapTexture(GL_RG32F, res, m.cube);
    m.drawn.setFilter(GL_NEAREST, GL_NEAREST);  // point lights' lookups read the texel a direction selects
    glClearTexImage(m.drawn.id(), 0, GL_RG, GL_FLOAT, noLayer);
    for (int f = 0; f < (m.cube ? 6 : 1); ++f) {
        if (m.cube) m.drawnFaceViews.push_back(gl::Texture::view2D(m.drawn, GL_RG32F, f));
        m.tintFaces[f].attach(GL_COLOR_ATTACHMENT1, drawnFace(m, f));
        m.tintFaces[f].setDrawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
        m.tintFaces[f].checkComplete("shadow tint map with drawn alpha " + std::to_string(res));
    }
    return true;
}

void DepthAndTintMaps::ensureStill(LightMaps& m) {
    if (m.still.id() != 0) return;
    m.still = mapTexture(GL_DEPTH_COMPONENT32F, m.resolution, m.cube);
    m.stillFaces = depthOnlyFaces(m.still, m.cube, "still casters' depth map " + std::to_string(m.resolution));
}

void DepthAndTintMaps::renderOpaque(const ShadowFrame& frame, LightMaps& m, std::size_t face, int light,
                                    const OpaqueRegion& region, std::uint64_t stillKey, bool moving, bool movingLater) {
    const glm::mat4& vp = (*frame.lightSpaces)[static_cast<std::size_t>(light)].viewProj[face];
    const float farDepth = 1.0f;
    const ScopedScissor scissor(region.texels, region.cropped);
    const auto drawInto = [&](const gl::Framebuffer& fb, Motion motion) {
        fb.bind();
        glClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
        frame.drawCasters(depthProgram_, {Casters::Opaque, region.cull, light, motion, vp, true,
                                          CasterMap{m.resolution, region.texels, region.cropped}});
    };
    const std::uint64_t overStill = std::exchange(m.depthOverStill[face], 0);
    if (stillKey == 0) {  // nothing reused: every caster, every frame
        drawInto(m.depthFaces[face], movingLater ? Motion::Still : Motion::Any);
        m.depthHolds[face] = 0;
        return;
    }
    if (!moving) {
        if (m.depthHolds[face] != stillKey) drawInto(m.depthFaces[face], Motion::Still);
        m.depthHolds[face] = stillKey;
        return;
    }
    const bool stillKept = m.stillHolds[face] == stillKey;
    if (!stillKept) drawInto(m.stillFaces[face], Motion::Still);
    m.stillHolds[face] = stillKey;
    // The still depth back where last frame's animated casters were and where this frame's are;
    // elsewhere `depth` holds it already. The animated casters are drawn inside their own texels
    // only, which keeps that true for the next frame. A cropped region (drawn under the outer
    // scissor) restores the whole face every frame instead.
    const TexelRect moved = m.movingTexels[face];
    const bool onlyMoved = stillKept && overStill == stillKey && !region.cropped;
    const TexelRect restore = onlyMoved ? unite(m.depthMovedIn[face], moved) : TexelRect(0, 0, m.resolution, m.resolution);
    const GLenum target = m.cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    const auto z = static_cast<GLint>(face);
    if (!isEmpty(restore))
        glCopyImageSubData(m.still.id(), target, 0, restore.x, restore.y, z, m.depth.id(), target, 0, restore.x, restore.y, z,
                           restore.z - restore.x, restore.w - restore.y, 1);
    if (!movingLater) drawMovingOver(frame, m, face, light, region);
    m.depthHolds[face] = 0;
    m.depthOverStill[face] = stillKey;
    m.depthMovedIn[face] = moved;
}

void DepthAndTintMaps::drawMovingOver(const ShadowFrame& frame, LightMaps& m, std::size_t face, int light, const OpaqueRegion& region) {
    const glm::mat4& vp = (*frame.lightSpaces)[static_cast<std::size_t>(light)].viewProj[face];
    const glm::vec2 po = (*frame.lights)[static_cast<std::size_t>(light)].shadow.polygonOffset;
    const gl::ScopedPassState state(gl::PassState::depthOnly().withPolygonOffset(po.x, po.y));
    const TexelRect texels = region.cropped ? region.texels : m.movingTexels[face];
    const ScopedScissor inside(texels);
    m.depthFaces[face].bind();
    frame.drawCasters(depthProgram_, {Casters::Opaque, region.cull, light, Motion::Moving, vp, true, CasterMap{m.resolution, texels, true}});
}

void DepthAndTintMaps::setFiltering(GLenum filter) {
    filter_ = filter;
    for (auto& m : maps_)
        if (m.depth.id()) {
            m.depth.setFilter(filter, filter);
            m.tint.setFilter(tintFilter(), tintFilter());
        }
}

glm::vec2 DepthAndTintMaps::translucentTestOffset(const Light& light) {
    // Eight units more: two triangles of one plane (the floor, a block's bottom face) rasterise
    // depths that differ by more than a unit, and the shader's slope (dFdx, dFdy of the float
    // depth) may fall short of the driver's by rounding. over_opaque.glsl takes a unit at its
    // largest (2^-23), which bounds every driver's r for depths below 1.
    constexpr float kMoreUnits = 8.0f;
    return light.shadow.polygonOffset + glm::vec2(0.0f, kMoreUnits);
}

const scene::Light* DepthAndTintMaps::renderAllButTheSun(const ShadowFrame& frame) {
    const int sun = frame.slots->sun;
    render(frame, frame.camera ? sun : -1);
    return sun >= 0 && frame.camera ? &(*frame.lights)[static_cast<std::size_t>(sun)] : nullptr;
}

void DepthAndTintMaps::render(const ShadowFrame& frame, int elsewhere, const TranslucentPass& translucentPass) {
    const auto& lights = *frame.lights;
    const auto& spaces = *frame.lightSpaces;
    slots_ = *frame.slots;
    const bool reuse = frame.reuseStillCasters && frame.casterDigest;
    depthElsewhere_ = elsewhere;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (!slots_.shadowed(i)) continue;
        const Light& light = lights[i];
        const LightSpace& ls = spaces[i];
        ensure(i, ls.resolution, slots_.cube[i]);
        // Allocated with the map whenever the scene animates anything, not when an animated caster
        // first reaches the light: the maps a technique holds then do not depend on the time.
        LightMaps& m = maps_[i];
        if (reuse && frame.scene && frame.scene->animated()) ensureStill(m);
        // Likewise the drawn alpha, whenever the scene has translucent casters; made for a map
        // that holds a tint already, it takes the whole tint drawn again.
        if (withTint_ && frame.translucentCasters && ensureDrawn(m)) m.translucentKeys.assign(m.translucentKeys.size(), 0);
        gl::DebugGroup group(("shadow map: " + light.name).c_str());
        // Unbind every texture unit first. Measured on llvmpipe: with the previous frame's lookup
        // textures still bound, every shadow map after the first in a frame costs 7-10x more to
        // rasterise (2048^2, one thread: 145-190 ms instead of 15-20 ms), whatever its order.
        gl::unbindTextureUnits(gpu::kLightingUnits);
        const glm::vec2 po = light.shadow.polygonOffset;
        // 1. opaque casters: depth only, with the light's polygon offset. 2. translucent casters
        // in front of the opaque depth into the tint (redrawTint).
        const gl::PassState opaquePass = gl::PassState::depthOnly().withPolygonOffset(po.x, po.y);
        glViewport(0, 0, ls.resolution, ls.resolution);
        for (int f = 0; f < ls.faceCount; ++f) {
            const auto face = static_cast<std::size_t>(f);
            const glm::mat4& vp = ls.viewProj[face];
            const int light = static_cast<int>(i);
            const CasterSelection translucent{Casters::Translucent, vp, light, Motion::Any, vp};
            const TexelRect translucentTexels = texelRect(frame.casterBounds(translucent), vp, ls.resolution);
            const TexelRect tinted = withTint_ ? translucentTexels : TexelRect(0);
            const bool anyTranslucent = !isEmpty(tinted);
            // A light whose depth lives elsewhere needs this depth only as the tint pass's depth
            // test, under the translucent casters: the opaque casters are culled to those texels
            // and drawn scissored to them (the rest of the map is stale and never read).
            const bool cropped = depthElsewhere(light) && anyTranslucent;
            const OpaqueRegion region{cropped ? cropTo(tinted, ls.resolution) * vp : vp,
                                      cropped ? tinted : TexelRect(0, 0, ls.resolution, ls.resolution), cropped};
            const CasterSelection movingOpaque{Casters::Opaque, region.cull, light, Motion::Moving};
            const scene::Bounds movingBounds = frame.casterBounds(movingOpaque);
            const bool moving = !movingBounds.empty();
            const TexelRect movingTexels = texelRect(movingBounds, vp, ls.resolution);
            // Translucent casters are tested against the still casters alone where that gives the
            // same light (translucentBehindMoving), in every frame alike, kept maps or not: then an
            // animated opaque caster changes nothing they draw. Maps other than the plain tint only
            // when their pass runs in between (translucentPass).
            const bool overStillDrawn = static_cast<bool>(translucentPass) || (withTint_ && tintAlpha_ == TintAlpha::NearestLayer);
            const bool translucentOverStill =
                overStillDrawn && !isEmpty(translucentTexels) && moving &&
                translucentBehindMoving(frame.casterBoxes(movingOpaque), frame.casterBoxes(translucent), vp, ls.resolution);
            const std::uint64_t stillKey =
                reuse ? util::Digest().add(frame.casterDigest({Casters::Opaque, region.cull, light, Motion::Still}), region.cull, po).value()
                      : 0;
            // Translucent casters are depth-tested against the opaque depth: animated translucent
            // casters, and animated opaque ones over the translucent casters' texels, change what
            // the translucent casters draw there only.
            const TexelRect movingTranslucent =
                reuse ? texelRect(frame.casterBounds({Casters::Translucent, vp, light, Motion::Moving}), vp, ls.resolution) : TexelRect(0);
            const std::uint64_t translucentKey =
                reuse ? util::Digest().add(stillKey, frame.casterDigest({Casters::Translucent, vp, light, Motion::Still})).value() : 0;
            const TexelRect movingOverTint = translucentOverStill ? TexelRect(0) : intersection(movingTexels, translucentTexels);
            const bool kept = keepTranslucent(m, face, translucentKey, unite(movingTranslucent, movingOverTint));
            m.stillKeys[face] = stillKey;
            m.movingTexels[face] = movingTexels;
            // The tint texels to draw again (nothing without a tint map): what changed, or where the
            // last translucent casters may have left something and where this frame's are.
            const TexelRect redraw = !withTint_ ? TexelRect(0) : kept ? m.translucentRedo[face] : unite(m.tintDirty[face], tinted);
            const bool opaqueDrawn = !depthElsewhere(light) || (anyTranslucent && !isEmpty(redraw));
            if (opaqueDrawn) {
                const gl::DebugGroup depthGroup("depth");
                const gl::ScopedPassState state(opaquePass);
                renderOpaque(frame, m, face, light, region, stillKey, moving, translucentOverStill);
            }
            if (!isEmpty(redraw)) {
                const gl::DebugGroup tintGroup("tint");
                m.tintDirty[face] = kept ? unite(m.tintDirty[face], tinted) : tinted;
                redrawTint(frame, m, face, anyTranslucent ? &translucent : nullptr, redraw, lights[i]);
            }
            if (translucentPass) {
                translucentPass(i, face);
                gl::unbindTextureUnits(gpu::kLightingUnits);  // what it read (see above)
                glViewport(0, 0, ls.resolution, ls.resolution);
            }
            if (opaqueDrawn && translucentOverStill) drawMovingOver(frame, m, face, light, region);
        }
    }
}

bool DepthAndTintMaps::keepTranslucent(LightMaps& m, std::size_t face, std::uint64_t key, const TexelRect& changed) {
    const bool kept = key != 0 && key == m.translucentKeys[face];
    m.translucentRedo[face] = kept ? unite(m.translucentMoving[face], changed) : TexelRect(0, 0, m.resolution, m.resolution);
    m.translucentMoving[face] = changed;
    m.translucentKeys[face] = key;
    return kept;
}

void DepthAndTintMaps::redrawTint(const ShadowFrame& frame, LightMaps& m, std::size_t face, const CasterSelection* translucent,
                                  const TexelRect& redraw, const Light& light) {
    const bool farthest = tintAlpha_ == TintAlpha::FarthestLayer, drawn = m.drawn.id() != 0;
    clearColourIn(m.tintFaces[face].id(), redraw, glm::vec4(1.0f, 1.0f, 1.0f, farthest ? 1.0f : 0.0f));  // alpha: no layer
    if (drawn) clearColourIn(m.tintFaces[face].id(), redraw, glm::vec4(1.0f), 1);  // the drawn alpha: no layer
    if (translucent) {
        // Transmittance multiplied into rgb (dst * src); alpha 1 - depth: of the nearest
        // translucent layer (MAX), or of the farthest (MIN); no depth writes.
        gl::PassState tintPass =
            gl::PassState::depthOnly().withBlend({GL_FUNC_ADD, static_cast<GLenum>(farthest ? GL_MIN : GL_MAX), GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE});
        tintPass.depthWrite = false;
        tintProgram_.set("uTestOffset", translucentTestOffset(light));
        const ScopedScissor scissor(redraw);
        m.tintFaces[face].bind();
        const gl::ScopedPassState state(tintPass);
        if (drawn) {  // the drawn alpha (attachment 1): 1 - the farthest depth, MIN
            glBlendEquationi(1, GL_MIN);
            glBlendFunci(1, GL_ONE, GL_ONE);
        }
        frame.drawCasters(tintProgram_, *translucent);
    }
}

void DepthAndTintMaps::bind(bool rawDepth) const {
    for (std::size_t i = 0; i < slots_.size() && i < maps_.size(); ++i) {
        if (!slots_.shadowed(i) || maps_[i].depth.id() == 0) continue;
        const auto raw = static_cast<GLuint>(slots_.rawUnit(i));
        maps_[i].depth.bind(static_cast<GLuint>(slots_.depthUnit(i)));
        maps_[i].tint.bind(static_cast<GLuint>(slots_.tintUnit(i)));
        if (maps_[i].drawn.id() != 0) maps_[i].drawn.bind(static_cast<GLuint>(slots_.drawnUnit(i)));
        if (rawDepth) {
            maps_[i].depth.bind(raw);
            rawSampler_.bind(raw);
        } else {
            gl::Sampler::unbind(raw);
        }
    }
}

std::size_t DepthAndTintMaps::memoryBytes() const {
    std::size_t total = 0;
    for (const auto& m : maps_) {
        total += m.depth.memoryBytes() + m.tint.memoryBytes() + m.still.memoryBytes();
        total += m.drawn.memoryBytes();
    }
    return total;
}

std::vector<DebugView> DepthAndTintMaps::debugViews() const {
    std::vector<DebugView> views;
    for (std::size_t i = 0; i < maps_.size(); ++i) {
        if (maps_[i].depth.id() == 0 || maps_[i].cube) continue;
        // A light whose depth lives in the technique's own map: this one is drawn only under
        // translucent casters, as the tint's depth test, and may be stale elsewhere.
        if (!depthElsewhere(static_cast<int>(i)))
            views.push_back({"light " + std::to_string(i) + " depth", maps_[i].depth.id(), GL_TEXTURE_2D, true, 0});
        views.push_back({"light " + std::to_string(i) + " colour", maps_[i].tint.id(), GL_TEXTURE_2D, false, 0});
    }
    return views;
}

}  // namespace penumbra::shadows
