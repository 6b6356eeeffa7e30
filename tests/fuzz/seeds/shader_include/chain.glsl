#version 450 core
#include "a.glsl"
#include "slot.glsl"
void main() {}

@@file slot.glsl
float slot() { return 1.0; }

@@file a.glsl
#include "b.glsl"
float a() { return b(); }

@@file b.glsl
float b() { return 2.0; }
