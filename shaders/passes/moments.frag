#version 450 core
// Depth map -> moments of (warped) linear depth, one texel each (blurred afterwards).
//   0 VSM (Donnelly & Lauritzen 2006): (x, x^2), x = linear depth remapped to [-1, 1]
//   1 ESM (Annen et al. 2008): exp(c x)
//   2 EVSM2: (e^{c+ x}, e^{2 c+ x});  3 EVSM4: + (-e^{-c- x}, e^{-2 c- x})
//   4 MSM (Peters & Klein 2015): (t, t^2, t^3, t^4), t = linear depth in [0, 1]
in vec2 vUv;
layout(binding = 0) uniform sampler2D uDepth;
uniform int uWarp;
uniform int uPerspective;
uniform float uNear, uFar;
uniform vec2 uExponents;  // c+, c-
layout(location = 0) out vec4 outMoments;

void main() {
    float z = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
    float t = z;
    if (uPerspective != 0) {
        float d = uNear * uFar / (uFar - z * (uFar - uNear));
        t = (d - uNear) / (uFar - uNear);
    }
    float x = 2.0 * t - 1.0;
    if (uWarp == 0) outMoments = vec4(x, x * x, 0.0, 0.0);
    else if (uWarp == 1) outMoments = vec4(exp(uExponents.x * x), 0.0, 0.0, 0.0);
    else if (uWarp == 2 || uWarp == 3) {
        float p = exp(uExponents.x * x), n = -exp(-uExponents.y * x);
        outMoments = vec4(p, p * p, n, n * n);
    } else outMoments = vec4(t, t * t, t * t * t, t * t * t * t);
}
