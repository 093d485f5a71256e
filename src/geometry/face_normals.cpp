#include "geometry/face_normals.h"

#include <algorithm>
#include <cmath>
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
    const Vec3 pa = scene.positions[a], pb = scene.positions[b], pc = scene.positions[c];
    const Vec3 n = normalized(cross(pb - pa, pc - pa));
    const std::uint32_t corner[3] = {a, b, c};
    const Vec3 at[3] = {pa, pb, pc};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = corner[k];
      if (v < first_vertex || v >= end) continue;
      const Vec3 e1 = normalized(at[(k + 1) % 3] - at[k]), e2 = normalized(at[(k + 2) % 3] - at[k]);
      const float angle = std::acos(std::clamp(dot(e1, e2), -1.0f, 1.0f));
      scene.normals[v] += n * angle;
    }
  }
  for (std::size_t v = first_vertex; v < end; ++v) {
    const Vec3 n = scene.normals[v];
    scene.normals[v] = dot(n, n) > 0 ? normalized(n) : Vec3{0, 0, 1};
  }
}

}  // namespace sylva::geometry
