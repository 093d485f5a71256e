#include "turtle/shape_drawer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "geometry/face_normals.h"
#include "geometry/patch_mesh.h"
#include "support/diagnostic.h"
#include "turtle/model_error_text.h"
#include "turtle/triangle_group.h"

namespace sylva::turtle {

using geometry::TriangleGroup;

namespace {

GroupLook look_of(const TurtleState& turtle, geometry::Provenance from, int texture = -1) {
  return GroupLook{turtle.color, turtle.back_color, texture, from};
}

// The turtle's surface divisions where set, else the surface's own.
int divisions(int turtle, int own) { return turtle > 0 ? turtle : own; }

}  // namespace

void ShapeDrawer::circle(const TurtleState& turtle, geometry::Provenance from, float radius, float outline,
                         bool facing_viewer) {
  if (!scene_) return;
  geometry::Circle c;
  c.center = turtle.position;
  c.normal = turtle.frame.up;
  c.heading = turtle.frame.heading;
  c.radius = radius;
  c.outline = outline;
  c.facing_viewer = facing_viewer;
  c.color = turtle.color;
  c.from = from;
  scene_->circles.push_back(c);
}

void ShapeDrawer::sphere(const TurtleState& turtle, geometry::Provenance from, float radius) {
  if (!scene_) return;
  geometry::Sphere s;
  s.center = turtle.position;
  s.radius = radius;
  s.slices = turtle.contour_sides;
  s.color = turtle.color;
  s.from = from;
  scene_->spheres.push_back(s);
}

int ShapeDrawer::flat_shape(const TurtleState& turtle, geometry::Provenance from, TriangleGroup::Kind kind,
                            const Vec3* corners, int count) {
  if (!scene_) return -1;
  const auto base = static_cast<std::uint32_t>(scene_->positions.size());
  scene_->normals.resize(scene_->positions.size(), Vec3{0, 0, 1});
  for (int k = 0; k < count; ++k) {
    scene_->positions.push_back(corners[k]);
    scene_->normals.push_back(turtle.frame.up);
  }
  const std::size_t first_index = scene_->indices.size();
  for (int k = 1; k + 1 < count; ++k)
    scene_->indices.insert(scene_->indices.end(),
                           {base, base + static_cast<std::uint32_t>(k), base + static_cast<std::uint32_t>(k + 1)});
  return add_triangle_group(*scene_, kind, first_index, look_of(turtle, from));
}

// Local coordinates (whose own heading and up are `local_heading`,
// `local_up`) at the turtle: `contact` goes to the turtle's position, the
// local heading to H and the local up to U; `scale` scales the local x, y, z.
geometry::Placement ShapeDrawer::placement(const TurtleState& turtle, Vec3 local_heading, Vec3 local_up, Vec3 contact,
                                           Vec3 scale) const {
  Vec3 h = normalized(local_heading);
  Vec3 l = cross(local_up, h);
  if (length(h) < kEpsilon || length(l) < kEpsilon) {
    h = {0, 1, 0};
    l = {-1, 0, 0};
  }
  l = normalized(l);
  const Vec3 u = cross(h, l);
  const Frame& f = turtle.frame;
  // Where each local axis points in the world: its components along the
  // local heading, left and up become the turtle's.
  auto image = [&](float along_h, float along_l, float along_u) {
    return f.heading * along_h + f.left * along_l + f.up * along_u;
  };
  geometry::Placement p = geometry::Placement::from_frame(Vec3{}, image(h.x, l.x, u.x), image(h.y, l.y, u.y),
                                                          image(h.z, l.z, u.z), scale);
  p.origin = turtle.position - (p.point(contact) - p.origin);
  return p;
}

void ShapeDrawer::require_view_file_id(const char* module, geometry::Provenance from, const char* kind,
                                       const char* kinds, int id, std::size_t count) {
  if (id >= 0 && static_cast<std::size_t>(id) < count) return;
  throw ModelError(std::string(module) + "(" + std::to_string(id) + ", ...)" + where(from) + ": there is no " + kind +
                   " " + std::to_string(id) +
                   (count ? " (the view file gives " + std::string(kinds) + " 0 to " + std::to_string(count - 1) + ")"
                          : " (no view file gives " + std::string(kinds) + ")"));
}

int ShapeDrawer::surface(const TurtleState& turtle, geometry::Provenance from, int id, Vec3 scale, const char* module,
                         bool view_texture_first, const char*& name) {
  require_view_file_id(module, from, "surface", "surfaces", id, settings_.surfaces ? settings_.surfaces->size() : 0);
  const geometry::BezierSurface& s = (*settings_.surfaces)[static_cast<std::size_t>(id)];
  name = s.name.c_str();
  if (!scene_) return -1;
  const float size = s.size != 0 ? s.size : 1.0f;
  const geometry::Placement place = placement(turtle, s.heading, s.up, s.contact, scale / size);
  const int texture = view_texture_first ? (s.texture >= 0 ? s.texture : turtle.texture)
                                         : (turtle.texture >= 0 ? turtle.texture : s.texture);
  const std::size_t first_index = scene_->indices.size();
  for (const geometry::BezierPatch& patch : s.patches)
    geometry::append_patch(*scene_, patch, place, divisions(turtle.u_precision, s.u_divisions),
                           divisions(turtle.v_precision, s.v_divisions), texture >= 0);
  return add_triangle_group(*scene_, TriangleGroup::Kind::Surface, first_index, look_of(turtle, from, texture));
}

int ShapeDrawer::mesh(const TurtleState& turtle, geometry::Provenance from, int id, Vec3 scale, const char* module,
                      const char*& name) {
  require_view_file_id(module, from, "mesh", "meshes", id, settings_.meshes ? settings_.meshes->size() : 0);
  const geometry::PredefinedMesh& m = (*settings_.meshes)[static_cast<std::size_t>(id)];
  name = m.name.c_str();
  if (!scene_) return -1;
  // Mesh coordinates as the turtle's initial frame sees the world: y along H, z along U.
  const geometry::Placement place = placement(turtle, {0, 1, 0}, {0, 0, 1}, m.contact, scale * m.scale);
  const auto base = static_cast<std::uint32_t>(scene_->positions.size());
  scene_->normals.resize(scene_->positions.size(), Vec3{0, 0, 1});
  const bool has_normals = m.normals.size() == m.positions.size();
  for (std::size_t k = 0; k < m.positions.size(); ++k) {
    scene_->positions.push_back(place.point(m.positions[k]));
    scene_->normals.push_back(has_normals ? place.normal(m.normals[k]) : Vec3{0, 0, 1});
  }
  const bool mirrored = dot(cross(place.x, place.y), place.z) < 0;
  const std::size_t first_index = scene_->indices.size();
  for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3) {
    const std::uint32_t a = base + m.indices[k], b = base + m.indices[k + 1], c = base + m.indices[k + 2];
    if (mirrored) scene_->indices.insert(scene_->indices.end(), {a, c, b});
    else scene_->indices.insert(scene_->indices.end(), {a, b, c});
  }
  if (!has_normals)
    geometry::set_normals_from_faces(*scene_, base, static_cast<std::uint32_t>(m.positions.size()),
                                     static_cast<std::uint32_t>(first_index),
                                     static_cast<std::uint32_t>(scene_->indices.size() - first_index));
  return add_triangle_group(*scene_, TriangleGroup::Kind::Mesh, first_index, look_of(turtle, from));
}

int ShapeDrawer::bezier_patch(const TurtleState& turtle, geometry::Provenance from, const unsigned char* points) {
  if (!scene_) return -1;
  geometry::BezierPatch patch;
  for (std::size_t k = 0; k < 16; ++k) {
    float xyz[3];
    std::memcpy(xyz, points + 12 * k, sizeof xyz);
    patch.points[k] = {xyz[0], xyz[1], xyz[2]};
  }
  // Like a surface whose frame is the turtle's initial one, at unit size.
  const geometry::Placement place = placement(turtle, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {1, 1, 1});
  const geometry::BezierSurface defaults;
  const std::size_t first_index = scene_->indices.size();
  geometry::append_patch(*scene_, patch, place, divisions(turtle.u_precision, defaults.u_divisions),
                         divisions(turtle.v_precision, defaults.v_divisions));
  return add_triangle_group(*scene_, TriangleGroup::Kind::Surface, first_index, look_of(turtle, from));
}

void ShapeDrawer::lsystem_surface_point(const TurtleState& turtle, geometry::Provenance from, int row, int column) {
  if (row < 0 || row > 3 || column < 0 || column > 3)
    throw ModelError("SurfacePoint(id, " + std::to_string(row) + ", " + std::to_string(column) + ")" + where(from) +
                     ": the control point's row and column go from 0 to 3");
  lsystem_surface_.points[static_cast<std::size_t>(4 * row + column)] = turtle.position;
}

int ShapeDrawer::draw_lsystem_surface(const TurtleState& turtle, geometry::Provenance from) {
  if (!scene_) return -1;
  const geometry::BezierSurface defaults;
  const std::size_t first_index = scene_->indices.size();
  // Its control points are turtle positions: already in the world.
  geometry::append_patch(*scene_, lsystem_surface_, geometry::Placement{},
                         divisions(turtle.u_precision, defaults.u_divisions),
                         divisions(turtle.v_precision, defaults.v_divisions));
  return add_triangle_group(*scene_, TriangleGroup::Kind::Surface, first_index, look_of(turtle, from));
}

void ShapeDrawer::label(const TurtleState& turtle, geometry::Provenance from, std::string text) {
  if (!scene_) return;
  geometry::Label l;
  l.position = turtle.position;
  l.text = std::move(text);
  l.color = turtle.color;
  l.from = from;
  scene_->labels.push_back(std::move(l));
}

}  // namespace sylva::turtle
