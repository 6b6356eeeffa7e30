// A shadow volume's vertex, in world space (w = 0: a direction, at infinity), to the camera's clip
// space. The light cap lies on the caster's own lit surface: nudged a little deeper (in window
// depth, `nudge` = 1) it fails the depth test there, as the dark cap does, and the two cancel.
// Sides and the dark cap are not nudged (0), so the shadow's edge on a receiver stays exact.
// Shared by volume.geom and volume_kept.vert, which draws its captured output again: `precise`
// keeps the compiler from fusing the two stages' products differently, so both put a vertex on the
// same bits and the kept volume counts the same pixels as the one it was captured from.
vec4 volumeClip(mat4 viewProj, vec4 world, float nudge) {
    precise vec4 clip = viewProj * world;
    clip.z += nudge * 2e-5 * clip.w;
    return clip;
}
