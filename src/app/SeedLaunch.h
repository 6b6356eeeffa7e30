#pragma once
// Seed 002's two ways of starting the program (its section 3.3): a text menu that asks for scene,
// shadow technique and camera manipulator (and, for LiSPSM, the tiles across and down), and the
// same choices as numbered flags for batch files: -sc N -sh N -m N -cw N -ch N. Both resolve to
// penumbra's named options; the numbers are the seed's.
#include "render/Renderer.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace penumbra::app {

// The seed's numbers; 0 = not given.
struct SeedChoices {
    int scene = 0;        // 1 bench in a park, 2 construction site, 3 street
    int technique = 0;    // 1 none, 2 shadow maps, 3 soft, 4 PSSM, 5 LiSPSM, 6 combined (street only)
    int manipulator = 0;  // 1 trackball, 2 first person, 3 orbit
    int tilesAcross = 0, tilesDown = 0;  // LiSPSM's cameras across and down (1-4)
    bool any() const { return scene || technique || manipulator || tilesAcross || tilesDown; }
};

// argv with the seed's flags spelled as penumbra's long ones (-sc -> --seed-scene, -sh ->
// --seed-technique, -m -> --seed-manipulator, -cw -> --tiles-across, -ch -> --tiles-down), so
// CLI11, which takes single-letter short options only, parses them.
std::vector<std::string> expandSeedFlags(int argc, char** argv);

// Registers --seed-scene, --seed-technique, --seed-manipulator, --tiles-across and --tiles-down.
void addSeedChoices(CLI::App& command, SeedChoices& choices);

// Applies the choices to the named options: the scene file, the technique (and LiSPSM's cols and
// rows), the camera controller. Throws std::invalid_argument for a combination the seed does not
// offer (tiles without LiSPSM); 6 on a scene without regions fails where the scene is loaded
// (RenderOptions::requireRegions).
void applySeedChoices(const SeedChoices& choices, std::filesystem::path& scene, render::RenderOptions& render,
                      std::string& controller);

// The menu on `in` and `out`: each question until a valid number comes; end of input throws
// std::runtime_error.
SeedChoices askSeedMenu(std::istream& in, std::ostream& out);

// The short-flag command line the choices equal ("penumbra view -sc 3 -sh 6 -m 1").
std::string seedCommandLine(const SeedChoices& choices);

}  // namespace penumbra::app
