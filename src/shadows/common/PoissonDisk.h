#pragma once
// The Poisson-disk points every filtered lookup shares (uPoisson[32] of
// src/shadows/common/glsl/kernels.glsl), generated once with Bridson's algorithm.
#include "gl/Program.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::shadows {

// `count` points in the unit disk at least `minDistance` apart, by Bridson's fast Poisson-disk
// sampling (SIGGRAPH 2007 sketch); the radius shrinks until `count` points fit. Deterministic.
std::vector<glm::vec2> poissonDisk(int count, std::uint32_t seed = 1);

class PoissonDisk {
public:
    static constexpr int kPoints = 32;  // uPoisson[32]
    PoissonDisk() : points_(poissonDisk(kPoints)) {}
    // Sets uPoisson on a program that includes kernels.glsl.
    void upload(const gl::Program& program) const;
    const std::vector<glm::vec2>& points() const { return points_; }

private:
    std::vector<glm::vec2> points_;
};

}  // namespace penumbra::shadows
