#pragma once
// The scene's meshes and images uploaded to the GPU, and the per-frame list of draws.
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/MeshClusters.h"
#include "scene/Scene.h"

#include <optional>
#include <vector>

namespace penumbra::render {

struct Draw {
    std::size_t object;
    std::size_t mesh;
    std::size_t part;
    const scene::Material* material;
    glm::mat4 model;
    bool translucent;
    bool castsShadow;
    bool visible;
    bool moving = false;  // the object is animated: its transform may differ from frame to frame
    float viewDepth = 0;  // for back-to-front sorting of translucent draws
    float farthest = 0;   // distance from the eye to the farthest corner of worldBounds (opaque order)
    // The part bounds a solid (Mesh::closedParts) wound outwards in the world, and its material
    // has no alpha test: from outside it only its front faces can be seen, and along any ray the
    // nearest of its surfaces is a front face. (Through an alpha-tested part's holes its inner
    // faces show.)
    bool solid = false;
    // The part is flat, or bounds a convex solid of one untextured material (uClosedPart): along a
    // ray to a light it crosses at most its own face and that solid's other one, the layers a
    // translucent receiver's lookup divides out (ownLayersFrom, shadow_filtering.glsl).
    bool ownLayersKnown = false;
    // The part shadows none of its own points that a light lights (N.L > 0), so a light's map holds
    // it, where nothing else is in front, at their own depth (Renderer's shadow reach). Either it is
    // flat (Mesh::partIsFlat) and bounds no solid, or it is a solid (above) whose surface is convex
    // and shaded with its faces' own normals (Mesh::partIsConvex, partHasFaceNormals): a ray to the
    // light from a face turned to it leaves the solid for good, and a face turned away has N.L <= 0.
    // The solid's case holds seen from outside only (its inner faces lit through it otherwise).
    bool selfShadowFree = false;
    // A flat part that bounds no solid: its plane (unit normal, offset) in the mesh's space, under
    // `model` (Renderer::flatCasterNeeds).
    std::optional<glm::vec4> plane;
    scene::Bounds worldBounds;  // the part's mesh bounds at this frame (shadow-pass culling)
    scene::Bounds meshBounds;   // the same in the mesh's own space, under `model` (render/TintReach.h's OrientedBox)
    std::size_t triangles = 0;
};

class GpuScene {
public:
    // `anisotropy`: the most anisotropic filtering of the scene's textures (1 = trilinear only).
    // `clusters`: cut big parts into clusters for drawInside (MeshClusters.h).
    explicit GpuScene(const scene::Scene& scene, float anisotropy = 1.0f, bool clusters = true);
    void setAnisotropy(float anisotropy);

    // All parts of all objects at `time`: opaque ones first, nearest farthest corner first;
    // translucent ones after them, back to front from `eye`.
    std::vector<Draw> draws(float time, const glm::vec3& eye) const;
    // Sets uModel, material uniforms and uClosedPart (the part bounds a solid of one untextured
    // material: a light ray leaves it through a face of the same transmittance) on `program`,
    // binds the texture, issues the draw.
    void draw(const Draw& d, const gl::Program& program) const;
    // The same, skipping the part's clusters (MeshClusters.h) outside the clip volume of
    // `viewProj` or wholly outside one of `planes` (world; CasterSelection::cullPlanes); returns
    // the triangles drawn.
    std::size_t drawInside(const Draw& d, const gl::Program& program, const glm::mat4& viewProj,
                           std::span<const glm::vec4> planes = {}) const;
    // The index ranges drawInside draws, or none for a part it draws whole (not cut into clusters).
    std::optional<std::vector<IndexRange>> rangesInside(const Draw& d, const glm::mat4& viewProj, std::span<const glm::vec4> planes) const;
    // draw() in two steps, for a part drawn several times with one program (Renderer::drawPieces,
    // scissored): prepare() sets and binds what draw() does, once; drawPrepared() issues the part's
    // draw with whatever was prepared last.
    void prepare(const Draw& d, const gl::Program& program) const;
    void drawPrepared(const Draw& d) const;
    // The same, with the part's triangles sorted back to front from `eye` (painter's by triangle).
    void drawTrianglesSorted(const Draw& d, const gl::Program& program, const glm::vec3& eye) const;
    const gl::Texture& image(int index) const { return images_[static_cast<std::size_t>(index)]; }
    // World boxes around the part's surface: one per cluster of a clustered part, else its bounds.
    void addSurfaceBounds(const Draw& d, std::vector<scene::Bounds>& out) const;

private:
    static void drawRange(std::uint32_t firstIndex, GLsizei count);
    struct GpuMesh {
        gl::Buffer vertices, indices;
        gl::VertexArray vao;
        std::vector<std::vector<MeshCluster>> clusters;  // per part; empty for parts drawn whole
        // Per part: it bounds a solid (Mesh::closedParts).
        std::vector<bool> closedParts;
        // Per part: it is flat, or it bounds a convex solid (Mesh::partIsFlat, partIsConvex).
        std::vector<bool> flatOrConvexParts;
        // Per part: its vertex normals are its faces' (Mesh::partHasFaceNormals).
        std::vector<bool> faceNormalParts;
        // Per part: the plane of a flat part that bounds no solid (Mesh::partPlane).
        std::vector<std::optional<glm::vec4>> planes;
    };
    const scene::Scene& scene_;
    std::vector<GpuMesh> meshes_;
    std::vector<gl::Texture> images_;
    // Per image, as uploaded: some texel's alpha is below 1 (scene::Image::hasTranslucentAlpha, a
    // scan of every texel, which ran every frame: 0.66 % of a hard bench's perf samples on the
    // default scene, whose cow has a 1024^2 texture).
    std::vector<bool> translucentAlpha_;
    mutable gl::Buffer sortedIndices_;  // streaming index buffer for drawTrianglesSorted
};

// A solid's back faces (Draw::solid) lie behind its front faces from any eye outside it, so the
// camera's opaque passes and the depth maps cull them: llvmpipe then neither rasterises them nor,
// where the index order puts them first, shades them before the front faces cover them. An eye
// inside a solid, or a near plane that cuts it open, sees its inside: such a solid (by its world
// bounds, nearPlaneMayCut through `viewProj`) keeps both faces, as every other draw does.
// Enables GL_CULL_FACE for `d` when it is to be culled and `cull` is set, disables it otherwise
// (`cull` false: both faces, RenderOptions::cullSolidBackFaces).
void cullBackFacesOfSolid(const Draw& d, bool cull, const glm::mat4& viewProj);

// Uploads an RGBA8 image with mipmaps (sRGB when it holds colour), trilinear, with at most
// `anisotropy` anisotropic samples.
gl::Texture uploadImage(const scene::Image& image, float anisotropy = 1.0f);

}  // namespace penumbra::render
