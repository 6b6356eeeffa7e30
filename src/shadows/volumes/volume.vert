#version 450 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
out int vIndex;  // the welded vertex's index: the geometry shader orders corners by it
void main() {
    gl_Position = uModel * vec4(aPosition, 1.0);  // world space; extruded per light
    vIndex = gl_VertexID;
}
