// The CSSM reconstruction filters compared by Mátl 2013 (§5.3, §6.1) plus a box matched to the
// stratified ξ, and the ways to draw ξ, numbered once for C++ (ColoredStochasticShadowMap) and
// GLSL (caster.frag, lookup.glsl).
#ifndef PENUMBRA_SHADOWS_CSSM_FILTER_H
#define PENUMBRA_SHADOWS_CSSM_FILTER_H
#include "../../gpu/ShaderContract.h"
GPU_NAMESPACE_BEGIN
GPU_CONST kCssmPcf9 = 0;       // 3 x 3 grid
GPU_CONST kCssmPoisson16 = 1;  // Poisson disk, 16 taps, rotated per pixel
GPU_CONST kCssmPoisson20 = 2;  // Poisson disk, 20 taps, rotated per pixel
GPU_CONST kCssmRandom30 = 3;   // 30 uniform random taps per pixel
GPU_CONST kCssmCross13 = 4;    // the thesis's 13-tap cross-plus-square with derivative jitter
GPU_CONST kCssmBox16 = 5;      // the 4 x 4 texels around the receiver: one whole tile of a 4 x 4 stratified ξ
GPU_CONST kCssmBox64 = 6;      // the 8 x 8 texels around the receiver: one whole tile of an 8 x 8 stratified ξ

// How the casters draw ξ (uXi of caster.frag).
GPU_CONST kXiWhite = 0;       // an independent random number per fragment (the thesis, the paper)
GPU_CONST kXiStratified = 1;  // one threshold per stratum in every tile, randomly permuted per tile and layer
GPU_NAMESPACE_END
#endif
