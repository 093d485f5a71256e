#include "geometry/face_normals.h"

#include <cstddef>

namespace sylva::geometry {

void set_normals_from_faces(Scene& scene, std::uint32_t first_vertex, std::uint32_t vertex_count,
                            std::uint32_t first_index, std::uint32_t index_count) {
  const std::size_t end = static_cast<std::size_t>(first_vertex) + vertex_count;
  if (scene.normals.size() < end) scene.normals.resize(end);
  for (std::size_t v = first_vertex; v < end; ++v) scene.normals[v] = Vec3{};
  for (std::uint32_t k = 0; k + 2 < index_count; k += 3) {
    const std::uint32_t a = scene.indices[first_index + k], b = scene.indices[first_index + k + 1],
                        c = scene.indices[first_index + k + 2];
    // The cross product's length is twice the area: larger faces weigh more.
    const Vec3 n = cross(scene.positions[b] - scene.positions[a], scene.positions[c] - scene.positions[a]);
    for (std::uint32_t v : {a, b, c})
      if (v >= first_vertex && v < end) scene.normals[v] += n;
  }
  for (std::size_t v = first_vertex; v < end; ++v) {
    const Vec3 n = scene.normals[v];
    scene.normals[v] = dot(n, n) > 0 ? normalized(n) : Vec3{0, 0, 1};
  }
}

}  // namespace sylva::geometry
