#pragma once
// `penumbra techniques [--verbose]`: the registry, and with --verbose every technique's typed
// parameters (kind, accepted values, default, help).
namespace penumbra::app {

// Returns the process exit code. --verbose creates each technique, so it opens an EGL context.
int printTechniques(bool verbose);

}  // namespace penumbra::app
