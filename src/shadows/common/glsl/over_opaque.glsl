// Translucent casters drawn over a light's opaque depth (the tint pass, CSSM's colour map): the
// depth they are tested with is pushed back as glPolygonOffset pushed the opaque casters', and a
// few units more (DepthAndTintMaps::translucentTestOffset), so that a translucent face lying on an
// opaque surface fails the test. What they store is gl_FragCoord.z, the face's own depth: a polygon
// offset would have moved that too (and interpolating clip z / w instead moved a receiver's rim
// texel by rounding, TranslucentReceiver.GetsTheGreenPaneInFrontOfItExactly).
uniform vec2 uTestOffset;  // (factor, units)
// The tested depth only grows: a GPU may still reject fragments early by their own depth.
layout(depth_greater) out float gl_FragDepth;

void testBehindOpaqueOffset() {
    float z = gl_FragCoord.z;
    // GL 4.5 §14.6.5: o = m factor + r units, m the depth slope (the larger of |dz/dx|, |dz/dy|,
    // or their Euclidean norm: |dz/dx| + |dz/dy| bounds both), r the 32-bit float depth's step
    // at z, 2^(e - 23).
    float m = abs(dFdx(z)) + abs(dFdy(z));
    float r = uintBitsToFloat((floatBitsToUint(max(z, 1e-30)) & 0x7f800000u) - (23u << 23));  // z's exponent, 23 less
    // Kept below the far plane's 1 (the largest float below it): a steep face (m large) over no
    // opaque caster still draws. Never below z (depth_greater).
    gl_FragDepth = max(z, min(z + uTestOffset.x * m + uTestOffset.y * r, 0.99999994));
}
