// Material uniforms shared by every pass that draws scene surfaces.
#include "src/gpu/ShaderContract.h"

layout(binding = kUnitDiffuse) uniform sampler2D uDiffuseTexture;
uniform int uHasTexture;
uniform vec3 uDiffuse;
uniform vec3 uSpecular;
uniform float uShininess;
uniform float uAlpha;          // coverage (McGuire & Enderton 2011)
uniform vec3 uTransmission;    // t_rgb
uniform float uAlphaCutoff;    // > 0: alpha test
uniform int uClosedPart;       // 1: the part bounds a solid of this one material (render/GpuScene.h)

#ifdef MATERIAL_UNTEXTURED  // render/LightingProgram.h: no sample even under a false uniform branch
vec4 materialTexel(vec2 uv) { return vec4(1.0); }
#else
vec4 materialTexel(vec2 uv) { return uHasTexture != 0 ? texture(uDiffuseTexture, uv) : vec4(1.0); }
#endif

// Coverage after the texture's alpha; fragments under the alpha-test cutoff are dropped.
// MATERIAL_NO_ALPHA_TEST: a build for materials without a cutoff (render/LightingProgram.h) has
// no `discard` at all, which lets llvmpipe write depth before shading instead of after it
// (lp_state_fs.c; the uniform's false does not count).
float materialCoverage(vec4 texel) {
#ifndef MATERIAL_NO_ALPHA_TEST
    if (uAlphaCutoff > 0.0 && texel.a < uAlphaCutoff) discard;
#endif
    return uAlphaCutoff > 0.0 ? uAlpha : uAlpha * texel.a;
}

// Fraction of light a surface stops, rho = (1 - t) * alpha (McGuire & Enderton 2011).
vec3 materialStopped(float coverage) { return (vec3(1.0) - uTransmission) * coverage; }

// The transmittance 1 - rho of the surface being shaded, set by the lighting program before it
// shades its lights: a lookup whose light-space product includes the receiver's own layer
// divides it out (CSSM's translucent receivers, cssm/lookup.glsl).
vec3 receiverTransmittance = vec3(1.0);
