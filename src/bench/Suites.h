#pragma once
// Named benchmark suites: the seeds' experiments as lists of cases, on scenes the repository
// has or generates.
// - cssm-table: Mátl 2013 Table 6.1, SM vs CSSM, map creation vs scene rendering, maps
//   2048/4096/8192, generated coloured-glass scenes of about 12k, 37k and 786k triangles.
// - osg-tables: Plachý 2012 Tables 4.1-4.8, FPS per map resolution 256-4096 with and without
//   shadows, SM / PCF soft / cascaded (PSSM) / LiSPSM at 1024, LiSPSM tiles 1x1 2x2 3x3, memory.
// - all-techniques: every technique on the default scene and on a ~1M-triangle scene.
// - floor: the bare depth-only raster, the bare Lambert + one-lookup frame and the bare unshadowed
//   Lambert frame beside none and hard (with kept maps, and with every map redrawn as the floor's).
// - triangle-scaling: hard, cascaded, lispsm and vsm on the generated grid at 10k, 30k, 100k,
//   300k and 1M triangles, every map redrawn every frame; the report fits each technique's shadow
//   pass against the triangles it drew (shadowPassScaling, Report.h).
#include "bench/Bench.h"

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::bench {

std::vector<std::string> suiteNames();
// The same, comma-separated (help texts and errors).
std::string suiteList();

// The cases of `suite`. Generated scenes are written under `sceneDir` (reused when present).
// Throws std::invalid_argument naming the known suites for an unknown name.
std::vector<BenchCase> suiteCases(const std::string& suite, const std::filesystem::path& sceneDir);

// A ground plane and a 10x10 grid of floating spheres and tori, tessellated to about
// `triangles` triangles, lit by one sun: `<dir>/<name>.json` for penumbra (one object per shape,
// so culling has objects to work with) and `<dir>/<name>.obj` holding the same triangles in one
// file for other programs (the OpenSceneGraph peer). With `colouredGlass`, every other shape is
// coloured glass (alpha 0.6, transmission red / green / blue / amber). Returns the JSON's path.
std::filesystem::path writeGridScene(const std::filesystem::path& dir, const std::string& name, std::size_t triangles,
                                     bool colouredGlass);

}  // namespace penumbra::bench
