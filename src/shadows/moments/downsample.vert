#version 450 core
// One mip level of every face of a light's moments in one instanced draw (MomentShadowMap::
// makeMipLevels): instance i draws face uFirstFace + i as a quad over the texels of the level it
// redoes (uRects), into layer `face` of a layered framebuffer (a cube map's six faces; a 2D map's
// one). llvmpipe pays a pass per framebuffer binding, about 0.1 ms each however few its texels: a
// point light's 8 small levels of 6 faces were most of its moments' mip cost (stop 68).
#if LAYERED
#extension GL_ARB_shader_viewport_layer_array : require
#endif

uniform int uFirstFace;
uniform ivec4 uRects[6];  // per face: the level's texels [x0, x1) x [y0, y1) to make; empty: none
uniform vec2 uLevelSize;
flat out int vFace;

void main() {
    vFace = uFirstFace + gl_InstanceID;
    const ivec4 r = uRects[vFace];
    const vec2 corner = vec2((gl_VertexID & 1) != 0 ? r.z : r.x, (gl_VertexID & 2) != 0 ? r.w : r.y);
    gl_Position = vec4(corner / uLevelSize * 2.0 - 1.0, 0.0, 1.0);
#if LAYERED
    gl_Layer = vFace;
#endif
}
