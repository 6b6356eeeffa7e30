#include "reference/Visibility.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace penumbra::reference {

using scene::Light;

namespace {

// PCG-style integer hash: decorrelated per-pixel, per-sample jitter, reproducible run to run.
std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}
float unit(std::uint32_t x) { return static_cast<float>(hash(x) >> 8) * (1.0f / 16777216.0f); }

// Stratified point on the unit disk: cell (i, j) of an n x n grid, jittered, warped with
// x = sqrt(v) cos 2πu, y = sqrt(v) sin 2πu (uniform area density).
glm::vec2 diskSample(int i, int j, int n, std::uint32_t seed) {
    const float u = (static_cast<float>(i) + unit(seed * 2u + 1u)) / static_cast<float>(n);
    const float v = (static_cast<float>(j) + unit(seed * 2u + 2u)) / static_cast<float>(n);
    const float r = std::sqrt(v), a = glm::two_pi<float>() * u;
    return {r * std::cos(a), r * std::sin(a)};
}

void basis(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
    u = glm::normalize(glm::cross(std::abs(w.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), w));
    v = glm::cross(w, u);
}

}  // namespace

glm::vec3 visibilityAt(const RayScene& rays, const Light& light, const glm::vec3& p, const glm::vec3& n, int samples,
                       std::uint32_t seed) {
    // Leave the surface by a hair along its normal so that it does not shadow itself.
    const float offset = rays.sceneRadius() * 1e-4f;
    const bool area = light.size > 0.0f && samples > 1;
    const int grid = area ? std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples))))) : 1;
    glm::vec3 sum(0.0f);
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            const std::uint32_t s = hash(seed * 7919u + static_cast<std::uint32_t>(i * grid + j));
            const glm::vec2 d = area ? diskSample(i, j, grid, s) : glm::vec2(0.0f);
            glm::vec3 toLight;
            float distance;
            if (light.type == Light::Type::Directional) {
                const glm::vec3 w = -light.direction;
                glm::vec3 u, v;
                basis(w, u, v);
                const float tanRadius = std::tan(glm::radians(light.size * 0.5f));
                toLight = glm::normalize(w + (u * d.x + v * d.y) * tanRadius);
                distance = std::numeric_limits<float>::infinity();
            } else {
                // A disk of diameter `size` facing the receiver (a sphere's silhouette).
                const glm::vec3 w = glm::normalize(p - light.position);
                glm::vec3 u, v;
                basis(w, u, v);
                const glm::vec3 q = light.position + (u * d.x + v * d.y) * (light.size * 0.5f);
                toLight = q - p;
                distance = glm::length(toLight);
                toLight /= distance;
            }
            const glm::vec3 side = glm::dot(n, toLight) >= 0.0f ? n : -n;
            sum += rays.transmittance(p + side * offset, toLight, 0.0f, distance - offset);
        }
    return sum / static_cast<float>(grid * grid);
}

std::vector<glm::vec3> traceVisibility(const RayScene& rays, const Light& light, const SurfacePoints& pts, int samples,
                                       const Progress& progress) {
    std::vector<glm::vec3> out(static_cast<std::size_t>(pts.width) * pts.height, glm::vec3(0.0f));
    std::atomic<int> nextRow{0}, rowsDone{0};
    auto worker = [&](bool reporter) {
        for (int y = nextRow++; y < pts.height; y = nextRow++) {
            for (int x = 0; x < pts.width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * pts.width + x;
                if (!pts.covered[i]) continue;
                out[i] = visibilityAt(rays, light, pts.position[i], pts.normal[i], samples, static_cast<std::uint32_t>(i));
            }
            const int done = ++rowsDone;
            if (reporter && progress) progress(static_cast<double>(done) / pts.height);
        }
    };
    const unsigned n = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < n; ++t) threads.emplace_back(worker, false);
    worker(true);
    for (auto& t : threads) t.join();
    if (progress) progress(1.0);
    return out;
}

Progress consoleProgress(const std::string& label) {
    const bool tty = isatty(fileno(stderr));
    auto lastDecile = std::make_shared<int>(-1);
    auto lastFraction = std::make_shared<double>(-1.0);
    return [=](double f) {
        if (tty) {
            if (f - *lastFraction < 0.01 && f < 1.0) return;
            *lastFraction = f;
            const int width = 30, filled = static_cast<int>(f * width);
            std::fprintf(stderr, "\r%s [%s%s] %3d%%", label.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                         std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), static_cast<int>(f * 100));
            if (f >= 1.0) std::fprintf(stderr, "\n");
            return;
        }
        const int decile = static_cast<int>(f * 10);
        if (decile == *lastDecile) return;
        *lastDecile = decile;
        std::fprintf(stderr, "%s: %d%%\n", label.c_str(), decile * 10);
    };
}

}  // namespace penumbra::reference
