// Circles, spheres, polygons, rhombi, triangles, Bézier surfaces, meshes and
// labels: the turtle's shapes other than lines and generalized cylinders.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "geometry/face_normals.h"
#include "geometry/patch_mesh.h"
#include "geometry/polygon_triangulation.h"
#include "support/diagnostic.h"

#include "turtle/interpreter_impl.h"
#include "turtle/trace.h"

namespace sylva::turtle {

using geometry::TriangleGroup;

void TurtleInterpreter::Impl::circle(float radius, float outline, bool facing_viewer) {
  if (scene_) {
    geometry::Circle c;
    c.center = state_.position;
    c.normal = state_.frame.up;
    c.heading = state_.frame.heading;
    c.radius = radius;
    c.outline = outline;
    c.facing_viewer = facing_viewer;
    c.color = state_.color;
    c.from = from_;
    scene_->circles.push_back(c);
  }
  if (trace_) {
    note_position(" at ", state_.position);
    *trace_ += " radius ";
    append_number(*trace_, radius);
  }
}

void TurtleInterpreter::Impl::sphere(float radius) {
  if (scene_) {
    geometry::Sphere s;
    s.center = state_.position;
    s.radius = radius;
    s.slices = state_.contour_sides;
    s.color = state_.color;
    s.from = from_;
    scene_->spheres.push_back(s);
  }
  if (trace_) {
    note_position(" at ", state_.position);
    *trace_ += " radius ";
    append_number(*trace_, radius);
  }
}

void TurtleInterpreter::Impl::begin_group() { group_first_index_ = scene_->indices.size(); }

void TurtleInterpreter::Impl::end_group(TriangleGroup::Kind kind) {
  TriangleGroup g;
  g.kind = kind;
  g.first_index = static_cast<std::uint32_t>(group_first_index_);
  g.index_count = static_cast<std::uint32_t>(scene_->indices.size() - group_first_index_);
  g.color = state_.color;
  g.back_color = state_.back_color;
  g.from = from_;
  g.texture = group_texture_;
  group_texture_ = -1;
  if (g.index_count > 0) scene_->groups.push_back(g);
  if (trace_) *trace_ += ", " + std::to_string(g.index_count / 3) + " triangles";
}

// ---- polygons ----------------------------------------------------------------------

void TurtleInterpreter::Impl::start_polygon() {
  polygons_.push_back(OpenPolygon{polygon_points_.size(), from_});
  if (trace_) *trace_ += " polygon depth " + std::to_string(polygons_.size());
}

void TurtleInterpreter::Impl::polygon_vertex() {
  if (polygons_.empty()) {
    note(" ignored: no polygon");
    return;
  }
  polygon_points_.push_back(state_.position);
  polygon_ups_.push_back(state_.frame.up);
  if (polygon_points_.size() - polygons_.back().first == 1) polygons_.back().first_frame = state_.frame;
  if (trace_) *trace_ += " vertex " + std::to_string(polygon_points_.size() - polygons_.back().first);
}

void TurtleInterpreter::Impl::end_polygon() {
  if (polygons_.empty()) {
    note(" ignored: no polygon");
    return;
  }
  const OpenPolygon open = polygons_.back();
  polygons_.pop_back();
  const Provenance module = from_;
  from_ = open.from;  // the polygon is the SP's: where it starts
  if (trace_) *trace_ += " polygon of " + std::to_string(polygon_points_.size() - open.first) + " vertices";
  draw_polygon(open.first, open.first_frame);
  from_ = module;
  polygon_points_.resize(open.first);
  polygon_ups_.resize(open.first);
}

// cpfg/textures.c SetPolygonTextureParams: s along the first vertex's right
// (-L), t along its heading, each stretched over the polygon's extent.
void TurtleInterpreter::Impl::texture_polygon(std::uint32_t base, std::size_t count, const Frame& first_frame) {
  const Vec3 s_axis = -first_frame.left, t_axis = first_frame.heading;
  float min_s = INFINITY, max_s = -INFINITY, min_t = INFINITY, max_t = -INFINITY;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 p = scene_->positions[base + k];
    min_s = std::min(min_s, dot(p, s_axis)), max_s = std::max(max_s, dot(p, s_axis));
    min_t = std::min(min_t, dot(p, t_axis)), max_t = std::max(max_t, dot(p, t_axis));
  }
  const float ds = max_s > min_s ? 1 / (max_s - min_s) : 0, dt = max_t > min_t ? 1 / (max_t - min_t) : 0;
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 p = scene_->positions[base + k];
    scene_->set_texcoord(base + static_cast<std::uint32_t>(k), {(dot(p, s_axis) - min_s) * ds, (dot(p, t_axis) - min_t) * dt});
  }
  group_texture_ = state_.texture;
}

void TurtleInterpreter::Impl::draw_polygon(std::size_t first, const Frame& first_frame) {
  const std::size_t count = polygon_points_.size() - first;
  if (!scene_ || count < 3) return;
  const Vec3* points = polygon_points_.data() + first;
  const auto base = static_cast<std::uint32_t>(scene_->positions.size());
  triangles_.clear();
  geometry::triangulate_polygon(points, count, base, triangles_, triangulation_work_);

  // The normal the polygon shows: from its first two edges ("auto normals"),
  // or the turtle's up at each vertex.
  Vec3 facing;
  if (settings_.auto_normals) {
    facing = cross(points[1] - points[0], points[2] - points[1]);
    if (length(facing) == 0) facing = geometry::newell_normal(points, count);
    facing = normalized(facing);
  } else {
    for (std::size_t k = 0; k < count; ++k) facing += polygon_ups_[first + k];
  }
  // Triangles wind like the vertices; turn them to face the chosen normal.
  if (dot(geometry::newell_normal(points, count), facing) < 0)
    for (std::size_t k = 0; k + 2 < triangles_.size(); k += 3) std::swap(triangles_[k + 1], triangles_[k + 2]);

  scene_->normals.resize(scene_->positions.size(), Vec3{0, 0, 1});
  scene_->positions.insert(scene_->positions.end(), points, points + count);
  if (settings_.auto_normals) scene_->normals.insert(scene_->normals.end(), count, facing);
  else scene_->normals.insert(scene_->normals.end(), polygon_ups_.begin() + static_cast<std::ptrdiff_t>(first),
                              polygon_ups_.end());
  if (cpfg_ && state_.texture >= 0) texture_polygon(base, count, first_frame);
  begin_group();
  scene_->indices.insert(scene_->indices.end(), triangles_.begin(), triangles_.end());
  end_group(TriangleGroup::Kind::Polygon);
}

// A convex shape in the HL plane, corners counter-clockwise around U.
void TurtleInterpreter::Impl::flat_shape(TriangleGroup::Kind kind, const Vec3* corners, int count) {
  if (trace_) note_position(" at ", state_.position);
  if (!scene_) return;
  const auto base = static_cast<std::uint32_t>(scene_->positions.size());
  scene_->normals.resize(scene_->positions.size(), Vec3{0, 0, 1});
  for (int k = 0; k < count; ++k) {
    scene_->positions.push_back(corners[k]);
    scene_->normals.push_back(state_.frame.up);
  }
  begin_group();
  for (int k = 1; k + 1 < count; ++k)
    scene_->indices.insert(scene_->indices.end(),
                           {base, base + static_cast<std::uint32_t>(k), base + static_cast<std::uint32_t>(k + 1)});
  end_group(kind);
}

// ---- surfaces and meshes -------------------------------------------------------------

// Local coordinates (whose own heading and up are `local_heading`,
// `local_up`) at the turtle: `contact` goes to the turtle's position, the
// local heading to H and the local up to U; `scale` scales the local x, y, z.
geometry::Placement TurtleInterpreter::Impl::placement(Vec3 local_heading, Vec3 local_up, Vec3 contact,
                                                       Vec3 scale) const {
  Vec3 h = normalized(local_heading);
  Vec3 l = cross(local_up, h);
  if (length(h) < kEpsilon || length(l) < kEpsilon) {
    h = {0, 1, 0};
    l = {-1, 0, 0};
  }
  l = normalized(l);
  const Vec3 u = cross(h, l);
  const Frame& f = state_.frame;
  // Where each local axis points in the world: its components along the
  // local heading, left and up become the turtle's.
  auto image = [&](float along_h, float along_l, float along_u) {
    return f.heading * along_h + f.left * along_l + f.up * along_u;
  };
  geometry::Placement p = geometry::Placement::from_frame(Vec3{}, image(h.x, l.x, u.x), image(h.y, l.y, u.y),
                                                          image(h.z, l.z, u.z), scale);
  p.origin = state_.position - (p.point(contact) - p.origin);
  return p;
}

void TurtleInterpreter::Impl::require_view_file_id(const char* module, const char* kind, const char* kinds, int id,
                                                   std::size_t count) const {
  if (id >= 0 && static_cast<std::size_t>(id) < count) return;
  throw ModelError(std::string(module) + "(" + std::to_string(id) + ", ...)" + where() + ": there is no " + kind + " " +
                   std::to_string(id) +
                   (count ? " (the view file gives " + std::string(kinds) + " 0 to " + std::to_string(count - 1) + ")"
                          : " (no view file gives " + std::string(kinds) + ")"));
}

void TurtleInterpreter::Impl::surface(int id, Vec3 scale, const char* module) {
  require_view_file_id(module, "surface", "surfaces", id, settings_.surfaces ? settings_.surfaces->size() : 0);
  const geometry::BezierSurface& s = (*settings_.surfaces)[static_cast<std::size_t>(id)];
  if (trace_) *trace_ += " \"" + s.name + "\"";
  note_position(" at ", state_.position);
  if (!scene_) return;
  const float size = s.size != 0 ? s.size : 1.0f;
  const geometry::Placement place = placement(s.heading, s.up, s.contact, scale / size);
  const int nu = state_.u_precision > 0 ? state_.u_precision : s.u_divisions;
  const int nv = state_.v_precision > 0 ? state_.v_precision : s.v_divisions;
  // lpfg: the turtle's texture, when on, wins over the view file's for the
  // surface; cpfg: the view file's wins over @Tx.
  const int texture = cpfg_ ? (s.texture >= 0 ? s.texture : state_.texture)
                            : (state_.texture >= 0 ? state_.texture : s.texture);
  begin_group();
  for (const geometry::BezierPatch& patch : s.patches)
    geometry::append_patch(*scene_, patch, place, nu, nv, texture >= 0);
  group_texture_ = texture;
  end_group(TriangleGroup::Kind::Surface);
}

void TurtleInterpreter::Impl::mesh(int id, Vec3 scale, const char* module) {
  require_view_file_id(module, "mesh", "meshes", id, settings_.meshes ? settings_.meshes->size() : 0);
  const geometry::PredefinedMesh& m = (*settings_.meshes)[static_cast<std::size_t>(id)];
  if (trace_) *trace_ += " \"" + m.name + "\"";
  note_position(" at ", state_.position);
  if (!scene_) return;
  // Mesh coordinates as the turtle's initial frame sees the world: y along H, z along U.
  const geometry::Placement place = placement({0, 1, 0}, {0, 0, 1}, m.contact, scale * m.scale);
  const auto base = static_cast<std::uint32_t>(scene_->positions.size());
  scene_->normals.resize(scene_->positions.size(), Vec3{0, 0, 1});
  const bool has_normals = m.normals.size() == m.positions.size();
  for (std::size_t k = 0; k < m.positions.size(); ++k) {
    scene_->positions.push_back(place.point(m.positions[k]));
    scene_->normals.push_back(has_normals ? place.normal(m.normals[k]) : Vec3{0, 0, 1});
  }
  const bool mirrored = dot(cross(place.x, place.y), place.z) < 0;
  begin_group();
  for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3) {
    const std::uint32_t a = base + m.indices[k], b = base + m.indices[k + 1], c = base + m.indices[k + 2];
    if (mirrored) scene_->indices.insert(scene_->indices.end(), {a, c, b});
    else scene_->indices.insert(scene_->indices.end(), {a, b, c});
  }
  if (!has_normals)
    geometry::set_normals_from_faces(*scene_, base, static_cast<std::uint32_t>(m.positions.size()),
                                     static_cast<std::uint32_t>(group_first_index_),
                                     static_cast<std::uint32_t>(scene_->indices.size() - group_first_index_));
  end_group(TriangleGroup::Kind::Mesh);
}

void TurtleInterpreter::Impl::dynamic_surface(const unsigned char* params) {
  note_position(" at ", state_.position);
  if (!scene_) return;
  geometry::BezierPatch patch;
  for (std::size_t k = 0; k < 16; ++k) {
    float xyz[3];
    std::memcpy(xyz, params + 12 * k, sizeof xyz);
    patch.points[k] = {xyz[0], xyz[1], xyz[2]};
  }
  // Like a surface whose frame is the turtle's initial one, at unit size.
  const geometry::Placement place = placement({0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {1, 1, 1});
  const geometry::BezierSurface defaults;
  begin_group();
  geometry::append_patch(*scene_, patch, place, state_.u_precision > 0 ? state_.u_precision : defaults.u_divisions,
                         state_.v_precision > 0 ? state_.v_precision : defaults.v_divisions);
  end_group(TriangleGroup::Kind::Surface);
}

void TurtleInterpreter::Impl::surface_point(int row, int column) {
  if (row < 0 || row > 3 || column < 0 || column > 3)
    throw ModelError("SurfacePoint(id, " + std::to_string(row) + ", " + std::to_string(column) +
                     ")" + where() + ": the control point's row and column go from 0 to 3");
  lsystem_surface_.points[static_cast<std::size_t>(4 * row + column)] = state_.position;
  note_position(" = ", state_.position);
}

void TurtleInterpreter::Impl::draw_lsystem_surface() {
  if (!scene_) return;
  const geometry::BezierSurface defaults;
  begin_group();
  // Its control points are turtle positions: already in the world.
  geometry::append_patch(*scene_, lsystem_surface_, geometry::Placement{},
                         state_.u_precision > 0 ? state_.u_precision : defaults.u_divisions,
                         state_.v_precision > 0 ? state_.v_precision : defaults.v_divisions);
  end_group(TriangleGroup::Kind::Surface);
}

void TurtleInterpreter::Impl::label(const unsigned char* params) {
  const char* text = nullptr;
  std::memcpy(&text, params, sizeof text);
  add_label(text ? text : "");
}

void TurtleInterpreter::Impl::add_label(std::string text) {
  note_position(" at ", state_.position);
  if (!scene_) return;
  geometry::Label l;
  l.position = state_.position;
  l.text = std::move(text);
  l.color = state_.color;
  l.from = from_;
  scene_->labels.push_back(std::move(l));
}

}  // namespace sylva::turtle
