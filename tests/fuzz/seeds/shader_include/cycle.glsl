#version 450 core
#include "x.glsl"

@@file x.glsl
#include "y.glsl"

@@file y.glsl
#include "x.glsl"
#include "main.glsl"
