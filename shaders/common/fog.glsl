// Distance fog towards the background before the far plane (Nápravník 2020, "Mlha"): the colour
// of a surface d from the camera becomes mix(colour, background, smoothstep(start, end, d)).
// Applied by the resolve pass to the float target, or by the lighting shader itself where the
// frame is shaded straight into 8-bit sRGB (FOG_IN_SHADING; render/SrgbTarget.h).
uniform vec3 uBackground;
uniform vec2 uFog;  // start, end distances from the camera
// The camera's perspective (glm::perspective) inverted for one pixel: window depth d lies at view
// depth uViewDepth.x / (d + uViewDepth.y), and the pixel's ray leaves at (ndc.xy * uRaySlope, -1)
// in view space. Measured on llvmpipe (default scene, 1280x720): inverting the whole projection
// matrix per pixel cost 2.1 ms of a 7 ms resolve.
uniform vec2 uViewDepth;
uniform vec2 uRaySlope;

float fogAmount(float distance) { return smoothstep(uFog.x, uFog.y, distance); }

// How far from the camera the surface at window depth `depth` lies, seen through the pixel at
// `uv` (0..1 over the frame).
float cameraDistance(float depth, vec2 uv) {
    vec2 ray = (uv * 2.0 - 1.0) * uRaySlope;
    return uViewDepth.x / (depth + uViewDepth.y) * sqrt(1.0 + dot(ray, ray));
}
