#include "geometry/scene.h"

#include <algorithm>

namespace sylva::geometry {

void Scene::add_triangles(TriangleGroup::Kind kind, const std::vector<Vec3>& vertices,
                          const std::vector<Vec3>& vertex_normals, const std::vector<std::uint32_t>& triangle_indices,
                          int color, Provenance from) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), vertices.begin(), vertices.end());
  normals.insert(normals.end(), vertex_normals.begin(), vertex_normals.end());
  normals.resize(positions.size(), Vec3{0, 0, 1});
  TriangleGroup g;
  g.kind = kind;
  g.first_index = static_cast<std::uint32_t>(indices.size());
  g.index_count = static_cast<std::uint32_t>(triangle_indices.size());
  g.color = color;
  g.from = from;
  for (std::uint32_t i : triangle_indices) indices.push_back(base + i);
  groups.push_back(g);
}

void Scene::append(const Scene& other) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  const auto first = static_cast<std::uint32_t>(indices.size());
  segments.insert(segments.end(), other.segments.begin(), other.segments.end());
  circles.insert(circles.end(), other.circles.begin(), other.circles.end());
  spheres.insert(spheres.end(), other.spheres.begin(), other.spheres.end());
  labels.insert(labels.end(), other.labels.begin(), other.labels.end());
  normals.resize(positions.size(), Vec3{0, 0, 1});
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  normals.resize(positions.size(), Vec3{0, 0, 1});
  if (!other.texcoords.empty()) {
    texcoords.resize(base);
    texcoords.insert(texcoords.end(), other.texcoords.begin(), other.texcoords.end());
  }
  for (std::uint32_t i : other.indices) indices.push_back(base + i);
  for (TriangleGroup g : other.groups) {
    g.first_index += first;
    groups.push_back(g);
  }
  if (!camera) camera = other.camera;
}

Box Scene::bounds() const {
  Box box;
  for (const Segment& s : segments) {
    float r = std::max(s.start_width, s.end_width) * 0.5f;
    for (Vec3 p : {s.start, s.end}) {
      box.add(p - Vec3{r, r, r});
      box.add(p + Vec3{r, r, r});
    }
  }
  for (const Circle& c : circles) {
    float r = c.radius + c.outline * 0.5f;
    box.add(c.center - Vec3{r, r, r});
    box.add(c.center + Vec3{r, r, r});
  }
  for (const Sphere& s : spheres) {
    box.add(s.center - Vec3{s.radius, s.radius, s.radius});
    box.add(s.center + Vec3{s.radius, s.radius, s.radius});
  }
  for (const Label& l : labels) box.add(l.position);
  for (const TriangleGroup& g : groups)
    for (std::uint32_t k = 0; k < g.index_count; ++k) box.add(positions[indices[g.first_index + k]]);
  return box;
}

}  // namespace sylva::geometry
