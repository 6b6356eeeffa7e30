#pragma once
// How far a technique's light visibility is from the ray-traced one, and pictures of it.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::reference {

// Accumulates over (pixel, light) pairs where the light reaches the surface unshadowed.
class VisibilityError {
public:
    static constexpr float kWrongThreshold = 0.1f;   // a pixel is "wrong" when any channel is off by more
    static constexpr float kColouredChroma = 0.05f;  // reference max-min channel above this: coloured shadow

    void add(const std::vector<glm::vec3>& technique, const std::vector<glm::vec3>& reference,
             const std::vector<bool>& mask);
    double rmse() const;               // over all channels of all counted pixels
    double wrongShare() const;         // share of counted pixels off by > kWrongThreshold
    double colourError() const;        // mean |difference| (per channel) inside coloured-shadow pixels
    std::size_t pixels() const { return count_; }
    std::size_t colouredPixels() const { return coloured_; }

private:
    double squared_ = 0, colourAbs_ = 0;
    std::size_t count_ = 0, wrong_ = 0, coloured_ = 0;
};

// Per-pixel largest channel difference over lights (0 where no light counts), for heat maps.
void accumulateMaxError(std::vector<float>& maxError, const std::vector<glm::vec3>& technique,
                        const std::vector<glm::vec3>& reference, const std::vector<bool>& mask);

// Heat map, top row first: grey where nothing was compared, black (0) through red, yellow to
// white (>= 1) elsewhere.
std::vector<std::uint8_t> heatMap(const std::vector<float>& maxError, const std::vector<bool>& compared, int width,
                                  int height);

// Linear RGB (GL row order, bottom first) -> sRGB RGBA8 top row first.
std::vector<std::uint8_t> encodeSrgb(const std::vector<glm::vec3>& linear, int width, int height);
// Linear values written as-is (visibility maps: 0.5 -> 128), top row first.
std::vector<std::uint8_t> encodeLinear(const std::vector<glm::vec3>& values, int width, int height);

// Half-size copy of an RGBA8 image (2x2 box filter); width and height become w/2, h/2.
std::vector<std::uint8_t> halve(const std::vector<std::uint8_t>& rgba, int width, int height);

// Several RGBA8 images of one size side by side (with a gap), in rows of `columns`.
std::vector<std::uint8_t> montage(const std::vector<const std::vector<std::uint8_t>*>& images, int width, int height,
                                  int columns, int& outWidth, int& outHeight);

}  // namespace penumbra::reference
