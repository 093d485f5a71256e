// The turtle's commands: what both languages' modules decode into (L+C's
// predefined modules in lpfg_decoder, cpfg's symbols in cpfg_decoder) and
// what the dispatcher executes. A command says what to do in the turtle's
// own terms; where L+C and cpfg mean different things by the same kind of
// module, the decoder has already settled it, or an argument here says so.
//
// Decoding and executing go module by module, each command passed with its
// own type from the decoder to the dispatcher (command_runner.h): the stream
// is never stored. TurtleCommand, any one command, is for looking at them.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

#include "geometry/vec3.h"

namespace sylva::turtle {

using geometry::Vec3;

namespace command {

// Does nothing but tell the trace `text` (why a module was ignored, or that
// it is not the turtle's to act on). `shows_frame`: the module was a
// rotation, whose trace line ends with the frame as for the others.
struct Note {
  const char* text = "";
  bool shows_frame = false;
};

// ---- the stack ------------------------------------------------------------------
struct Push {};
struct Pop {};

// ---- moves and lines ------------------------------------------------------------
// F f G g: `distance` times the turtle's scale (cpfg's @D; always 1 in L+C).
// `draw`: a line (F G); `records_vertex`: the new position is a vertex of
// the open polygon and a control point of a cpfg {(type) cylinder (F f).
struct Forward {
  float distance = 0;
  bool draw = true;
  bool records_vertex = true;
};
// Where the coordinates of a MoveTo, LineTo or Line are.
enum class Coordinates : std::uint8_t {
  Local,        // SetCoordinateSystem's (the world until it is set)
  LocalOffset,  // from the turtle, along SetCoordinateSystem's axes
  World,        // cpfg's @M: the world's, with coordinates not given kept
};
struct MoveTo {
  Vec3 point;
  Coordinates coordinates = Coordinates::Local;
  int given = 3;  // World: how many of x, y, z are given
};
// A line from the turtle to `point`, which the turtle moves to.
struct LineTo {
  Vec3 point;
  Coordinates coordinates = Coordinates::Local;
};
// A line between two points (Local), the turtle ending at `to`.
struct Line {
  Vec3 from, to;
};
// Local coordinates from here on: x along the turtle's right, y along its
// heading, z along its up, all times `scale`, from its position.
struct SetCoordinateSystem {
  float scale = 1;
};

// ---- rotations ------------------------------------------------------------------
enum class Axis : std::uint8_t { Up, Left, Heading };
// Right-handed around the axis: positive turns H toward L (Up), H toward
// -U (Left), U toward -L (Heading).
struct Turn {
  Axis axis = Axis::Up;
  float degrees = 0;
};
struct TurnAround {};
struct RollToVertical {};
// Around `axis`, in world coordinates or (turtle_axes) in H, L, U.
struct Rotate {
  Vec3 axis;
  float degrees = 0;
  bool turtle_axes = false;
};
struct SetHeadUp {
  Vec3 heading, up;
};
// The smallest rotation taking H to `heading`.
struct SetHeading {
  Vec3 heading;
};
// cpfg's @Tp: up and left carried from the last step's heading to the
// current one without twist; @Tf: the twist so far is wanted.
struct MinimizeTwist {};
struct ForceTwist {};

// ---- widths and colours -----------------------------------------------------------
struct SetWidth {
  float width = 1;
};
// The width plus `by`, never below 0 (cpfg's # and ! without a parameter).
struct StepWidth {
  float by = 0;
};
// How a stepped colour index comes back into the colour map.
enum class ColorWrap : std::uint8_t {
  Lpfg,      // IncColor, DecColor: one step round 1..255
  CpfgUp,    // cpfg's ; and @; (cpfg_color)
  CpfgDown,  // cpfg's , and @,
};
// cpfg's ; and , (cpfg/interpret.c): the colour is wrapped once, upward past
// 255 by ; and downward below 0 by , so ;(600) names entry 88 of colormap 2
// (-m2) while ;(300) is entry 44 of colormap 1. Colormap 0 (a colour below 0
// after ;) is not kept: such colours wrap into colormap 1.
inline int cpfg_color(int c, bool up) {
  if (up && c > 255) c -= 256;
  if (!up && c < 0) c += 256;
  return c < 0 ? ((c % 256) + 256) % 256 : c;
}
// `back_side`: the colour of the back of surfaces, polygons and cylinders
// (cpfg's @; @,), stepped from the front's until set. SetColor's index is
// the colour as it stands: the decoders have checked or wrapped it.
struct SetColor {
  int index = 1;
  bool back_side = false;
};
struct StepColor {
  int by = 1;
  ColorWrap wrap = ColorWrap::Lpfg;
  bool back_side = false;
};

// ---- the turtle's scale (cpfg's @D @Di @Dd, sub-L-systems ?(label,s) ... $) ----
struct SetScale {
  float scale = 1;
};
struct MultiplyScale {
  float by = 1;
};
struct DivideScale {
  float by = 1;
};
// The scale multiplied by `scale` until the matching return.
struct CallSubLsystem {
  float scale = 1;
};
struct ReturnFromSubLsystem {};

// ---- shapes -------------------------------------------------------------------------
// `radius` times the turtle's scale; none: half the width. `outlined`: a
// ring of the turtle's width; `facing_viewer`: in the screen's plane, not HL.
struct Circle {
  std::optional<float> radius;
  bool outlined = false;
  bool facing_viewer = false;
};
struct Sphere {
  std::optional<float> radius;
};
// The turtle at the bottom corner; `length` along H, `width` along L.
struct Rhombus {
  float length = 0, width = 0;
};
// The turtle at the middle of the base; the apex `height` along H.
struct Triangle {
  float width = 0, height = 0;
};
// The view file's surface or mesh `id` (from 0), `scale` times the turtle's
// scale; `module` names it in errors. `view_texture_first`: the surface's
// own texture wins over the turtle's (cpfg), rather than the other way (lpfg).
struct Surface {
  int id = 0;
  Vec3 scale{1, 1, 1};
  const char* module = "Surface";
  bool view_texture_first = false;
};
struct Mesh {
  int id = 0;
  Vec3 scale{1, 1, 1};
  const char* module = "Mesh";
};
// The divisions of surfaces drawn from here on (0: each surface's own).
struct SurfacePrecision {
  bool along_v = false;
  int divisions = 0;
};
// The one Bézier patch whose control points are turtle positions.
struct StartLsystemSurface {};
struct LsystemSurfacePoint {
  int row = 0, column = 0;
};
struct DrawLsystemSurface {};
// DSurface: a patch of 16 control points (12 bytes each, in the module's
// parameters) in the turtle's frame.
struct BezierPatch {
  const unsigned char* points = nullptr;
};
// `shown`: the text is not the module's own (cpfg's formatted @L), so the trace shows it.
struct Label {
  std::string_view text;
  bool shown = false;
};
struct Camera {};

// ---- polygons -----------------------------------------------------------------------
struct StartPolygon {};
struct PolygonVertex {};
// `textured`: the turtle's texture stretched over the polygon (cpfg's @Tx).
struct EndPolygon {
  bool textured = false;
};

// ---- generalized cylinders (cylinder_builder.h) ------------------------------------
// `type` 0: StartGC or @Gs, whose start is the first control point; 1..4:
// cpfg's {(type). `unknown_type`: the module asked for another type, and 1 is used.
struct StartCylinder {
  int type = 0;
  bool unknown_type = false;
};
// `strips`: the bands from the previous control point (cpfg's @Gc(strips)).
struct CylinderPoint {
  int strips = 1;
};
// cpfg's .(strips) in a cylinder: a control point, or the strips of the
// last one where the turtle has not moved since.
struct CylinderDot {
  int strips = 1;
};
// `type`: }(type)'s, checked against {(type)'s; 0 for EndGC and @Ge.
struct EndCylinder {
  int strips = 1;
  int type = 0;
};
// At the end of the string: cylinder slot `slot`, left open.
struct CloseCylinder {
  int slot = 0;
};
struct SetContour {
  int contour = 0, blend_contour = 0;
  float blend = 0;
  const char* module = "CurrentContour";
};
struct ScaleContour {
  float left = 1, up = 1;
};
struct ContourSides {
  int sides = 8;
};
// cpfg's @Gt: the Hermite tangent coefficients of the next stretches.
struct CylinderTangents {
  float start = 1.2f, end = 1.2f;
};
// cpfg's @Gr(angle1,length1,angle2,length2) and @Gr(flag).
struct RadiusTangents {
  float angle1 = 0, length1 = 0, angle2 = 0, length2 = 0;
};
struct RadiusAdjust {
  bool adjust = false;
};

// ---- textures -----------------------------------------------------------------------
struct SetTexture {
  int texture = -1;  // the view file's, from 0; -1: none
};
struct TextureVCoeff {
  float v = 1;
};

// ---- tropisms -----------------------------------------------------------------------
// The elasticity of the view file's tropism `tropism` (from 1): `value`, or
// (relative) plus `value`.
struct SetElasticity {
  int tropism = 1;
  float value = 0;
  bool relative = false;
};
// The simple tropism's ("stropism") elasticity.
struct SimpleElasticity {
  float value = 0;
};

// ---- query modules --------------------------------------------------------------------
enum class Quantity : std::uint8_t { Position, Heading, Left, Up, CpfgUp /* cpfg's U: -up */ };
// The module receives the quantity's first `count` coordinates (at most 3).
struct Query {
  Quantity quantity = Quantity::Position;
  int count = 3;
};

}  // namespace command

using TurtleCommand = std::variant<
    command::Note, command::Push, command::Pop, command::Forward, command::MoveTo, command::LineTo, command::Line,
    command::SetCoordinateSystem, command::Turn, command::TurnAround, command::RollToVertical, command::Rotate,
    command::SetHeadUp, command::SetHeading, command::MinimizeTwist, command::ForceTwist, command::SetWidth,
    command::StepWidth, command::SetColor, command::StepColor, command::SetScale, command::MultiplyScale,
    command::DivideScale, command::CallSubLsystem, command::ReturnFromSubLsystem, command::Circle, command::Sphere,
    command::Rhombus, command::Triangle, command::Surface, command::Mesh, command::SurfacePrecision,
    command::StartLsystemSurface, command::LsystemSurfacePoint, command::DrawLsystemSurface, command::BezierPatch,
    command::Label, command::Camera, command::StartPolygon, command::PolygonVertex, command::EndPolygon,
    command::StartCylinder, command::CylinderPoint, command::CylinderDot, command::EndCylinder,
    command::CloseCylinder, command::SetContour, command::ScaleContour, command::ContourSides,
    command::CylinderTangents, command::RadiusTangents, command::RadiusAdjust, command::SetTexture,
    command::TextureVCoeff, command::SetElasticity, command::SimpleElasticity, command::Query>;

// Keeps the command a decoder sends it, to be looked at rather than executed.
struct CommandRecorder {
  template <class Command>
  void operator()(const Command& c) {
    command = c;
  }
  TurtleCommand command;
};

// What a command did that neither the command nor the turtle after it
// shows: what the trace tells besides them. Commands that always do just
// what they say report nothing (their dispatcher run returns void). Small,
// as it is made for every command that reports.
struct CommandResult {
  // Why the command was ignored (then nothing else here is set), or a
  // remark on a rotation.
  const char* note = nullptr;
  // A move's or a line's ends.
  Vec3 from, to;
  // A surface's or mesh's name.
  const char* name = "";
  // SetElasticity: the elasticity after the change.
  float elasticity = 0;
  // StartPolygon: the polygon's depth; PolygonVertex and Forward in a
  // polygon: the vertex's number; EndPolygon: the polygon's vertices. 0: none.
  int polygon = 0;
  // The cylinder control point added (CylinderPoint, CylinderDot, Forward in
  // a {(type) cylinder) or, `strips_only`, whose strips CylinderDot set. 0: none.
  int cylinder_point = 0;
  // The triangles drawn; -1: nothing was drawn (no Scene, or a polygon of
  // fewer than 3 vertices).
  int triangles = -1;
  // A cylinder this command ended: its rings and sides (-1: none ended).
  int closed_rings = -1, closed_sides = 0;
  // EndCylinder: the type of the {(type) it ended (0: @Gs or StartGC).
  int opened_type = 0;
  bool strips_only = false;
};

// A command that did nothing, or a rotation that left the frame unchanged,
// for the reason `note` gives.
inline CommandResult noted(const char* note) {
  CommandResult r;
  r.note = note;
  return r;
}

}  // namespace sylva::turtle
