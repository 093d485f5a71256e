#include "turtle/polygon_builder.h"

#include <algorithm>
#include <cmath>

#include "geometry/face_normals.h"
#include "geometry/polygon_triangulation.h"

namespace sylva::turtle {

int PolygonBuilder::start(geometry::Provenance from) {
  open_.push_back(OpenPolygon{points_.size(), from, Frame{}});
  return static_cast<int>(open_.size());
}

int PolygonBuilder::add_vertex(Vec3 position, const Frame& frame) {
  points_.push_back(position);
  ups_.push_back(frame.up);
  const auto number = static_cast<int>(points_.size() - open_.back().first);
  if (number == 1) open_.back().first_frame = frame;
  return number;
}

PolygonBuilder::Ended PolygonBuilder::end(geometry::Scene* scene, const Look& look) {
  const OpenPolygon polygon = open_.back();
  open_.pop_back();
  Ended ended;
  ended.vertices = static_cast<int>(points_.size() - polygon.first);
  if (scene && ended.vertices >= 3) draw(*scene, polygon.first, polygon.first_frame, look, polygon.from, ended);
  points_.resize(polygon.first);
  ups_.resize(polygon.first);
  return ended;
}

namespace {

// cpfg/textures.c SetPolygonTextureParams: s along the first vertex's right
// (-L), t along its heading, each stretched over the polygon's extent.
void set_texture_coordinates(geometry::Scene& scene, std::uint32_t base, std::size_t count, const Frame& first_frame) {
  const Vec3 s_axis = -first_frame.left, t_axis = first_frame.heading;
  float min_s = INFINITY, max_s = -INFINITY, min_t = INFINITY, max_t = -INFINITY;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 p = scene.positions[base + k];
    min_s = std::min(min_s, dot(p, s_axis)), max_s = std::max(max_s, dot(p, s_axis));
    min_t = std::min(min_t, dot(p, t_axis)), max_t = std::max(max_t, dot(p, t_axis));
  }
  const float ds = max_s > min_s ? 1 / (max_s - min_s) : 0, dt = max_t > min_t ? 1 / (max_t - min_t) : 0;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 p = scene.positions[base + k];
    scene.set_texcoord(base + static_cast<std::uint32_t>(k), {(dot(p, s_axis) - min_s) * ds, (dot(p, t_axis) - min_t) * dt});
  }
}

}  // namespace

void PolygonBuilder::draw(geometry::Scene& scene, std::size_t first, const Frame& first_frame, const Look& look,
                          geometry::Provenance from, Ended& ended) {
  const std::size_t count = points_.size() - first;
  const Vec3* points = points_.data() + first;
  const auto base = static_cast<std::uint32_t>(scene.positions.size());
  triangles_.clear();
  geometry::triangulate_polygon(points, count, base, triangles_, triangulation_work_);

  // The normal the polygon shows: from its first two edges ("auto normals"),
  // or the turtle's up at each vertex.
  Vec3 facing;
  if (look.auto_normals) {
    facing = cross(points[1] - points[0], points[2] - points[1]);
    if (length(facing) == 0) facing = geometry::newell_normal(points, count);
    facing = normalized(facing);
  } else {
    for (std::size_t k = 0; k < count; ++k) facing += ups_[first + k];
  }
  // Triangles wind like the vertices; turn them to face the chosen normal.
  if (dot(geometry::newell_normal(points, count), facing) < 0)
    for (std::size_t k = 0; k + 2 < triangles_.size(); k += 3) std::swap(triangles_[k + 1], triangles_[k + 2]);

  scene.normals.resize(scene.positions.size(), Vec3{0, 0, 1});
  scene.positions.insert(scene.positions.end(), points, points + count);
  if (look.auto_normals) scene.normals.insert(scene.normals.end(), count, facing);
  else scene.normals.insert(scene.normals.end(), ups_.begin() + static_cast<std::ptrdiff_t>(first), ups_.end());
  if (look.texture >= 0) set_texture_coordinates(scene, base, count, first_frame);
  const std::size_t first_index = scene.indices.size();
  scene.indices.insert(scene.indices.end(), triangles_.begin(), triangles_.end());
  // The polygon is the module's that started it.
  ended.triangles = add_triangle_group(scene, geometry::TriangleGroup::Kind::Polygon, first_index,
                                       GroupLook{look.color, look.back_color, look.texture, from});
}

}  // namespace sylva::turtle
