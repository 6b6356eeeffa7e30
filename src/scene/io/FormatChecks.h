#pragma once
// Structural checks of model files before Assimp reads them. Debian's Assimp 5.2 loops forever on
// some malformed PLY files and allocates whatever a glTF buffer or accessor declares (tests/fuzz
// found both), so a file that breaks its format's rules is refused here, at once, with the rule
// it breaks (InputError: file, line where there is one, what is wrong). Files that pass are
// well-formed as far as these checks go; Assimp still reports its own errors.
#include <filesystem>

namespace penumbra::scene::io {

// PLY (Bourke's format): a strict header ("ply", a known format 1.0, named elements with
// counts, properties of known types, end_header), then data that holds every element the
// header declares: binary walked instance by instance (list lengths included), ASCII one
// instance per line with the right number of numbers.
void checkPly(const std::filesystem::path& file);

// glTF 2.0 (.gltf and .glb): the GLB container (magic, version, length, JSON and BIN chunks)
// and, in the JSON, that every buffer's bytes exist (BIN chunk, data: URI or file beside the
// model), that buffer views lie inside their buffers and accessors inside their views.
void checkGltf(const std::filesystem::path& file);

}  // namespace penumbra::scene::io
