// A predefined mesh from the view file ("mesh: file.obj S:scale C:x y z",
// LPFG manual 8.1.5), drawn by the Mesh and Mesh3 modules.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/vec3.h"

namespace sylva::geometry {

struct PredefinedMesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;           // one per position, or empty: computed from the faces
  std::vector<std::uint32_t> indices;  // triangles, 3 per
  Vec3 contact{0, 0, 0};               // the point placed at the turtle's position
  float scale = 1;                     // multiplies the module's scale
};

}  // namespace sylva::geometry
