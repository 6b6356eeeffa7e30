// Texture units and buffer bindings shared by the lighting shader and the shadow lookups.
// Mirrored in src/render/Bindings.h: change both together.
#define MAX_LIGHTS 8
#define MAX_SHADOW_2D 8
#define MAX_SHADOW_CUBE 4
#define MAX_PROJECTORS 2

#define UNIT_DIFFUSE 0
#define UNIT_PROJECTOR 1      // .. +MAX_PROJECTORS
#define UNIT_SHADOW_2D 4      // .. +MAX_SHADOW_2D
#define UNIT_SHADOW_CUBE 12   // .. +MAX_SHADOW_CUBE
#define UNIT_TINT_2D 16       // .. +MAX_SHADOW_2D
#define UNIT_TINT_CUBE 24     // .. +MAX_SHADOW_CUBE
