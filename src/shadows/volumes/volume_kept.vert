#version 450 core
// A still caster's shadow volume as volume.geom made it on an earlier frame (VolumeCache: captured
// in world space by transform feedback), drawn again through this frame's camera.
#include "src/shadows/volumes/volume_clip.glsl"
layout(location = 0) in vec4 aWorld;
layout(location = 1) in float aNudge;
uniform mat4 uViewProj;
void main() { gl_Position = volumeClip(uViewProj, aWorld, aNudge); }
