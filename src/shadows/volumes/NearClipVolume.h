#pragma once
// Where z-pass counting is safe (Everitt & Kilgard 2002, "Practical and Robust Stenciled Shadow
// Volumes", §4.2): z-pass counts volume faces in front of the visible surface, which is wrong
// only where the near plane cuts a volume. A caster's volume reaches the near plane's rectangle
// only if the caster lies between that rectangle and the light: inside the near-clip volume, the
// rectangle swept towards the light (a pyramid up to a point light; a prism for the sun). Casters
// outside it can be counted z-pass, without caps; the rest need z-fail. Pure CPU, no GL.
#include "scene/Light.h"
#include "scene/Mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace penumbra::shadows {

class NearClipVolume {
public:
    // `inverseViewProj`: the camera's clip -> world (GL's -1..1 depth). A light on or behind the
    // near plane's plane, or one the rectangle is seen edge-on from, gives no planes: every caster
    // then takes z-fail.
    NearClipVolume(const glm::mat4& inverseViewProj, const scene::Light& light);
    // False only when `worldBounds` lies wholly outside one bounding plane: z-pass is safe.
    // Conservative: a box that straddles every plane counts as held, even where no point of it is.
    bool mayHold(const scene::Bounds& worldBounds) const;

private:
    std::vector<glm::vec4> planes_;  // inside: dot(plane, (p, 1)) >= 0; none: it may hold everything
};

}  // namespace penumbra::shadows
