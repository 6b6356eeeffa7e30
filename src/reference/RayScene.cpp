#include "reference/RayScene.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace penumbra::reference {

namespace {
// What a hit needs to know about the surface it landed on.
struct Surface {
    const scene::Material* material;
    const scene::Image* texture;  // null when untextured
};
struct GeometryData {
    std::vector<glm::vec2> uvs;           // per vertex
    std::vector<std::uint32_t> indices;   // per triangle: 3
    std::vector<int> surfaceOfTriangle;   // index into surfaces
};

// Bilinear-free (nearest texel) alpha lookup with wrapping: matches GL_REPEAT closely enough
// for coverage; the rasteriser's filtering differs only at texel edges.
float textureAlpha(const scene::Image& img, glm::vec2 uv) {
    uv -= glm::floor(uv);
    const int x = std::min(img.width - 1, static_cast<int>(uv.x * img.width));
    const int y = std::min(img.height - 1, static_cast<int>(uv.y * img.height));
    return img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4 + 3] / 255.0f;
}
}  // namespace

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene rtc = nullptr;
    std::vector<Surface> surfaces;
    std::vector<GeometryData> geometries;  // indexed by Embree geomID
};

RayScene::RayScene(const scene::Scene& s, float time) : impl_(std::make_unique<Impl>()) {
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device) throw std::runtime_error("Embree: cannot create a device (error " +
                                                 std::to_string(rtcGetDeviceError(nullptr)) + ")");
    impl_->rtc = rtcNewScene(impl_->device);
    rtcSetSceneFlags(impl_->rtc, RTC_SCENE_FLAG_ROBUST);
    const scene::Bounds bounds = s.boundsAt(time);
    radius_ = std::max(glm::length(bounds.extent()) * 0.5f, 1e-3f);

    for (const auto& object : s.objects) {
        const scene::Mesh& mesh = s.meshes[static_cast<std::size_t>(object.mesh)];
        if (!object.castsShadow || mesh.indices.empty()) continue;
        const glm::mat4 model = object.transformAt(time);
        GeometryData data;
        data.indices = mesh.indices;
        data.uvs.reserve(mesh.vertices.size());
        RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.vertices.size()));
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            const glm::vec3 p = glm::vec3(model * glm::vec4(mesh.vertices[i].position, 1.0f));
            v[3 * i] = p.x;
            v[3 * i + 1] = p.y;
            v[3 * i + 2] = p.z;
            data.uvs.push_back(mesh.vertices[i].uv);
        }
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), mesh.indices.size() / 3));
        std::copy(mesh.indices.begin(), mesh.indices.end(), idx);
        data.surfaceOfTriangle.resize(mesh.indices.size() / 3);
        for (const auto& part : mesh.parts) {
            const scene::Material& m = s.material(object, part);
            const scene::Image* tex = m.diffuseTexture >= 0 ? &s.images[static_cast<std::size_t>(m.diffuseTexture)] : nullptr;
            impl_->surfaces.push_back({&m, tex});
            for (std::uint32_t t = part.firstIndex / 3; t < (part.firstIndex + part.indexCount) / 3; ++t)
                data.surfaceOfTriangle[t] = static_cast<int>(impl_->surfaces.size()) - 1;
        }
        rtcCommitGeometry(geom);
        const unsigned id = rtcAttachGeometry(impl_->rtc, geom);
        rtcReleaseGeometry(geom);
        if (impl_->geometries.size() <= id) impl_->geometries.resize(id + 1);
        impl_->geometries[id] = std::move(data);
        triangles_ += mesh.indices.size() / 3;
    }
    rtcCommitScene(impl_->rtc);
}

RayScene::~RayScene() {
    if (impl_->rtc) rtcReleaseScene(impl_->rtc);
    if (impl_->device) rtcReleaseDevice(impl_->device);
}

static RTCRayHit makeRay(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) {
    RTCRayHit rh{};
    rh.ray.org_x = o.x;
    rh.ray.org_y = o.y;
    rh.ray.org_z = o.z;
    rh.ray.dir_x = d.x;
    rh.ray.dir_y = d.y;
    rh.ray.dir_z = d.z;
    rh.ray.tnear = tMin;
    rh.ray.tfar = tMax;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

glm::vec3 RayScene::transmittance(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const {
    glm::vec3 throughput(1.0f);
    // Step past each surface along the segment; an epsilon relative to the scene keeps a ray from
    // hitting the same triangle again.
    const float step = radius_ * 1e-6f;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (int layer = 0; layer < 4096 && tMin < tMax; ++layer) {
        RTCRayHit rh = makeRay(origin, dir, tMin, tMax);
        rtcIntersect1(impl_->rtc, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
        const GeometryData& g = impl_->geometries[rh.hit.geomID];
        const Surface& surface = impl_->surfaces[static_cast<std::size_t>(g.surfaceOfTriangle[rh.hit.primID])];
        const scene::Material& m = *surface.material;
        float coverage = m.alpha;
        if (surface.texture) {
            const std::uint32_t* tri = &g.indices[3 * static_cast<std::size_t>(rh.hit.primID)];
            const glm::vec2 uv = (1.0f - rh.hit.u - rh.hit.v) * g.uvs[tri[0]] + rh.hit.u * g.uvs[tri[1]] + rh.hit.v * g.uvs[tri[2]];
            const float a = textureAlpha(*surface.texture, uv);
            if (m.alphaCutoff > 0.0f) coverage = a < m.alphaCutoff ? 0.0f : m.alpha;
            else coverage *= a;
        }
        throughput *= glm::vec3(1.0f) - (glm::vec3(1.0f) - m.transmission) * coverage;
        if (glm::all(glm::lessThanEqual(throughput, glm::vec3(0.0f)))) return glm::vec3(0.0f);
        tMin = rh.ray.tfar + step;
    }
    return throughput;
}

float RayScene::firstHit(const glm::vec3& origin, const glm::vec3& dir) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = makeRay(origin, dir, 0.0f, std::numeric_limits<float>::infinity());
    rtcIntersect1(impl_->rtc, &context, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity() : rh.ray.tfar;
}

}  // namespace penumbra::reference
