#pragma once
// Mirrors shaders/common/bindings.glsl: change both together.
namespace penumbra::render {

inline constexpr int kMaxLights = 8;
inline constexpr int kMaxShadow2D = 4;
inline constexpr int kMaxShadowCube = 2;
inline constexpr int kMaxProjectors = 2;

inline constexpr unsigned kUnitDiffuse = 0;
inline constexpr unsigned kUnitProjector = 1;
inline constexpr unsigned kUnitJitter = 3;
inline constexpr unsigned kUnitShadow2D = 4;
inline constexpr unsigned kUnitTint2D = 8;
inline constexpr unsigned kUnitRaw2D = 12;
inline constexpr unsigned kUnitShadowCube = 16;
inline constexpr unsigned kUnitTintCube = 18;
inline constexpr unsigned kUnitRawCube = 20;
inline constexpr unsigned kUnitLayered = 22;  // a technique's LayeredDepthMap (cascades, LiSPSM tiles)
inline constexpr unsigned kUnitScreenShadow = 23;  // screen-space visibility (shadow volumes, planar)
inline constexpr unsigned kUnitScreenDepth = 24;   // the camera depth pre-pass it belongs to

inline constexpr unsigned kLightBlockBinding = 0;

}  // namespace penumbra::render
