// The light block (std140) and the light-type codes: defined once, for C++ and GLSL alike, in
// src/gpu/ShaderContract.h.
#include "src/gpu/ShaderContract.h"

int lightType(int i) { return int(uLights[i].colorType.w); }
