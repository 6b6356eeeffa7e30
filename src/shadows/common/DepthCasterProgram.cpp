#include "shadows/ShadowTechnique.h"

namespace penumbra::shadows {

DepthCasterProgram::DepthCasterProgram() {
    const gl::ProgramDesc plain{.vertex = "src/shadows/common/glsl/caster.vert",
                                   .fragment = "src/shadows/common/glsl/depth.frag"};
    gl::ProgramDesc alphaTested = plain;
    alphaTested.defines = {"ALPHA_TEST 1"};
    plain_ = gl::Program::build(plain);
    alphaTested_ = gl::Program::build(alphaTested);
}

}  // namespace penumbra::shadows
