// The CSSM reconstruction filters compared by Mátl 2013 (§5.3, §6.1), numbered once for C++
// (ColoredStochasticShadowMap) and GLSL (lookup.glsl).
#ifndef PENUMBRA_SHADOWS_CSSM_FILTER_H
#define PENUMBRA_SHADOWS_CSSM_FILTER_H
#include "../../gpu/ShaderContract.h"
GPU_NAMESPACE_BEGIN
GPU_CONST kCssmPcf9 = 0;       // 3 x 3 grid
GPU_CONST kCssmPoisson16 = 1;  // Poisson disk, 16 taps, rotated per pixel
GPU_CONST kCssmPoisson20 = 2;  // Poisson disk, 20 taps, rotated per pixel
GPU_CONST kCssmRandom30 = 3;   // 30 uniform random taps per pixel
GPU_CONST kCssmCross13 = 4;    // the thesis's 13-tap cross-plus-square with derivative jitter
GPU_NAMESPACE_END
#endif
