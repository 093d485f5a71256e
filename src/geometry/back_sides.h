// Mesh files have one material per triangle, seen from both sides. A part
// whose back side has a colour of its own (cpfg's @; @,) is split in two:
// the front part keeps its triangles and is marked Front, and a Back part
// repeats them, wound the other way with normals reversed, in the back
// colour. A viewer that hides the side a triangle faces away from then shows
// each side in its colour.
#pragma once

#include "geometry/tessellation.h"

namespace sylva::geometry {

// Appends the Back part right after each such part, keeping string order.
void split_back_sides(TriangleMesh& mesh);

}  // namespace sylva::geometry
