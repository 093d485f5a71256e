// cpfg background scene files (CPFGManual 8.3) as arvo's obstacles: the
// primitives (polygon, polygonuv, rectangle, mesh, box, cone, cylinder,
// sphere) placed by the transformation commands (loadidentity, loadmatrix,
// pushmatrix, popmatrix, translate, rotate, scale, mulmatrix). Materials,
// lighting and projection commands are read and have no effect on collisions.
// Comments (/* */ and //) and object-like "#define NAME value" macros are
// understood, as cpfg preprocesses the file.
#pragma once

#include <filesystem>

#include "env/programs/arvo_obstacles.h"

namespace sylva::env::arvo {

// Adds the file's primitives to `scene`; a ModelError with file:line:column
// for anything that is not a command with the numbers it needs.
void read_background_file(const std::filesystem::path& path, ObstacleScene& scene);

}  // namespace sylva::env::arvo
