#version 450 core
// Forward Blinn-Phong in linear space (Blinn 1977; Mátl 2013 §5.2):
//   ambient*diffuse + sum_lights (diffuse*max(N.L,0) + specular) * colour*intensity * visibility
// where visibility (rgb, coloured) comes from the active shadow technique's lookup.
#include "../common/color.glsl"
#include "../common/material.glsl"
#include "../common/lights.glsl"
#include "shadow_lookup.glsl"
#ifndef SCENE_LIGHT_COUNT
#error "the lighting program is built for a light layout (render/LightingProgram.h)"
#endif

in VertexOut {
    vec3 worldPos;
    vec3 normal;
    vec2 uv;
} vIn;

layout(binding = kUnitProjector) uniform sampler2D uProjectorImage[kMaxProjectors];
uniform vec3 uCameraPos;
uniform vec3 uAmbient;
uniform int uTranslucentPass;  // 1: dual-source output of transmittance for blending
#ifdef DEBUG_OUTPUT  // a debug channel's build (Renderer::withOutputDefines); shaded builds hold none of it
uniform int uOutputMode;       // 0 shaded, 1 visibility of uDebugLight, 2 world position, 3 normal,
                               // 4 unshadowed light from uDebugLight, 5 ambient term
uniform int uDebugLight;
uniform int uShowBehind;  // 1: show the nearest surface behind uBehindDepth's (Renderer::showBehind)
layout(binding = kUnitBehindDepth) uniform sampler2D uBehindDepth;
#endif

// Translucent output, chosen by the renderer's transparency mode (Mátl 2013 ch. 3):
//   default: dual-source blending dst * transmit + src (painter's order)
//   TRANSLUCENT_WEIGHTED: weighted blended OIT (McGuire & Bavoil 2013), two targets
//   TRANSLUCENT_PEEL: depth peeling (Everitt 2001), one layer per pass, two targets
//   TRANSLUCENT_STOCHASTIC_DEPTH / _ACCUM: stochastic transparency (Enderton et al. 2010)
//   TRANSLUCENT_DUAL_PEEL: dual depth peeling (Bavoil & Myers 2008): per pass the nearest and the
//     farthest remaining layer; (-z, z) MAX-blended finds them for the next pass
#if defined(TRANSLUCENT_DUAL_PEEL)
vec4 outColor, outTransmit;  // routed to the front or back layer at the end of main
layout(location = 0) out vec4 outDualDepth;
layout(location = 1) out vec4 outFrontColour;
layout(location = 2) out vec4 outFrontTransmit;
layout(location = 3) out vec4 outBackColour;
layout(location = 4) out vec4 outBackTransmit;
layout(binding = kUnitDualDepth) uniform sampler2D uDualDepth;  // previous pass: (-nearest, farthest)
#elif defined(TRANSLUCENT_WEIGHTED) || defined(TRANSLUCENT_PEEL) || defined(TRANSLUCENT_STOCHASTIC_ACCUM) || defined(TRANSLUCENT_STOCHASTIC_DEPTH)
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outTransmit;
#else
layout(location = 0, index = 0) out vec4 outColor;
layout(location = 0, index = 1) out vec4 outTransmit;
#endif
#ifdef TRANSLUCENT_PEEL
layout(binding = kUnitPeelDepth) uniform sampler2D uPeelDepth;    // the previous layer's depth (0 before the first)
#endif
#if defined(TRANSLUCENT_PEEL) || defined(TRANSLUCENT_STOCHASTIC_DEPTH) || defined(TRANSLUCENT_STOCHASTIC_ACCUM) || defined(TRANSLUCENT_DUAL_PEEL) || (defined(FOG_IN_SHADING) && defined(MATERIAL_TRANSLUCENT))
layout(binding = kUnitOpaqueDepth) uniform sampler2D uOpaqueDepth;  // the opaque surfaces' depth
#endif
#ifdef FOG_IN_SHADING
#include "../common/fog.glsl"
#endif
#if defined(TRANSLUCENT_STOCHASTIC_DEPTH) || defined(TRANSLUCENT_STOCHASTIC_ACCUM)
#include "../common/random.glsl"
#define STOCHASTIC_SAMPLES 4
layout(binding = kUnitStochasticDepth) uniform sampler2DMS uStochasticDepth;  // nearest stochastic surface per sample
#endif

// Constant indices only: llvmpipe (LLVM 15) crashes on dynamically indexed sampler arrays
// once a cube sampler is in the same shader (see shaders/common/shadow_samplers.glsl).
// Implicit derivatives, so the call must stay in uniform control flow (incidentRadiance). llvmpipe
// samples with explicit ones (textureGrad) on a far slower path: measured on the default scene,
// whose projector covers part of the frame but is sampled for every pixel, textureGrad cost the
// opaque pass 5-7 ms of 38 (none) and 56 (hard); 40 of 921,600 pixels moved by 1/255 (the level of
// detail llvmpipe takes per 2 x 2 quad rather than per pixel).
vec3 projectorTexel(int slot, vec2 uv) {
    return slot == 0 ? texture(uProjectorImage[0], uv).rgb : texture(uProjectorImage[1], uv).rgb;
}

// Light arriving at P from light i before shadowing: radiance shaped by spot cone or projector
// picture (Nápravník 2020, "Projekce": the picture rides on the light, the shadow map cuts it).
vec3 incidentRadiance(int i, vec3 P, out vec3 L) {
    LightData light = uLights[i];
    int type = lightType(i);
    if (type == kLightDirectional) {
        L = -light.directionFar.xyz;
        return light.colorType.rgb;
    }
    vec3 toLight = light.positionNear.xyz - P;
    L = normalize(toLight);
    if (type == kLightPoint) return light.colorType.rgb;
    if (type == kLightSpot) {
        float cosAngle = dot(-L, light.directionFar.xyz);
        return light.colorType.rgb * smoothstep(light.cone.x, light.cone.y, cosAngle);
    }
    // Projector: look the picture up where the projector's frustum maps P. Images are stored
    // top row first: flip v so the picture lands upright. The picture is sampled before the
    // divergent test below, where implicit derivatives would be undefined.
    vec4 s = light.shadowMatrix * vec4(P, 1.0);
    vec2 uv = vec2(s.x / s.w, 1.0 - s.y / s.w);
    int slot = lightProjectorSlot(i);
    vec3 picture = slot < 0 ? vec3(0.0) : projectorTexel(slot, uv);
    if (s.w <= 0.0 || slot < 0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec3(0.0);
    return light.colorType.rgb * picture;
}

// The light sums of one surface point, built light by light.
struct LightSum {
    vec3 diffuse, specular;
    vec3 debugVisibility, debugContribution;  // of uDebugLight (DEBUG_OUTPUT builds)
};

void addLight(int i, vec3 P, vec3 N, vec3 V, vec3 albedo, inout LightSum sum) {
#ifdef SKIPPED_LIGHTS
    // A light that reaches none of the pixels this build shades (a projector or spot light whose
    // frustum misses them: Renderer's light reach) would add exactly 0 there; left out, with its
    // picture and shadow lookup, which llvmpipe would otherwise run for every pixel.
    if (((SKIPPED_LIGHTS >> uint(i)) & 1u) != 0u) return;
#endif
    vec3 L;
    vec3 radiance = incidentRadiance(i, P, L);
    float NdotL = dot(N, L);
#ifdef UNSHADOWED_LIGHTS
    // No other caster's shadow falls on the pixels this build shades (Renderer's shadow reach): the
    // map holds the receiver itself or what lies behind it, and the lookup would answer 1.
    vec3 visibility = vec3(1.0);
    if (((UNSHADOWED_LIGHTS >> uint(i)) & 1u) == 0u) visibility = shadowVisibility(i, P, N, NdotL);
#else
    vec3 visibility = shadowVisibility(i, P, N, NdotL);
#endif
#ifdef DEBUG_OUTPUT
    if (i == uDebugLight) sum.debugVisibility = visibility;
#endif
    if (NdotL <= 0.0) return;
#ifdef MATERIAL_NO_SPECULAR
    // uSpecular is (0, 0, 0): the highlight would add exactly 0 (LightingPrograms).
    vec3 highlight = vec3(0.0);
#else
    vec3 H = normalize(L + V);
    vec3 highlight = uSpecular * pow(max(dot(N, H), 0.0), uShininess);  // Blinn-Phong
#endif
#ifdef DEBUG_OUTPUT
    vec3 unshadowed = (albedo * NdotL + highlight) * radiance;
    if (i == uDebugLight) sum.debugContribution = unshadowed;
#endif
    sum.diffuse += albedo * NdotL * radiance * visibility;
#ifndef MATERIAL_NO_SPECULAR
    sum.specular += highlight * radiance * visibility;
#endif
}

void main() {
#ifdef DEBUG_OUTPUT
    // Both frames draw every surface through the same invariant transform (lighting.vert), so the
    // nearest surface's own fragments land on its depth to the bit and `<=` peels exactly it.
    if (uShowBehind != 0 && gl_FragCoord.z <= texelFetch(uBehindDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
#endif
#ifdef TRANSLUCENT_PEEL
    // Keep only the nearest surface behind the previous layer (strictly), in front of the opaque.
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (gl_FragCoord.z <= texelFetch(uPeelDepth, p, 0).r || gl_FragCoord.z >= texelFetch(uOpaqueDepth, p, 0).r) discard;
#endif
#if defined(TRANSLUCENT_STOCHASTIC_DEPTH) || defined(TRANSLUCENT_STOCHASTIC_ACCUM)
    if (gl_FragCoord.z >= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
#endif
#ifdef TRANSLUCENT_DUAL_PEEL
    float z = gl_FragCoord.z;
    vec2 previous = texelFetch(uDualDepth, ivec2(gl_FragCoord.xy), 0).rg;
    float nearest = -previous.x, farthest = previous.y;
    if (z >= texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r || z < nearest || z > farthest) discard;  // peeled
    outFrontColour = vec4(0.0);
    outBackColour = vec4(0.0);
    outFrontTransmit = vec4(1.0);
    outBackTransmit = vec4(1.0);
    if (z > nearest && z < farthest) {  // still inside: bound the next pass's layers
        outDualDepth = vec4(-z, z, 0.0, 0.0);
        return;
    }
    outDualDepth = vec4(-1.0);  // neutral under MAX blending
#endif
    vec4 texel = materialTexel(vIn.uv);
    float coverage = materialCoverage(texel);
    vec3 albedo = uDiffuse * texel.rgb;
    receiverTransmittance = vec3(1.0) - materialStopped(coverage);
    vec3 P = vIn.worldPos;
    vec3 N = normalize(vIn.normal);
    if (!gl_FrontFacing) N = -N;  // two-sided surfaces (planes, panes) light on both faces
    vec3 V = normalize(uCameraPos - P);

    LightSum sum = LightSum(vec3(0.0), vec3(0.0), vec3(1.0), vec3(0.0));
    // Unrolled with literal indices, so each light's type and shadow slot fold to constants and
    // its lookups address one sampler each. Measured on llvmpipe (default scene, 1280x720, hard):
    // a run-time loop over the light block, whose slot switches sample every slot's sampler,
    // cost the opaque pass 100 ms against 40 ms unrolled (issue 15).
    // SHADE_EACH_LIGHT is SHADE_LIGHT(0) SHADE_LIGHT(1) ... up to the scene's light count.
#define SHADE_LIGHT(i) addLight(i, P, N, V, albedo, sum);
    SHADE_EACH_LIGHT
#undef SHADE_LIGHT
    vec3 diffuse = sum.diffuse, specular = sum.specular;
    vec3 ambient = uAmbient * albedo;
#ifdef DEBUG_OUTPUT
    if (uOutputMode == 1) { outColor = vec4(sum.debugVisibility, 1.0); outTransmit = vec4(0.0); return; }
    if (uOutputMode == 2) { outColor = vec4(P, 1.0); outTransmit = vec4(0.0); return; }
    if (uOutputMode == 3) { outColor = vec4(N, 1.0); outTransmit = vec4(0.0); return; }
    if (uOutputMode == 4) { outColor = vec4(sum.debugContribution, 1.0); outTransmit = vec4(0.0); return; }
    if (uOutputMode == 5) { outColor = vec4(ambient, 1.0); outTransmit = vec4(0.0); return; }
#endif
    // Opaque builds are never drawn in the translucent pass: what follows the block is dead code to
    // them (llvmpipe would run it for every fragment, masked, behind a uniform test).
#ifdef MATERIAL_TRANSLUCENT
    if (uTranslucentPass == 0)
#endif
    {
        outColor = vec4(ambient + diffuse + specular, 1.0);
#ifdef FOG_IN_SHADING
        outColor.rgb = mix(outColor.rgb, uBackground, fogAmount(length(P - uCameraPos)));
#endif
#ifdef ENCODE_SRGB_IN_SHADER
        // The opaque pass writes the frame's sRGB bytes itself (Renderer::render): cheaper than
        // llvmpipe's sRGB store, and within 1/255 of it. Translucent surfaces, below, blend and
        // stay linear: GL encodes them.
        outColor.rgb = linearToSrgbFast(outColor.rgb);
#endif
        outTransmit = vec4(0.0);
        return;
    }
    // Translucent surface over what is behind it (dual-source blending: dst*transmit + src):
    // the covered, non-transmitting share reflects; light passes with 1 - rho per channel.
    vec3 stopped = materialStopped(coverage);
    outColor = vec4((ambient + diffuse) * stopped + specular * coverage, 1.0);
    outTransmit = vec4(vec3(1.0) - stopped, 1.0);
#if defined(FOG_IN_SHADING) && defined(MATERIAL_TRANSLUCENT)  // only there: llvmpipe runs this code for every opaque fragment too
    // The float target fogs the composited pixel by the opaque surface behind it (resolve.frag):
    // F = mix(dst T + S, bg, f). dst is fogged by that same f already, so src S' = S (1 - f) +
    // bg f (1 - T) gives dst' T + S' = F, for each layer of a back-to-front stack in turn.
    float behind = texelFetch(uOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
    float f = behind < 1.0 ? fogAmount(cameraDistance(behind, gl_FragCoord.xy / vec2(textureSize(uOpaqueDepth, 0)))) : 0.0;
    outColor.rgb = outColor.rgb * (1.0 - f) + uBackground * f * stopped;  // 1 - T = stopped
#endif
#ifdef TRANSLUCENT_STOCHASTIC_DEPTH
    // Pass 1: each sample of the pixel is covered with probability = opacity (the mean of ρ),
    // so the multisampled depth holds, per sample, the nearest surface that happened to cover it.
    float opacity = dot(stopped, vec3(1.0 / 3.0));
    int mask = 0;
    for (int i = 0; i < STOCHASTIC_SAMPLES; ++i)
        if (fragmentRandom(uint(i)) < opacity) mask |= 1 << i;
    if (mask == 0) discard;
    gl_SampleMask[0] = mask;
#endif
#ifdef TRANSLUCENT_STOCHASTIC_ACCUM
    // Pass 2: this surface's visibility = share of samples whose nearest stochastic surface is
    // not in front of it; colour and opacity are summed weighted by it. The resolve applies the
    // paper's alpha correction: sum(C a vis) / sum(a vis) * (1 - prod(1 - a)), the last factor
    // exact (and coloured) from the multiplied transmittance.
    float a = max(dot(stopped, vec3(1.0 / 3.0)), 1e-3);
    float visible = 0.0;
    for (int i = 0; i < STOCHASTIC_SAMPLES; ++i)
        visible += texelFetch(uStochasticDepth, ivec2(gl_FragCoord.xy), i).r >= gl_FragCoord.z - 1e-6 ? 1.0 : 0.0;
    visible /= float(STOCHASTIC_SAMPLES);
    outColor = vec4(outColor.rgb * visible, a * visible);
#endif
#ifdef TRANSLUCENT_DUAL_PEEL
    // MAX blending keeps this layer's colour over the zeros of the others, MIN its transmittance.
    if (z == nearest) {
        outFrontColour = outColor;
        outFrontTransmit = outTransmit;
    } else {
        outBackColour = outColor;
        outBackTransmit = outTransmit;
    }
#endif
#ifdef TRANSLUCENT_WEIGHTED
    // Eq. 7 of McGuire & Bavoil: depth-weighted sums of premultiplied colour and of coverage;
    // the transmittance itself is multiplied exactly (per channel) by blending into outTransmit.
    float a = max(dot(stopped, vec3(1.0 / 3.0)), 1e-3);
    float w = clamp(a * max(1e-2, 3e3 * pow(1.0 - gl_FragCoord.z, 3.0)), 1e-2, 3e3);
    outColor = vec4(outColor.rgb * w, a * w);
#endif
}
