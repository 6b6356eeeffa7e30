// The PCF kernels, numbered once for C++ (PercentageCloserFilter::Kernel) and GLSL (lookup.glsl).
#ifndef PENUMBRA_SHADOWS_PCF_KERNEL_H
#define PENUMBRA_SHADOWS_PCF_KERNEL_H
#include "../../gpu/ShaderContract.h"
GPU_NAMESPACE_BEGIN
GPU_CONST kPcfGrid = 0;      // N x N grid (3 x 3 = 9 taps)
GPU_CONST kPcfBilinear = 1;  // hardware 2 x 2 (the depth map samples with GL_LINEAR)
GPU_CONST kPcfGaussian = 2;  // Gaussian-weighted N x N grid
GPU_CONST kPcfPoisson = 3;   // Poisson disk (Bridson 2007)
GPU_CONST kPcfRandom = 4;    // uniform random taps per pixel
GPU_CONST kPcfJitter = 5;    // jittered grid warped onto a disk, 3D texture (GPU Gems 2 ch. 17, OSG SoftShadowMap)
GPU_CONST kPcfDither = 6;    // two offset sets alternating in a checkerboard
GPU_CONST kPcfRotated = 7;   // Poisson disk rotated per pixel
GPU_CONST kPcfAdaptive = 8;  // cheap edge test, the full kernel only in the penumbra
GPU_NAMESPACE_END
#endif
