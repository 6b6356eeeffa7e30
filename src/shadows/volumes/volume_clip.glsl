// A shadow volume's vertex, in world space (w = 0: a direction, at infinity), to the camera's clip
// space. The light cap lies on the caster's own lit surface: nudged a little deeper (in window
// depth, `nudge` = 1) it fails the depth test there, as the dark cap does, and the two cancel.
// Sides and the dark cap are not nudged (0), so the shadow's edge on a receiver stays exact.
// Shared by volume.geom and volume_kept.vert, which draws its captured output again, so that both
// stages take the same steps (`precise`: no contraction chosen per stage). On llvmpipe the two
// still differ in a few pixels of dense open foliage (17 of 230,400 on street.json), with or
// without `precise`; on the GL test's boxes in none (docs/measurements.md, stop 61).
vec4 volumeClip(mat4 viewProj, vec4 world, float nudge) {
    precise vec4 clip = viewProj * world;
    clip.z += nudge * 2e-5 * clip.w;
    return clip;
}
