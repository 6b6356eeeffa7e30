#include "scene/io/ModelImporter.h"

#include "util/Error.h"
#include "util/Log.h"

#include <assimp/GltfMaterial.h>
#include <assimp/ObjMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <regex>

namespace penumbra::scene::io {

namespace fs = std::filesystem;

namespace {

glm::vec3 toVec3(const aiColor4D& c) { return {c.r, c.g, c.b}; }

class MaterialMapper {
public:
    MaterialMapper(const aiScene& ai, const fs::path& file, Scene& scene) : ai_(ai), file_(file), scene_(scene) {}

    int map(const aiMaterial& m) {
        Material out;
        aiString name;
        if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
        aiColor4D c;
        aiColor4D base;
        const bool hasBase = m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS;
        if (hasBase) out.diffuse = toVec3(base);
        else if (m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) out.diffuse = toVec3(c);
        if (m.Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS) out.specular = toVec3(c);
        float f = 0;
        if (m.Get(AI_MATKEY_SHININESS, f) == AI_SUCCESS && f > 0) out.shininess = f;
        if (m.Get(AI_MATKEY_OPACITY, f) == AI_SUCCESS) out.alpha = f;  // OBJ `d` (Assimp maps `Tr` to 1-Tr)
        mapTransmission(m, out, hasBase ? toVec3(base) : out.diffuse);
        mapAlphaMode(m, out, hasBase ? base.a : 1.0f);
        int twoSided = 0;
        if (m.Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) out.doubleSided = twoSided != 0;
        out.diffuseTexture = texture(m);
        scene_.materials.push_back(out);
        return static_cast<int>(scene_.materials.size()) - 1;
    }

private:
    // OBJ: `Tf` is the transmission filter of a material whose illumination model refracts
    // (illum 4, 6, 7, 9); elsewhere Tf (often "1 1 1" on opaque walls) carries no meaning.
    // glTF: KHR_materials_transmission scales the tint, which is the volume attenuation colour
    // when KHR_materials_volume gives one, else the base colour (thin-walled glass).
    void mapTransmission(const aiMaterial& m, Material& out, const glm::vec3& baseColor) {
        float transmission = 0;
        if (m.Get(AI_MATKEY_TRANSMISSION_FACTOR, transmission) == AI_SUCCESS && transmission > 0) {
            aiColor3D att(1, 1, 1);
            glm::vec3 tint = baseColor;
            if (m.Get(AI_MATKEY_VOLUME_ATTENUATION_COLOR, att) == AI_SUCCESS) tint = {att.r, att.g, att.b};
            out.transmission = tint * transmission;
            return;
        }
        int illum = 0;
        aiColor3D tf;
        if (m.Get(AI_MATKEY_OBJ_ILLUM, illum) == AI_SUCCESS && (illum == 4 || illum == 6 || illum == 7 || illum == 9) &&
            m.Get(AI_MATKEY_COLOR_TRANSPARENT, tf) == AI_SUCCESS)
            out.transmission = {tf.r, tf.g, tf.b};
    }

    void mapAlphaMode(const aiMaterial& m, Material& out, float baseAlpha) {
        aiString mode;
        if (m.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) != AI_SUCCESS) return;
        const std::string s = mode.C_Str();
        if (s == "OPAQUE") {
            out.alpha = 1.0f;
        } else if (s == "MASK") {
            float cutoff = 0.5f;
            m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff);
            out.alphaCutoff = cutoff;
            out.alpha = 1.0f;
        } else if (s == "BLEND") {
            out.alpha = baseAlpha;
        }
    }

    int texture(const aiMaterial& m) {
        aiString path;
        if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &path) != AI_SUCCESS &&
            m.GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS)
            return -1;
        const std::string key = path.C_Str();
        if (auto it = cache_.find(key); it != cache_.end()) return it->second;
        Image img;
        if (const aiTexture* embedded = ai_.GetEmbeddedTexture(key.c_str())) {
            if (embedded->mHeight != 0) {
                log::warn("{}: uncompressed embedded texture '{}' is not supported; using a checker", file_.string(), key);
                img = checkerImage();
            } else {
                img = imageFromMemory(reinterpret_cast<const std::uint8_t*>(embedded->pcData), embedded->mWidth,
                                      file_.string() + ":" + key);
            }
        } else {
            std::string rel = key;
            std::replace(rel.begin(), rel.end(), '\\', '/');
            img = loadImageOrChecker(file_.parent_path() / rel, file_.string());
        }
        scene_.images.push_back(std::move(img));
        const int index = static_cast<int>(scene_.images.size()) - 1;
        cache_[key] = index;
        return index;
    }

    const aiScene& ai_;
    fs::path file_;
    Scene& scene_;
    std::map<std::string, int> cache_;
};

// Flattens the node hierarchy into one mesh, one part per (aiMesh) with node transforms baked in.
void appendNode(const aiScene& ai, const aiNode& node, const aiMatrix4x4& parent, const std::vector<int>& materialMap,
                Mesh& out) {
    const aiMatrix4x4 world = parent * node.mTransformation;
    glm::mat4 m = glm::transpose(glm::make_mat4(&world.a1));
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *ai.mMeshes[node.mMeshes[i]];
        if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            Vertex vert{};
            const aiVector3D& p = mesh.mVertices[v];
            vert.position = glm::vec3(m * glm::vec4(p.x, p.y, p.z, 1.0f));
            if (mesh.mNormals) {
                const aiVector3D& n = mesh.mNormals[v];
                const glm::vec3 wn = normalMatrix * glm::vec3(n.x, n.y, n.z);
                vert.normal = glm::length(wn) > 0 ? glm::normalize(wn) : glm::vec3(0, 1, 0);
            }
            // Images are stored top row first, so v is flipped here once for every format.
            if (mesh.mTextureCoords[0]) vert.uv = {mesh.mTextureCoords[0][v].x, 1.0f - mesh.mTextureCoords[0][v].y};
            out.vertices.push_back(vert);
        }
        MeshPart part;
        part.firstIndex = static_cast<std::uint32_t>(out.indices.size());
        part.material = materialMap[mesh.mMaterialIndex];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;
            for (int k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
        }
        part.indexCount = static_cast<std::uint32_t>(out.indices.size()) - part.firstIndex;
        if (part.indexCount > 0) out.parts.push_back(part);
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(ai, *node.mChildren[c], world, materialMap, out);
}

// Assimp's messages often carry "Line N" or "line N"; surface it as file:N.
int lineFromMessage(const std::string& msg) {
    static const std::regex re(R"([Ll]ine[: ]+(\d+))");
    std::smatch m;
    return std::regex_search(msg, m, re) ? std::stoi(m[1]) : 0;
}

}  // namespace

int importModel(const fs::path& file, Scene& scene) {
    if (!fs::exists(file)) throw InputError(file, "model file not found");
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                           aiProcess_SortByPType | aiProcess_ValidateDataStructure | aiProcess_FindInvalidData;
    const aiScene* ai = importer.ReadFile(file.string(), flags);
    if (!ai || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode) {
        const std::string msg = importer.GetErrorString();
        throw InputError(file, lineFromMessage(msg), "cannot read model: " + (msg.empty() ? "unknown error" : msg));
    }
    MaterialMapper mapper(*ai, file, scene);
    std::vector<int> materialMap;
    for (unsigned i = 0; i < ai->mNumMaterials; ++i) materialMap.push_back(mapper.map(*ai->mMaterials[i]));
    if (materialMap.empty()) {
        scene.materials.push_back(Material{});
        materialMap.push_back(static_cast<int>(scene.materials.size()) - 1);
    }
    Mesh mesh;
    mesh.name = file.filename().string();
    appendNode(*ai, *ai->mRootNode, aiMatrix4x4(), materialMap, mesh);
    if (mesh.indices.empty()) throw InputError(file, "model contains no triangles");
    for (const auto& v : mesh.vertices)
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z))
            throw InputError(file, "model has non-finite vertex positions");
    mesh.computeBounds();
    scene.meshes.push_back(std::move(mesh));
    return static_cast<int>(scene.meshes.size()) - 1;
}

}  // namespace penumbra::scene::io
