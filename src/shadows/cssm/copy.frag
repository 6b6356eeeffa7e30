#version 450 core
// CSSM2 step 2 (Mátl 2013 §5.4.2): copy the opaque casters' depth into every colour channel.
// Depth is stored linear in [0, 1] (half floats would waste their precision on perspective
// depth); texels with no opaque caster get 1, i.e. white, so translucent surfaces with nothing
// opaque behind them do not shadow wrongly (the thesis's white-clear fix).
#include "shaders/common/depth.glsl"
layout(binding = 0) uniform sampler2D uDepth;
uniform int uPerspective;
uniform float uNear, uFar;
layout(location = 0) out vec4 outDepth;

float linearDepth(float z) {
    if (uPerspective == 0 || z >= 1.0) return z;  // 1 stays exactly 1: nothing opaque there
    return perspectiveLinearDepth(z, uNear, uFar);
}

void main() { outDepth = vec4(vec3(linearDepth(texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r)), 1.0); }
