#include "app/TechniqueList.h"

#include "platform/EglContext.h"
#include "shadows/ShadowTechnique.h"

#include <cstdio>

namespace penumbra::app {

static const char* kindName(shadows::Parameter::Kind kind) {
    switch (kind) {
        case shadows::Parameter::Kind::Real: return "real";
        case shadows::Parameter::Kind::Integer: return "integer";
        case shadows::Parameter::Kind::Flag: return "flag";
        case shadows::Parameter::Kind::Choice: return "choice";
    }
    return "?";
}

int printTechniques(bool verbose) {
    std::unique_ptr<platform::EglContext> context;
    if (verbose) context = platform::EglContext::create("auto");
    for (const auto& info : shadows::techniqueRegistry()) {
        std::printf("%-14s %s\n", info.name.c_str(), info.description.c_str());
        if (!verbose) continue;
        auto technique = shadows::createTechnique(info.name);
        for (const auto& p : technique->parameters())
            std::printf("    --param %s=<%s>  %s, default %s: %s\n", p.name.c_str(), p.accepted().c_str(), kindName(p.kind),
                        p.defaultText.c_str(), p.help.c_str());
    }
    return 0;
}

}  // namespace penumbra::app
