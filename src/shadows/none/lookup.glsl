// No shadows: every light reaches every surface.
vec3 shadowVisibility(int light, vec3 worldPos, vec3 worldNormal, float NdotL) { return vec3(1.0); }
