// What a moment map stores, numbered once for C++ (MomentShadowMap::Warp) and GLSL
// (moments.frag, lookup.glsl).
#ifndef PENUMBRA_SHADOWS_MOMENT_WARP_H
#define PENUMBRA_SHADOWS_MOMENT_WARP_H
#include "../../gpu/ShaderContract.h"
GPU_NAMESPACE_BEGIN
GPU_CONST kWarpVariance = 0;               // VSM (Donnelly & Lauritzen 2006): (x, x^2)
GPU_CONST kWarpExponential = 1;            // ESM (Annen et al. 2008): exp(c x)
GPU_CONST kWarpExponentialVariance2 = 2;   // EVSM, positive warp: (e^{c+ x}, e^{2 c+ x})
GPU_CONST kWarpExponentialVariance4 = 3;   // EVSM, both warps: + (-e^{-c- x}, e^{-2 c- x})
GPU_CONST kWarpMoments4 = 4;               // MSM (Peters & Klein 2015): (t, t^2, t^3, t^4)

// MSM's optimized moment quantization (Peters & Klein 2015, section 4.3): an affine map of
// b = (t, t^2, t^3, t^4), t in [0, 1], into the unit cube that spreads the moments over 16 bits:
// stored = kMomentsQuantize * b + kMomentsQuantizeOffset, an RGBA16 texel (`quantized`, msm's
// default). Filtering commutes with it (its weights sum to 1); the lookup maps back with
// kMomentsDequantize (the inverse). Column-major in both languages, as printed in the paper.
GPU_CONSTANT(mat4) kMomentsQuantize = mat4(-2.07224649f, 13.7948857237f, 0.105877704f, 9.7924062118f,
                                           32.23703778f, -59.4683975703f, -1.9077466311f, -33.7652110555f,
                                           -68.571074599f, 82.0359750338f, 9.3496555107f, 47.9456096605f,
                                           39.3703274134f, -35.364903257f, -6.6543490743f, -23.9728048165f);
GPU_CONSTANT(vec4) kMomentsQuantizeOffset = vec4(0.035955884801f, 0.0f, 0.0f, 0.0f);
GPU_CONSTANT(mat4) kMomentsDequantize = mat4(0.2227744146f, 0.1549679261f, 0.1451988946f, 0.163127443f,
                                             0.0771972861f, 0.1394629426f, 0.2120202157f, 0.2591432266f,
                                             0.7926986636f, 0.7963415838f, 0.7258694464f, 0.6539092497f,
                                             0.0319417555f, -0.1722823173f, -0.2758014811f, -0.3376131734f);
GPU_NAMESPACE_END
#endif
