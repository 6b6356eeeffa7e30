#include "render/GpuScene.h"

#include "gpu/ShaderContract.h"

#include <algorithm>
#include <cmath>

namespace penumbra::render {

gl::Texture uploadImage(const scene::Image& img, float anisotropy) {
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(img.width, img.height))));
    gl::Texture t = gl::Texture::create2D(img.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, img.width, img.height, levels);
    glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    glGenerateTextureMipmap(t.id());
    t.setWrap(GL_REPEAT);
    t.setFilter(img.fallback ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR, img.fallback ? GL_NEAREST : GL_LINEAR);
    glTextureParameterf(t.id(), GL_TEXTURE_MAX_ANISOTROPY, anisotropy);
    return t;
}

GpuScene::GpuScene(const scene::Scene& scene, float anisotropy, bool clusters) : scene_(scene) {
    for (const auto& mesh : scene.meshes) {
        ClusteredIndices clustered = clusters ? clusterMesh(mesh) : ClusteredIndices{mesh.indices, std::vector<std::vector<MeshCluster>>(mesh.parts.size())};
        GpuMesh g{gl::Buffer(std::span<const scene::Vertex>(mesh.vertices)),
                  gl::Buffer(std::span<const std::uint32_t>(clustered.indices)), gl::VertexArray(), std::move(clustered.clusters)};
        glVertexArrayVertexBuffer(g.vao.id(), 0, g.vertices.id(), 0, sizeof(scene::Vertex));
        glVertexArrayElementBuffer(g.vao.id(), g.indices.id());
        g.vao.attribute(0, 0, 3, offsetof(scene::Vertex, position));
        g.vao.attribute(1, 0, 3, offsetof(scene::Vertex, normal));
        g.vao.attribute(2, 0, 2, offsetof(scene::Vertex, uv));
        g.closedParts.assign(mesh.parts.size(), false);
        g.flatOrConvexParts.assign(mesh.parts.size(), false);
        g.faceNormalParts.assign(mesh.parts.size(), false);
        g.planes.assign(mesh.parts.size(), std::nullopt);
        meshes_.push_back(std::move(g));
    }
    // Each mesh once, however many objects draw it, and none that no object draws.
    std::vector<bool> judged(scene.meshes.size());
    for (const auto& object : scene.objects) {
        const auto meshIndex = static_cast<std::size_t>(object.mesh);
        if (judged[meshIndex]) continue;
        judged[meshIndex] = true;
        meshes_[meshIndex].closedParts = scene.meshes[meshIndex].closedParts();
        for (std::size_t p = 0; p < scene.meshes[meshIndex].parts.size(); ++p) {
            if (!meshes_[meshIndex].closedParts[p]) meshes_[meshIndex].planes[p] = scene.meshes[meshIndex].partPlane(p);
            meshes_[meshIndex].flatOrConvexParts[p] = meshes_[meshIndex].closedParts[p] ? scene.meshes[meshIndex].partIsConvex(p)
                                                                                        : meshes_[meshIndex].planes[p].has_value();
            meshes_[meshIndex].faceNormalParts[p] = meshes_[meshIndex].flatOrConvexParts[p] && scene.meshes[meshIndex].partHasFaceNormals(p);
        }
    }
    for (const auto& img : scene.images) {
        images_.push_back(uploadImage(img, anisotropy));
        translucentAlpha_.push_back(img.hasTranslucentAlpha());
    }
}

void GpuScene::setAnisotropy(float anisotropy) {
    for (const gl::Texture& t : images_) glTextureParameterf(t.id(), GL_TEXTURE_MAX_ANISOTROPY, anisotropy);
}

std::vector<Draw> GpuScene::draws(float time, const glm::vec3& eye) const {
    std::vector<Draw> out;
    for (std::size_t o = 0; o < scene_.objects.size(); ++o) {
        const scene::Object& obj = scene_.objects[o];
        const glm::mat4 model = obj.transformAt(time);
        const auto meshIndex = static_cast<std::size_t>(obj.mesh);
        const scene::Mesh& mesh = scene_.meshes[meshIndex];
        for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
            const scene::Material& mat = scene_.material(obj, mesh.parts[p]);
            const bool textureAlpha = mat.diffuseTexture >= 0 && mat.alphaCutoff <= 0 &&
                                      translucentAlpha_[static_cast<std::size_t>(mat.diffuseTexture)];
            Draw d{o, meshIndex, p, &mat, model, mat.translucent() || textureAlpha, obj.castsShadow, obj.visible};
            d.moving = !obj.animation.empty();
            const GpuMesh& g = meshes_[meshIndex];
            // A mirroring transform turns the winding inside out; such parts are drawn whole.
            d.solid = g.closedParts[p] && mat.alphaCutoff <= 0.0f && glm::determinant(glm::mat3(model)) > 0.0f;
            d.ownLayersKnown = g.flatOrConvexParts[p] && (!g.closedParts[p] || mat.diffuseTexture < 0);
            d.selfShadowFree = g.flatOrConvexParts[p] && (!g.closedParts[p] || (d.solid && g.faceNormalParts[p]));
            d.plane = g.planes[p];
            // Painter's order by the object's centre (as Mátl 2013 did); sorted-triangles sorts within each object.
            d.viewDepth = glm::length(glm::vec3(model * glm::vec4(mesh.bounds.center(), 1.0f)) - eye);
            d.worldBounds = mesh.bounds.transformed(model);
            d.meshBounds = mesh.bounds;
            for (int i = 0; i < 8; ++i) d.farthest = std::max(d.farthest, glm::length(d.worldBounds.corner(i) - eye));
            d.triangles = mesh.parts[p].indexCount / 3;
            out.push_back(d);
        }
    }
    // Opaque parts first, nearest farthest corner first: the ground and other big surfaces behind
    // the rest come last, so the early depth test drops their hidden fragments before shading.
    // Measured (llvmpipe, 1280x720, three alternated rounds against scene order, opaque pass):
    // default scene hard 33.6-39.9 -> 31.0-36.2 ms, cssm2 42.3-60.9 -> 35.8-45.7; glass scene hard
    // 34.2-41.3 -> 28.7-35.2, cssm2 48.5-58.0 -> 40.8-48.2. The box centre's distance (the
    // translucent order) gained nothing: a ground plane's centre is as near as the objects on it.
    std::stable_sort(out.begin(), out.end(), [](const Draw& a, const Draw& b) {
        if (a.translucent != b.translucent) return !a.translucent;
        return a.translucent ? a.viewDepth > b.viewDepth : a.farthest < b.farthest;
    });
    return out;
}

void GpuScene::drawTrianglesSorted(const Draw& d, const gl::Program& program, const glm::vec3& eye) const {
    const scene::Mesh& mesh = scene_.meshes[d.mesh];
    const scene::MeshPart& part = mesh.parts[d.part];
    const std::uint32_t count = part.indexCount / 3;
    std::vector<std::pair<float, std::uint32_t>> order(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        const std::uint32_t* tri = &mesh.indices[part.firstIndex + 3 * t];
        const glm::vec3 c = (mesh.vertices[tri[0]].position + mesh.vertices[tri[1]].position + mesh.vertices[tri[2]].position) / 3.0f;
        order[t] = {-glm::length(glm::vec3(d.model * glm::vec4(c, 1.0f)) - eye), t};  // farthest first
    }
    std::sort(order.begin(), order.end());
    std::vector<std::uint32_t> indices;
    indices.reserve(part.indexCount);
    for (const auto& [depth, t] : order)
        for (int k = 0; k < 3; ++k) indices.push_back(mesh.indices[part.firstIndex + 3 * t + k]);
    const std::size_t bytes = indices.size() * sizeof(std::uint32_t);
    if (sortedIndices_.size() < bytes) sortedIndices_ = gl::Buffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    sortedIndices_.update(0, bytes, indices.data());
    const GpuMesh& g = meshes_[d.mesh];
    glVertexArrayElementBuffer(g.vao.id(), sortedIndices_.id());
    prepare(d, program);
    drawRange(0, static_cast<GLsizei>(indices.size()));
    glVertexArrayElementBuffer(g.vao.id(), g.indices.id());
}

void GpuScene::draw(const Draw& d, const gl::Program& program) const {
    prepare(d, program);
    drawPrepared(d);
}

void GpuScene::drawPrepared(const Draw& d) const {
    const scene::MeshPart& part = scene_.meshes[d.mesh].parts[d.part];
    drawRange(part.firstIndex, static_cast<GLsizei>(part.indexCount));
}

std::optional<std::vector<IndexRange>> GpuScene::rangesInside(const Draw& d, const glm::mat4& viewProj,
                                                               std::span<const glm::vec4> planes) const {
    const std::vector<MeshCluster>& clusters = meshes_[d.mesh].clusters[d.part];
    if (clusters.empty()) return std::nullopt;
    std::vector<glm::vec4> meshPlanes;  // dot(p, M x) = dot(transpose(M) p, x)
    meshPlanes.reserve(planes.size());
    for (const glm::vec4& p : planes) meshPlanes.push_back(glm::transpose(d.model) * p);
    return visibleRanges(clusters, viewProj * d.model, meshPlanes);
}

std::size_t GpuScene::drawInside(const Draw& d, const gl::Program& program, const glm::mat4& viewProj,
                                 std::span<const glm::vec4> planes) const {
    const std::optional<std::vector<IndexRange>> ranges = rangesInside(d, viewProj, planes);
    if (!ranges) {
        draw(d, program);
        return d.triangles;
    }
    std::size_t triangles = 0;
    if (!ranges->empty()) prepare(d, program);
    for (const IndexRange& r : *ranges) {
        drawRange(r.firstIndex, static_cast<GLsizei>(r.indexCount));
        triangles += r.indexCount / 3;
    }
    return triangles;
}

void GpuScene::prepare(const Draw& d, const gl::Program& program) const {
    const scene::Material& m = *d.material;
    program.set("uModel", d.model);
    program.set("uDiffuse", m.diffuse);
    program.set("uSpecular", m.specular);
    program.set("uShininess", m.shininess);
    program.set("uAlpha", m.alpha);
    program.set("uTransmission", m.transmission);
    program.set("uAlphaCutoff", m.alphaCutoff);
    program.set("uHasTexture", m.diffuseTexture >= 0 ? 1 : 0);
    program.set("uClosedPart", m.diffuseTexture < 0 && meshes_[d.mesh].closedParts[d.part] ? 1 : 0);
    if (m.diffuseTexture >= 0) images_[static_cast<std::size_t>(m.diffuseTexture)].bind(gpu::kUnitDiffuse);
    program.use();
    meshes_[d.mesh].vao.bind();
}

void GpuScene::drawRange(std::uint32_t firstIndex, GLsizei count) {
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(firstIndex) * sizeof(std::uint32_t)));
}

void GpuScene::addSurfaceBounds(const Draw& d, std::vector<scene::Bounds>& out) const {
    const auto& clusters = meshes_[d.mesh].clusters;
    if (d.part >= clusters.size() || clusters[d.part].empty()) {
        out.push_back(d.worldBounds);
        return;
    }
    for (const MeshCluster& c : clusters[d.part]) out.push_back(c.bounds.transformed(d.model));
}

void cullBackFacesOfSolid(const Draw& d, bool cull, const glm::mat4& viewProj) {
    if (d.solid && cull && !nearPlaneMayCut(viewProj, d.worldBounds)) glEnable(GL_CULL_FACE);
    else glDisable(GL_CULL_FACE);
}

}  // namespace penumbra::render
