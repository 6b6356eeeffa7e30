// The light block (std140) and the light-type codes: defined once, for C++ and GLSL alike, in
// src/gpu/ShaderContract.h.
#include "src/gpu/ShaderContract.h"

// Per light: its type, its shadow slot (-1: unshadowed) and its projector-picture slot (-1: none).
// A program the renderer specialised to the scene's lights (render/LightingProgram.h defines
// SCENE_LIGHT_COUNT and the lists) reads them as constants, so branches on them fold away;
// otherwise they come from the light block at run time.
#ifdef SCENE_LIGHT_COUNT
const int kSceneLightType[kMaxLights] = int[](SCENE_LIGHT_TYPES);
const int kSceneShadowSlot[kMaxLights] = int[](SCENE_SHADOW_SLOTS);
const int kSceneProjectorSlot[kMaxLights] = int[](SCENE_PROJECTOR_SLOTS);
int lightType(int i) { return kSceneLightType[i]; }
int lightShadowSlot(int i) { return kSceneShadowSlot[i]; }
int lightProjectorSlot(int i) { return kSceneProjectorSlot[i]; }
#else
int lightType(int i) { return int(uLights[i].colorType.w); }
int lightShadowSlot(int i) { return int(uLights[i].cone.w); }
int lightProjectorSlot(int i) { return int(uLights[i].cone.z); }
#endif
// Directional lights have orthographic maps; spot, projector and point lights perspective ones
// (shadows/LightSpace.cpp). A constant in a specialised program.
bool lightPerspective(int i) { return lightType(i) != kLightDirectional; }
