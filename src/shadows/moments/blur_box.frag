#version 450 core
// The box pre-filter (`blur_kernel=auto` at blur_radius 1-2 and half resolution; `box` at any
// radius) over a raw map of every moment, which MSAA's conversion makes (otherwise the casters
// write depth alone and blur_box_first_order.frag takes its moments, the same box):
// a 2 x 2 box of moment texels in one bilinear fetch, at the corner texel p shares with
// p + (1, 1). The box's centre lies half a texel past p's, so the casters' moments are drawn half a
// texel the other way (MomentShadowMap::rasterMoments): each output texel is then the mean of the
// four samples around its own centre. Its variance, 1/4 texel^2 per axis, is that of a Gaussian of
// sigma 1/2 moment texel (blur_radius 2 at half resolution), which blur_bilinear.frag's three taps
// a side sample at 0.21. Against those four fetches, on llvmpipe (vsm, default scene, every map
// redrawn, alternated rounds): frame 0.887x (0.814-0.900) at stop 68, 0.87x at stop 69. Against the
// reference (compare, default scene, 1280 x 720) it is as near: wrong pixels vsm 0.591 % against
// 0.571, msm 0.851 / 0.840, esm 0.674 / 0.673; RMSE vsm 0.0255 / 0.0259; its shadow edges show
// fewer stairs (docs/measurements.md, stop 69).
layout(binding = 0) uniform sampler2D uSource;  // linear filtering, clamped to its edges
layout(location = 0) out vec4 outValue;

void main() { outValue = texture(uSource, (gl_FragCoord.xy + 0.5) / vec2(textureSize(uSource, 0))); }
