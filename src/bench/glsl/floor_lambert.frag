#version 450 core
// Bare camera pass: Lambert from one light times one hardware-compared shadow-map lookup, into
// RGBA8; with SHADOWED 0, Lambert alone (the floor of a shadowless frame).
in vec3 vWorld;
in vec3 vNormal;

uniform sampler2DShadow uShadowMap;
uniform mat4 uShadowMatrix;  // world -> [0,1]^3 of the light's map
uniform vec3 uToLight;       // unit vector towards the (directional) light
uniform float uBias;         // depth bias in [0,1] depth units

out vec4 fragColor;

void main() {
    vec3 n = normalize(vNormal);
    vec4 s = uShadowMatrix * vec4(vWorld, 1.0);
#if SHADOWED
    float lit = texture(uShadowMap, vec3(s.xy / s.w, s.z / s.w - uBias));
#else
    float lit = 1.0;
#endif
    float lambert = abs(dot(n, uToLight));  // planes are seen from both sides
    fragColor = vec4(vec3(0.08 + lambert * lit), 1.0);
}
