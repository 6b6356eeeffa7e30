#include "render/GpuScene.h"

#include "render/Bindings.h"

#include <algorithm>
#include <cmath>

namespace penumbra::render {

gl::Texture uploadImage(const scene::Image& img) {
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(img.width, img.height))));
    gl::Texture t = gl::Texture::create2D(img.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, img.width, img.height, levels);
    glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    glGenerateTextureMipmap(t.id());
    t.setWrap(GL_REPEAT);
    t.setFilter(img.fallback ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR, img.fallback ? GL_NEAREST : GL_LINEAR);
    glTextureParameterf(t.id(), GL_TEXTURE_MAX_ANISOTROPY, 8.0f);
    return t;
}

GpuScene::GpuScene(const scene::Scene& scene) : scene_(scene) {
    for (const auto& mesh : scene.meshes) {
        GpuMesh g{gl::Buffer(std::span<const scene::Vertex>(mesh.vertices)),
                  gl::Buffer(std::span<const std::uint32_t>(mesh.indices)), gl::VertexArray()};
        glVertexArrayVertexBuffer(g.vao.id(), 0, g.vertices.id(), 0, sizeof(scene::Vertex));
        glVertexArrayElementBuffer(g.vao.id(), g.indices.id());
        g.vao.attribute(0, 0, 3, offsetof(scene::Vertex, position));
        g.vao.attribute(1, 0, 3, offsetof(scene::Vertex, normal));
        g.vao.attribute(2, 0, 2, offsetof(scene::Vertex, uv));
        meshes_.push_back(std::move(g));
    }
    for (const auto& img : scene.images) images_.push_back(uploadImage(img));
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
                                      scene_.images[static_cast<std::size_t>(mat.diffuseTexture)].hasTranslucentAlpha();
            Draw d{o, meshIndex, p, &mat, model, mat.translucent() || textureAlpha, obj.castsShadow, obj.visible};
            // Painter's order by the object's centre (as seed 000 did); per-triangle order is issue 5.
            d.viewDepth = glm::length(glm::vec3(model * glm::vec4(mesh.bounds.center(), 1.0f)) - eye);
            out.push_back(d);
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const Draw& a, const Draw& b) {
        if (a.translucent != b.translucent) return !a.translucent;
        return a.translucent && a.viewDepth > b.viewDepth;
    });
    return out;
}

void GpuScene::draw(const Draw& d, const gl::Program& program) const {
    const scene::Material& m = *d.material;
    program.set("uModel", d.model);
    program.set("uDiffuse", m.diffuse);
    program.set("uSpecular", m.specular);
    program.set("uShininess", m.shininess);
    program.set("uAlpha", m.alpha);
    program.set("uTransmission", m.transmission);
    program.set("uAlphaCutoff", m.alphaCutoff);
    program.set("uHasTexture", m.diffuseTexture >= 0 ? 1 : 0);
    if (m.diffuseTexture >= 0) images_[static_cast<std::size_t>(m.diffuseTexture)].bind(kUnitDiffuse);
    const GpuMesh& g = meshes_[d.mesh];
    const scene::MeshPart& part = scene_.meshes[d.mesh].parts[d.part];
    program.use();
    g.vao.bind();
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(part.indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(static_cast<std::uintptr_t>(part.firstIndex) * sizeof(std::uint32_t)));
}

}  // namespace penumbra::render
