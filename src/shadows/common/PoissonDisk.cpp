#include "shadows/common/PoissonDisk.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>

namespace penumbra::shadows {

namespace {

// Bridson 2007 in the square [-1,1]^2 restricted to the unit disk.
std::vector<glm::vec2> bridson(float r, std::mt19937& rng) {
    const int k = 30;
    const float cell = r / std::sqrt(2.0f);
    const int n = static_cast<int>(std::ceil(2.0f / cell));
    std::vector<int> grid(static_cast<std::size_t>(n * n), -1);
    std::vector<glm::vec2> points, active;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto cellOf = [&](glm::vec2 p) {
        return glm::ivec2(std::clamp(static_cast<int>((p.x + 1) / cell), 0, n - 1),
                          std::clamp(static_cast<int>((p.y + 1) / cell), 0, n - 1));
    };
    auto fits = [&](glm::vec2 p) {
        if (glm::length(p) > 1.0f) return false;
        const glm::ivec2 c = cellOf(p);
        for (int y = std::max(0, c.y - 2); y <= std::min(n - 1, c.y + 2); ++y)
            for (int x = std::max(0, c.x - 2); x <= std::min(n - 1, c.x + 2); ++x) {
                const int i = grid[static_cast<std::size_t>(y * n + x)];
                if (i >= 0 && glm::length(points[static_cast<std::size_t>(i)] - p) < r) return false;
            }
        return true;
    };
    auto add = [&](glm::vec2 p) {
        const glm::ivec2 c = cellOf(p);
        grid[static_cast<std::size_t>(c.y * n + c.x)] = static_cast<int>(points.size());
        points.push_back(p);
        active.push_back(p);
    };
    add({0.0f, 0.0f});
    while (!active.empty()) {
        const std::size_t pick = static_cast<std::size_t>(unit(rng) * static_cast<float>(active.size())) % active.size();
        const glm::vec2 base = active[pick];
        bool found = false;
        for (int t = 0; t < k && !found; ++t) {
            const float a = unit(rng) * glm::two_pi<float>(), d = r * (1.0f + unit(rng));
            const glm::vec2 p = base + d * glm::vec2(std::cos(a), std::sin(a));
            if (fits(p)) {
                add(p);
                found = true;
            }
        }
        if (!found) active.erase(active.begin() + static_cast<long>(pick));
    }
    return points;
}

}  // namespace

std::vector<glm::vec2> poissonDisk(int count, std::uint32_t seed) {
    // The densest packing of `count` disks in the unit disk has spacing ~ sqrt(pi / count)
    // (hexagonal: 0.91 coverage); start there and shrink until enough points fit.
    float r = 1.7f / std::sqrt(static_cast<float>(count));
    for (int attempt = 0; attempt < 200; ++attempt, r *= 0.97f) {
        std::mt19937 rng(seed);
        std::vector<glm::vec2> pts = bridson(r, rng);
        if (static_cast<int>(pts.size()) >= count) {
            pts.resize(static_cast<std::size_t>(count));
            return pts;
        }
    }
    return std::vector<glm::vec2>(static_cast<std::size_t>(count), glm::vec2(0.0f));
}

void PoissonDisk::upload(const gl::Program& program) const {
    glProgramUniform2fv(program.id(), program.location("uPoisson[0]"), static_cast<GLsizei>(points_.size()), &points_[0].x);
}

}  // namespace penumbra::shadows
