#include "scene/io/ModelImporter.h"

#include "scene/io/FormatChecks.h"

#include "util/Error.h"
#include "util/Log.h"

#include <assimp/GltfMaterial.h>
#include <assimp/ObjMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <mutex>
#include <poll.h>
#include <sstream>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

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
        sanitise(out);
        scene_.materials.push_back(out);
        return static_cast<int>(scene_.materials.size()) - 1;
    }

private:
    // Files carry any number: an OBJ `d 3`, a glTF alpha of -1, a NaN colour. Values outside
    // what the renderer's equations mean are clamped into range, with a warning naming them.
    void sanitise(Material& out) const {
        std::string fixed;
        auto clampTo = [&](float& v, float lo, float hi, float fallback, const char* what) {
            const float before = v;
            v = std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
            if (v != before && fixed.find(what) == std::string::npos) fixed += std::string(fixed.empty() ? "" : ", ") + what;
        };
        clampTo(out.alpha, 0.0f, 1.0f, 1.0f, "opacity");
        clampTo(out.alphaCutoff, 0.0f, 2.0f, 0.0f, "alpha cutoff");  // glTF: >= 0; above 1 all is cut
        clampTo(out.shininess, 1e-3f, 1e4f, 32.0f, "shininess");
        for (int i = 0; i < 3; ++i) {
            clampTo(out.transmission[i], 0.0f, 1.0f, 0.0f, "transmission");
            clampTo(out.diffuse[i], 0.0f, 1e3f, 0.8f, "diffuse colour");
            clampTo(out.specular[i], 0.0f, 1e3f, 0.0f, "specular colour");
        }
        if (!fixed.empty())
            log::warn("{}: material '{}': {} out of range, clamped", file_.string(), out.name, fixed);
    }

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
// Hand-parsed: the message may be long and carry numbers of any size.
int lineFromMessage(const std::string& msg) {
    for (std::size_t at = msg.find("ine"); at != std::string::npos; at = msg.find("ine", at + 1)) {
        if (at == 0 || (msg[at - 1] != 'L' && msg[at - 1] != 'l')) continue;
        std::size_t i = at + 3;
        while (i < msg.size() && (msg[i] == ':' || msg[i] == ' ')) ++i;
        long line = 0;
        std::size_t n = 0;
        for (; i < msg.size() && std::isdigit(static_cast<unsigned char>(msg[i])) && n < 9; ++i, ++n) line = line * 10 + (msg[i] - '0');
        if (n > 0 && i > at + 3) return static_cast<int>(line);
    }
    return 0;
}

int importTimeoutSeconds = 120;

// The one way penumbra reads a file with Assimp: triangles only, smooth normals, validated. The
// probe child and this process must read identically for the probe to vouch for the real read.
const aiScene* readWithAssimp(Assimp::Importer& importer, const fs::path& file) {
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* raw = importer.ReadFile(file.string(), 0);
    if (!raw) return nullptr;
    // Assimp's OBJ reader turns two-vertex faces ("f 1 2", as in Sweet Home 3D's park-light.obj)
    // into LINE faces without reporting LINE in the mesh's primitive types, which validation then
    // rejects and SortByPType cannot remove. Recount the types from the faces first.
    for (unsigned m = 0; raw->mMeshes && m < raw->mNumMeshes; ++m) {
        aiMesh* mesh = raw->mMeshes[m];
        if (!mesh || !mesh->mFaces) continue;  // validation names what is missing
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const unsigned n = mesh->mFaces[f].mNumIndices;
            types |= n == 1 ? aiPrimitiveType_POINT : n == 2 ? aiPrimitiveType_LINE : n == 3 ? aiPrimitiveType_TRIANGLE : aiPrimitiveType_POLYGON;
        }
        if (types) mesh->mPrimitiveTypes = types;
    }
    return importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                                        aiProcess_SortByPType | aiProcess_ValidateDataStructure | aiProcess_FindInvalidData);
}

std::string assimpName() {
    return "the importer (Assimp " + std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) + ")";
}

// Assimp (Debian's 5.2) crashes on some malformed OBJ files and loops forever on some PLY
// headers; tests/fuzz found both. Its reader therefore runs first in a helper process: if the
// helper dies or overruns the time limit, the file is refused with a message, and penumbra goes
// on. Only when the helper read the file cleanly does this process read it (Assimp is
// deterministic), so the importer costs one extra parse and nothing can take the program down.
//
// The helper is forked once and reads file after file; it is forked again only after it died or
// was stopped. A fork per file cost 40-140 ms (copying the page tables of a large process, and
// Assimp's buffers copied on write): the model fuzz targets ran at 7-30 files/s.
class ImportProbe {
public:
    ~ImportProbe() { stop(); }

    // Throws InputError when the helper crashed on `file` or overran the limit; returns when it
    // read the file (or when no helper can be had: then the file is read in-process, as before).
    void check(const fs::path& file) {
        const std::lock_guard lock(mutex_);
        const std::string path = file.string();
        // A helper that died between files (killed from outside, or with the thread that forked
        // it: PR_SET_PDEATHSIG follows threads) is replaced before the file is blamed.
        if (!ask(path)) {
            stop();
            if (!ask(path)) return;
        }
        using Clock = std::chrono::steady_clock;
        const auto deadline = Clock::now() + std::chrono::seconds(importTimeoutSeconds);
        char done = 0;
        int ready = -1;
        while (true) {  // signals (a profiler's or a fuzzer's timer) interrupt poll, which then resumes
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
            pollfd pfd{socket_, POLLIN, 0};
            ready = left > 0 ? ::poll(&pfd, 1, static_cast<int>(left)) : 0;
            if (ready >= 0 || errno != EINTR) break;
        }
        if (ready > 0 && ::recv(socket_, &done, 1, 0) == 1) return;  // read cleanly
        const bool overran = ready <= 0;
        const int status = stop();
        if (overran)
            throw InputError(file, "cannot read model: " + assimpName() + " did not finish within " +
                                       std::to_string(importTimeoutSeconds) + " s; the file is malformed or too large");
        throw InputError(file, "cannot read model: " + assimpName() + " crashed on this file (signal " +
                                   std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0) + "); the file is malformed");
    }

private:
    // Sends the path to the helper, starting one if there is none; false if it could not be sent.
    bool ask(const std::string& path) {
        if (owner_ != ::getpid()) forget();  // a forked copy of this process has no helper of its own
        if (child_ < 0 && !start()) return false;
        const auto size = static_cast<std::uint32_t>(path.size());
        return sendAll(&size, sizeof size) && sendAll(path.data(), path.size());
    }

    bool sendAll(const void* data, std::size_t size) {  // a dead helper: EPIPE, not SIGPIPE
        return moveAll(static_cast<const char*>(data), size,
                       [&](const char* at, std::size_t n) { return ::send(socket_, at, n, MSG_NOSIGNAL); });
    }

    static bool receiveAll(int socket, void* data, std::size_t size) {
        return moveAll(static_cast<char*>(data), size,
                       [socket](char* at, std::size_t n) { return ::recv(socket, at, n, 0); });
    }

    // Repeats `io` (a send or a recv) until `size` bytes have moved; false when the other side is gone.
    template <typename Byte, typename Io>
    static bool moveAll(Byte* at, std::size_t size, Io io) {
        while (size > 0) {
            const ssize_t n = io(at, size);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            at += n;
            size -= static_cast<std::size_t>(n);
        }
        return true;
    }

    bool start() {
        int fds[2];
        if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) return false;
        const pid_t child = ::fork();
        if (child < 0) {
            ::close(fds[0]);
            ::close(fds[1]);
            return false;
        }
        if (child == 0) {
            ::close(fds[0]);
            serve(fds[1]);
        }
        ::close(fds[1]);
        child_ = child;
        socket_ = fds[0];
        owner_ = ::getpid();
        return true;
    }

    // The helper: reads each path it is sent and answers one byte, until its socket closes.
    [[noreturn]] static void serve(int socket) {
        // Default actions for crash signals, so a crash ends only the helper quietly (a fuzzer's
        // or sanitizer's handler would otherwise report the helper's crash as the parent's).
        for (int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) ::signal(sig, SIG_DFL);
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the program that asked
        if (::getppid() == 1) ::_exit(0);
        std::string path;
        while (true) {
            std::uint32_t size = 0;
            if (!receiveAll(socket, &size, sizeof size)) ::_exit(0);
            path.resize(size);
            if (!receiveAll(socket, path.data(), size)) ::_exit(0);
            {
                Assimp::Importer importer;
                readWithAssimp(importer, path);
            }
            const char done = 1;
            if (::send(socket, &done, 1, MSG_NOSIGNAL) != 1) ::_exit(0);
        }
    }

    // Stops the helper (if any) and returns its wait status.
    int stop() {
        if (child_ < 0 || owner_ != ::getpid()) {
            forget();
            return 0;
        }
        ::close(socket_);  // a waiting helper exits; a busy or stuck one is killed
        ::kill(child_, SIGKILL);
        int status = 0;
        while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {}
        child_ = -1;
        socket_ = -1;
        return status;
    }

    void forget() {
        if (socket_ >= 0) ::close(socket_);
        child_ = -1;
        socket_ = -1;
        owner_ = ::getpid();
    }

    std::mutex mutex_;
    pid_t child_ = -1, owner_ = -1;
    int socket_ = -1;
};

}  // namespace

void setModelImportTimeout(int seconds) { importTimeoutSeconds = std::max(1, seconds); }

void probeWithAssimp(const fs::path& file) {
    static ImportProbe probe;
    probe.check(file);
}

int importModel(const fs::path& file, Scene& scene) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw InputError(file, "model file not found");
    // A folder or a device (/dev/zero, a FIFO) would make the importer fail or read forever.
    if (!fs::is_regular_file(file, ec)) throw InputError(file, "model path is not a regular file");
    checkPly(file);  // files that break their format's rules never reach Assimp (FormatChecks.h)
    checkGltf(file);
    probeWithAssimp(file);
    Assimp::Importer importer;
    const aiScene* ai = readWithAssimp(importer, file);
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
    // Coordinates near float's limit overflow every product the renderer forms (extent, light
    // boxes, the framing camera); 1e15 is far beyond any real scene in any unit.
    const float reach = std::max(glm::length(mesh.bounds.min), glm::length(mesh.bounds.max));
    if (!std::isfinite(reach) || reach > 1e15f || !std::isfinite(glm::length(mesh.bounds.extent())))
        throw InputError(file, "model coordinates are out of range (beyond 1e15 from the origin)");
    scene.meshes.push_back(std::move(mesh));
    return static_cast<int>(scene.meshes.size()) - 1;
}

}  // namespace penumbra::scene::io
