#include "geometry/patch_mesh.h"

#include <algorithm>
#include <cstdint>

namespace sylva::geometry {

void append_patch(Scene& scene, const BezierPatch& patch, const Placement& place, int u_divisions, int v_divisions,
                  bool textured) {
  const int nu = std::max(u_divisions, 1), nv = std::max(v_divisions, 1);
  const auto base = static_cast<std::uint32_t>(scene.positions.size());
  scene.normals.resize(scene.positions.size(), Vec3{0, 0, 1});
  for (int j = 0; j <= nv; ++j) {
    const float v = static_cast<float>(j) / static_cast<float>(nv);
    for (int i = 0; i <= nu; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(nu);
      scene.positions.push_back(place.point(evaluate_patch(patch, u, v)));
      scene.normals.push_back(place.normal(patch_normal(patch, u, v)));
      if (textured) scene.set_texcoord(static_cast<std::uint32_t>(scene.positions.size() - 1), {v, 1 - u});
    }
  }
  const auto row = static_cast<std::uint32_t>(nu + 1);
  // A mirroring placement turns counter-clockwise into clockwise.
  const bool mirrored = dot(cross(place.x, place.y), place.z) < 0;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const std::uint32_t a = base + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const std::uint32_t b = a + 1, c = a + row + 1, d = a + row;
      // Counter-clockwise around dP/du x dP/dv, the normal's direction.
      if (mirrored) scene.indices.insert(scene.indices.end(), {a, c, b, a, d, c});
      else scene.indices.insert(scene.indices.end(), {a, b, c, a, c, d});
    }
  }
}

}  // namespace sylva::geometry
