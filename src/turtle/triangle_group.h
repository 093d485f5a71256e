// A group of the Scene's triangles as the turtle draws it: the colours,
// texture and module of whatever made it (polygons, surfaces, meshes ...).
#pragma once

#include <cstddef>
#include <cstdint>

#include "geometry/scene.h"

namespace sylva::turtle {

struct GroupLook {
  int color = 1;
  int back_color = -1;
  int texture = -1;
  geometry::Provenance from;
};

// The Scene's indices from `first_index` to its last as one group (none
// when there are no triangles); returns the number of triangles.
inline int add_triangle_group(geometry::Scene& scene, geometry::TriangleGroup::Kind kind, std::size_t first_index,
                              const GroupLook& look) {
  geometry::TriangleGroup g;
  g.kind = kind;
  g.first_index = static_cast<std::uint32_t>(first_index);
  g.index_count = static_cast<std::uint32_t>(scene.indices.size() - first_index);
  g.color = look.color;
  g.back_color = look.back_color;
  g.from = look.from;
  g.texture = look.texture;
  if (g.index_count > 0) scene.groups.push_back(g);
  return static_cast<int>(g.index_count / 3);
}

}  // namespace sylva::turtle
