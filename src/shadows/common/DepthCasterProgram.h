#pragma once
#include "gl/Program.h"
#include "shadows/ShadowTechnique.h"

namespace penumbra::shadows {

// Opaque casters into depth alone (depth.frag), as a pair: an empty fragment stage for most
// materials and the alpha test for alpha-tested ones (see DrawPrograms for why they differ).
// Uniforms set here reach both.
class DepthCasterProgram {
public:
    DepthCasterProgram();
    template <class T>
    void set(const char* name, const T& value) const {
        plain_.set(name, value);
        alphaTested_.set(name, value);
    }
    operator DrawPrograms() const { return {plain_, alphaTested_}; }  // NOLINT: implicit by design

private:
    gl::Program plain_, alphaTested_;
};

}  // namespace penumbra::shadows
