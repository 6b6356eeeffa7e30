// Translucent casters drawn over a light's opaque depth (the tint pass, CSSM's colour map): the
// depth they are tested with is pushed back as glPolygonOffset pushed the opaque casters', and a
// few units more (DepthAndTintMaps::translucentTestOffset), so that a translucent face lying on an
// opaque surface fails the test. What they store is gl_FragCoord.z, the face's own depth: a polygon
// offset would have moved that too (and interpolating clip z / w instead moved a receiver's rim
// texel by rounding, TranslucentReceiver.GetsTheGreenPaneInFrontOfItExactly).
uniform vec2 uTestOffset;  // (factor, units)
// The tested depth only grows: a GPU may still reject fragments early by their own depth.
layout(depth_greater) out float gl_FragDepth;

// GL 4.5 §14.6.5: o = m factor + r units, m the depth slope (the larger of |dz/dx|, |dz/dy|, or
// their Euclidean norm: |dz/dx| + |dz/dy| bounds both), r the 32-bit float depth's step at "the
// maximum z in the primitive", 2^(e - 23). A fragment cannot know its primitive's largest z, so r
// is taken at its largest, 2^-23: z below 1 has e <= -1, and NVIDIA's unit is twice the step
// (measured on an H200, OverOpaqueTest). Where z is small and the opaque triangle reaches deep (a
// floor under a sun), r at the fragment's own z can be many times smaller than the driver's: so
// on the H200 the floor under a glass block took its bottom face's tint a second time (CompareTest;
// this unit is not yet checked there). 10 units of 2^-23 are 1.2e-6 of the light's depth range,
// far below anything a scene models.
const float kLargestDepthStep = 1.0 / 8388608.0;  // 2^-23

void testBehindOpaqueOffset() {
    float z = gl_FragCoord.z;
    float m = abs(dFdx(z)) + abs(dFdy(z));
    // Kept below the far plane's 1 (the largest float below it): a steep face (m large) over no
    // opaque caster still draws. Never below z (depth_greater).
    gl_FragDepth = max(z, min(z + uTestOffset.x * m + uTestOffset.y * kLargestDepthStep, 0.99999994));
}
