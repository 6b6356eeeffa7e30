#pragma once
// glibc's malloc kept from handing llvmpipe's per-frame memory back to the kernel. glibc returns
// the driver's freed binning memory and faults it in again, and page faults are dear in this VM:
// the same pass ran 2-5x slower in some processes than in others (PLATFORM.md, "Timing on
// llvmpipe"). Switched frame by frame inside one `render` (stop 65, llvmpipe), the tuned frames
// were 1.3-2.6 ms (4-7 %) faster on the default scene and 1.7-7.4 ms (3-11 %) on the glass scene.
// bench, render and view apply it unless told `--malloc default`; bench.json and stats.json
// record what was in force.
#include <nlohmann/json.hpp>

namespace CLI {
class App;
}

namespace penumbra::app {

// `--malloc tuned|default` on `command`, into `tuned` (its default: tuned).
void addMallocOption(CLI::App& command, bool& tuned);

// Applies the choice to this process (tuned: mallopt, before the GL context is made) and returns
// what is in force: the mode, GLIBC_TUNABLES, and the mallopt settings when tuned.
nlohmann::json configureMalloc(bool tuned);

}  // namespace penumbra::app
