#include "shadows/ShadowTechnique.h"

namespace penumbra::shadows {

CasterProgramPair::CasterProgramPair(const gl::ProgramDesc& plain, const gl::ProgramDesc& textured, bool coverageFromTexture)
    : plain_(gl::Program::build(plain)), textured_(gl::Program::build(textured)), coverageFromTexture_(coverageFromTexture) {}

static gl::ProgramDesc withDefine(gl::ProgramDesc desc, const char* define) {
    desc.defines.emplace_back(define);
    return desc;
}

static const gl::ProgramDesc kDepth{.vertex = "src/shadows/common/glsl/caster.vert", .fragment = "src/shadows/common/glsl/depth.frag"};
static const gl::ProgramDesc kTint{.vertex = "src/shadows/common/glsl/caster.vert", .fragment = "src/shadows/common/glsl/transmit.frag"};

DepthCasterProgram::DepthCasterProgram() : CasterProgramPair(kDepth, withDefine(kDepth, "ALPHA_TEST 1"), false) {}

TintCasterProgram::TintCasterProgram() : CasterProgramPair(withDefine(kTint, "MATERIAL_UNTEXTURED 1"), kTint, true) {}

}  // namespace penumbra::shadows
