#version 450 core
// `blur_kernel=box`: a 2 x 2 box of moment texels in one bilinear fetch, at the corner texel p
// shares with p + (1, 1). The box's centre lies half a texel past p's, so the casters' moments
// are drawn half a texel the other way (MomentShadowMap::rasterMoments): each output texel is then
// the mean of the four samples around its own centre. Its variance, 1/4 texel^2 per axis, is that
// of the default Gaussian (blur_radius 2 at half resolution: sigma 1/2 moment texel). Against
// blur_bilinear.frag's four fetches, on llvmpipe (vsm, default scene, every map redrawn, six
// alternated rounds): frame 0.887x (0.814-0.900), shadow pass 14-17 ms against 18-21.5. Its wrong
// pixels against the reference are a few per cent more (docs/measurements.md, stop 68).
layout(binding = 0) uniform sampler2D uSource;  // linear filtering, clamped to its edges
layout(location = 0) out vec4 outValue;

void main() { outValue = texture(uSource, (gl_FragCoord.xy + 0.5) / vec2(textureSize(uSource, 0))); }
