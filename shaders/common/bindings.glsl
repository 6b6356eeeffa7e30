// Texture units and buffer bindings shared by the lighting shader and the shadow lookups.
// Mirrored in src/render/Bindings.h: change both together.
#define MAX_LIGHTS 8
#define MAX_SHADOW_2D 4       // shadowed directional / spot / projector lights
#define MAX_SHADOW_CUBE 2     // shadowed point lights
#define MAX_PROJECTORS 2

#define UNIT_DIFFUSE 0
#define UNIT_PROJECTOR 1      // .. +MAX_PROJECTORS
#define UNIT_JITTER 3         // 3D jitter texture of the PCF family
#define UNIT_SHADOW_2D 4      // depth with hardware compare
#define UNIT_TINT_2D 8        // transmittance of translucent casters
#define UNIT_RAW_2D 12        // raw depth (no compare) or a technique's moments
#define UNIT_SHADOW_CUBE 16
#define UNIT_TINT_CUBE 18
#define UNIT_RAW_CUBE 20
#define UNIT_LAYERED 22       // sampler2DArrayShadow of a LayeredDepthMap (cascades, LiSPSM tiles)
#define UNIT_SCREEN_SHADOW 23 // R8 array, per-light visibility in screen space (shadow volumes, planar)
#define UNIT_SCREEN_DEPTH 24  // the camera depth pre-pass of that mask
