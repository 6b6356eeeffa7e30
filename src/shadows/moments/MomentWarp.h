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
GPU_NAMESPACE_END
#endif
