// The dispatcher's drawing commands: shapes (shape_drawer.h), polygons
// (polygon_builder.h), generalized cylinders (cylinder_builder.h) and the
// settings they draw with.
#include <algorithm>
#include <string>

#include "turtle/dispatcher.h"

namespace sylva::turtle {

using namespace command;
using geometry::TriangleGroup;

namespace {

CommandResult drew(int triangles) {
  CommandResult r;
  r.triangles = triangles;
  return r;
}

CommandResult closed(CylinderBuilder::Closed c) {
  CommandResult r;
  r.closed_rings = c.rings;
  r.closed_sides = c.sides;
  return r;
}

constexpr const char* kNoCylinder = " ignored: no generalized cylinder";

}  // namespace

// ---- shapes -----------------------------------------------------------------------

float CommandDispatcher::radius(const TurtleState& turtle, const std::optional<float>& radius) {
  return (radius ? *radius : turtle.width / 2) * turtle.scale;
}

void CommandDispatcher::run(const Circle& c) {
  shapes_.circle(state_, from_, radius(state_, c.radius), c.outlined ? state_.width : 0, c.facing_viewer);
}

void CommandDispatcher::run(const Sphere& c) { shapes_.sphere(state_, from_, radius(state_, c.radius)); }

CommandResult CommandDispatcher::run(const Rhombus& c) {
  const Frame& f = state_.frame;
  const Vec3 o = state_.position, h = f.heading * c.length, l = f.left * (c.width / 2);
  const Vec3 corners[4] = {o, o + h * 0.5f - l, o + h, o + h * 0.5f + l};
  return drew(shapes_.flat_shape(state_, from_, TriangleGroup::Kind::Rhombus, corners, 4));
}

CommandResult CommandDispatcher::run(const Triangle& c) {
  const Frame& f = state_.frame;
  const Vec3 o = state_.position, l = f.left * (c.width / 2);
  const Vec3 corners[3] = {o + l, o - l, o + f.heading * c.height};
  return drew(shapes_.flat_shape(state_, from_, TriangleGroup::Kind::Triangle, corners, 3));
}

CommandResult CommandDispatcher::run(const Surface& c) {
  CommandResult r;
  r.triangles = shapes_.surface(state_, from_, c.id, c.scale * state_.scale, c.module, c.view_texture_first, r.name);
  return r;
}

CommandResult CommandDispatcher::run(const Mesh& c) {
  CommandResult r;
  r.triangles = shapes_.mesh(state_, from_, c.id, c.scale, c.module, r.name);
  return r;
}

void CommandDispatcher::run(const SurfacePrecision& c) {
  (c.along_v ? state_.v_precision : state_.u_precision) = c.divisions;
}

void CommandDispatcher::run(const StartLsystemSurface&) {
  shapes_.start_lsystem_surface();
}

void CommandDispatcher::run(const LsystemSurfacePoint& c) {
  shapes_.lsystem_surface_point(state_, from_, c.row, c.column);
}

CommandResult CommandDispatcher::run(const DrawLsystemSurface&) {
  return drew(shapes_.draw_lsystem_surface(state_, from_));
}

CommandResult CommandDispatcher::run(const BezierPatch& c) { return drew(shapes_.bezier_patch(state_, from_, c.points)); }

void CommandDispatcher::run(const Label& c) {
  shapes_.label(state_, from_, std::string(c.text));
}

void CommandDispatcher::run(const Camera&) {
  if (scene_) scene_->camera = geometry::CameraPose{state_.position, state_.frame.heading, state_.frame.up, from_};
}

// ---- polygons ---------------------------------------------------------------------

CommandResult CommandDispatcher::run(const StartPolygon&) {
  CommandResult r;
  r.polygon = polygons_.start(from_);
  return r;
}

CommandResult CommandDispatcher::run(const PolygonVertex&) {
  if (!polygons_.any_open()) return noted(" ignored: no polygon");
  CommandResult r;
  r.polygon = polygons_.add_vertex(state_.position, state_.frame);
  return r;
}

CommandResult CommandDispatcher::run(const EndPolygon& c) {
  if (!polygons_.any_open()) return noted(" ignored: no polygon");
  PolygonBuilder::Look look;
  look.auto_normals = settings_.auto_normals;
  look.texture = c.textured && state_.texture >= 0 ? state_.texture : -1;
  look.color = state_.color;
  look.back_color = state_.back_color;
  const PolygonBuilder::Ended ended = polygons_.end(scene_, look);
  CommandResult r;
  r.polygon = ended.vertices;
  r.triangles = ended.triangles;
  return r;
}

// ---- generalized cylinders ------------------------------------------------------------

CommandResult CommandDispatcher::run(const StartCylinder& c) {
  return closed(cylinders_.start(state_, stack_.empty() ? nullptr : &stack_.back(), c.type, from_));
}

CommandResult CommandDispatcher::run(const CylinderPoint& c) {
  CommandResult r;
  r.cylinder_point = cylinders_.add_point(state_, from_, c.strips);
  if (r.cylinder_point == 0) r.note = kNoCylinder;
  return r;
}

CommandResult CommandDispatcher::run(const CylinderDot& c) {
  const CylinderBuilder::Dot dot = cylinders_.dot(state_, from_, c.strips);
  CommandResult r;
  r.cylinder_point = dot.point;
  r.strips_only = dot.strips_only;
  if (dot.point == 0) r.note = kNoCylinder;
  return r;
}

CommandResult CommandDispatcher::run(const EndCylinder& c) {
  if (!cylinders_.open(state_)) return noted(kNoCylinder);
  const CylinderBuilder::Ended ended = cylinders_.end(state_, from_, c.strips, c.type);
  CommandResult r = closed(ended.closed);
  r.opened_type = ended.opened_type;
  return r;
}

CommandResult CommandDispatcher::run(const CloseCylinder& c) { return closed(cylinders_.close(c.slot)); }

void CommandDispatcher::run(const SetContour& c) {
  cylinders_.check_contour(c.contour, c.module, from_);
  cylinders_.check_contour(c.blend_contour, c.module, from_);
  state_.contour = c.contour;
  state_.blend_contour = c.blend_contour;
  state_.blend = c.blend;
}

void CommandDispatcher::run(const ScaleContour& c) {
  state_.contour_scale_left = c.left;
  state_.contour_scale_up = c.up;
}

CommandResult CommandDispatcher::run(const ContourSides& c) {
  if (cylinders_.open(state_)) return noted(" ignored: inside a generalized cylinder");
  state_.contour_sides = c.sides;
  return {};
}

void CommandDispatcher::run(const CylinderTangents& c) {
  state_.cylinder_tangent_start = c.start;
  state_.cylinder_tangent_end = c.end;
}

void CommandDispatcher::run(const RadiusTangents& c) {
  geometry::RadiusTangents& t = state_.radius_tangents;
  t.given = true;
  t.angle1 = c.angle1;
  t.length1 = c.length1;
  t.angle2 = c.angle2;
  t.length2 = c.length2;
}

void CommandDispatcher::run(const RadiusAdjust& c) {
  state_.radius_tangents.adjust = c.adjust;
}

// ---- textures ---------------------------------------------------------------------

void CommandDispatcher::run(const SetTexture& c) {
  state_.texture = c.texture;
}

void CommandDispatcher::run(const TextureVCoeff& c) {
  state_.texture_v = c.v;
}

}  // namespace sylva::turtle
