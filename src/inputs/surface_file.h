// Bézier surface files (.s, VLAB Tools manual 5.4), as bezieredit and stedit
// write them.
#pragma once

#include <string>

#include "geometry/surface.h"

namespace sylva::io {

// The surface is named after the file. Patch colours and neighbours are read
// past: the surface is drawn in the turtle's colour.
geometry::BezierSurface read_surface_file(const std::string& path);

}  // namespace sylva::io
