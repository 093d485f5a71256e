#include "turtle/lpfg_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "sylva/predefined_ids.h"
#include "turtle/command_runner.h"
#include "turtle/trace.h"

namespace sylva::turtle {
namespace {

template <class T>
T read(const unsigned char* p, std::size_t offset = 0) {
  T v;
  std::memcpy(&v, p + offset, sizeof v);
  return v;
}

float f32(const unsigned char* p, std::size_t offset = 0) { return read<float>(p, offset); }
int i32(const unsigned char* p, std::size_t offset = 0) { return read<int>(p, offset); }
Vec3 v3f(const unsigned char* p, std::size_t offset = 0) {
  return {f32(p, offset), f32(p, offset + 4), f32(p, offset + 8)};
}
Vec3 v3d(const unsigned char* p, std::size_t offset = 0) {
  return {static_cast<float>(read<double>(p, offset)), static_cast<float>(read<double>(p, offset + 8)),
          static_cast<float>(read<double>(p, offset + 16))};
}
Vec3 v2f(const unsigned char* p, std::size_t offset = 0) { return {f32(p, offset), f32(p, offset + 4), 0}; }
Vec3 v2d(const unsigned char* p, std::size_t offset = 0) {
  return {static_cast<float>(read<double>(p, offset)), static_cast<float>(read<double>(p, offset + 8)), 0};
}
int precision(const unsigned char* p) { return std::max(0, static_cast<int>(std::lround(f32(p)))); }

}  // namespace

TurtleState LpfgDecoder::initial_state(const TurtleSettings& settings) {
  TurtleState s;
  s.width = settings.initial_width;
  s.color = settings.initial_color;
  return s;
}

void LpfgDecoder::append_text(std::string& out, ModuleId id, const unsigned char* params) {
  append_module(out, id, params);
}

template <class Emit>
bool LpfgDecoder::decode(ModuleId id, const unsigned char* p, Emit& emit) const {
  namespace m = rt::mid;
  using namespace command;
  using C = Coordinates;
  if (id >= m::PredefinedCount) return false;
  // lpfg's "corrected rotation": Up turns H toward U, Down toward -U, RollL
  // turns U toward L, RollR toward -L. lpfg's old rotations went the other way.
  const float corrected = settings_.corrected_rotation ? -1.0f : 1.0f;
  auto turn = [&](Axis axis, float degrees) { emit(Turn{axis, degrees}); };
  switch (id) {
    case m::SB: emit(Push{}); break;
    case m::EB: emit(Pop{}); break;
    case m::Cut: emit(Note{" (the derivation's; nothing to draw)"}); break;

    case m::F: emit(Forward{f32(p), true, true}); break;
    case m::f: emit(Forward{f32(p), false, true}); break;
    case m::G: emit(Forward{f32(p), true, false}); break;
    case m::g: emit(Forward{f32(p), false, false}); break;
    case m::MoveTo: case m::MoveTo3f: emit(MoveTo{v3f(p), C::Local}); break;
    case m::MoveTo3d: emit(MoveTo{v3d(p), C::Local}); break;
    case m::MoveTo2f: emit(MoveTo{v2f(p), C::Local}); break;
    case m::MoveTo2d: emit(MoveTo{v2d(p), C::Local}); break;
    case m::MoveRel3f: emit(MoveTo{v3f(p), C::LocalOffset}); break;
    case m::MoveRel3d: emit(MoveTo{v3d(p), C::LocalOffset}); break;
    case m::MoveRel2f: emit(MoveTo{v2f(p), C::LocalOffset}); break;
    case m::MoveRel2d: emit(MoveTo{v2d(p), C::LocalOffset}); break;
    case m::LineTo: case m::LineTo3f: emit(LineTo{v3f(p), C::Local}); break;
    case m::LineTo3d: emit(LineTo{v3d(p), C::Local}); break;
    case m::LineTo2f: emit(LineTo{v2f(p), C::Local}); break;
    case m::LineTo2d: emit(LineTo{v2d(p), C::Local}); break;
    case m::LineRel3f: emit(LineTo{v3f(p), C::LocalOffset}); break;
    case m::LineRel3d: emit(LineTo{v3d(p), C::LocalOffset}); break;
    case m::LineRel2f: emit(LineTo{v2f(p), C::LocalOffset}); break;
    case m::LineRel2d: emit(LineTo{v2d(p), C::LocalOffset}); break;
    case m::Line3f: emit(Line{v3f(p), v3f(p, 12)}); break;
    case m::Line3d: emit(Line{v3d(p), v3d(p, 24)}); break;
    case m::Line2f: emit(Line{v2f(p), v2f(p, 8)}); break;
    case m::Line2d: emit(Line{v2d(p), v2d(p, 16)}); break;
    case m::SetCoordinateSystem: emit(SetCoordinateSystem{f32(p)}); break;

    case m::Left: turn(Axis::Up, f32(p)); break;
    case m::Right: turn(Axis::Up, -f32(p)); break;
    case m::Up: turn(Axis::Left, corrected * f32(p)); break;
    case m::Down: turn(Axis::Left, -corrected * f32(p)); break;
    case m::RollL: turn(Axis::Heading, corrected * f32(p)); break;
    case m::RollR: turn(Axis::Heading, -corrected * f32(p)); break;
    case m::TurnAround: emit(TurnAround{}); break;
    case m::RollToVert: emit(RollToVertical{}); break;
    case m::RotateXYZ: emit(Rotate{v3f(p), f32(p, 12), false}); break;
    case m::RotateHLU: emit(Rotate{v3f(p), f32(p, 12), true}); break;
    case m::SetHead: emit(SetHeadUp{v3f(p), v3f(p, 12)}); break;
    case m::SetHead3f: emit(SetHeading{v3f(p)}); break;

    case m::IncColor: emit(StepColor{1, ColorWrap::Lpfg}); break;
    case m::DecColor: emit(StepColor{-1, ColorWrap::Lpfg}); break;
    case m::SetColor: {
      const int n = i32(p);
      if (n >= 1 && n <= 255) emit(SetColor{n});
      else emit(Note{" ignored: outside 1..255"});
      break;
    }
    case m::SetWidth: {
      const float w = f32(p);
      if (w > 0) emit(SetWidth{w});
      else emit(Note{" ignored: not positive"});
      break;
    }

    case m::Circle0: emit(Circle{std::nullopt, false, false}); break;
    case m::CircleFront0: emit(Circle{std::nullopt, false, true}); break;
    case m::Circle: emit(Circle{f32(p), false, false}); break;
    case m::CircleFront: emit(Circle{f32(p), false, true}); break;
    case m::CircleB: emit(Circle{f32(p), true, false}); break;
    case m::CircleFrontB: emit(Circle{f32(p), true, true}); break;
    case m::Sphere0: emit(Sphere{}); break;
    case m::Sphere: emit(Sphere{f32(p)}); break;

    case m::SP: emit(StartPolygon{}); break;
    case m::EP: emit(end_polygon()); break;
    case m::PP: emit(PolygonVertex{}); break;
    case m::Rhombus: emit(Rhombus{f32(p), f32(p, 4)}); break;
    case m::Triangle: emit(Triangle{f32(p), f32(p, 4)}); break;

    case m::Surface: {
      const float s = f32(p, 4);
      emit(Surface{i32(p), {s, s, s}, "Surface"});
      break;
    }
    case m::Surface3: emit(Surface{i32(p), v3f(p, 4), "Surface3"}); break;
    case m::Mesh: {
      const float s = f32(p, 4);
      emit(Mesh{i32(p), {s, s, s}, "Mesh"});
      break;
    }
    case m::Mesh3: emit(Mesh{i32(p), v3f(p, 4), "Mesh3"}); break;
    case m::SetUPrecision: emit(SurfacePrecision{false, precision(p)}); break;
    case m::SetVPrecision: emit(SurfacePrecision{true, precision(p)}); break;
    case m::InitSurface: emit(StartLsystemSurface{}); break;
    case m::SurfacePoint: emit(LsystemSurfacePoint{i32(p, 4), i32(p, 8)}); break;
    case m::DrawSurface: emit(DrawLsystemSurface{}); break;
    case m::DSurface: emit(BezierPatch{p}); break;

    case m::StartGC: emit(StartCylinder{}); break;
    case m::PointGC: emit(CylinderPoint{}); break;
    case m::EndGC: emit(EndCylinder{}); break;
    case m::CurrentContour: emit(SetContour{i32(p), i32(p), 0, "CurrentContour"}); break;
    case m::BlendedContour: emit(SetContour{i32(p), i32(p, 4), f32(p, 8), "BlendedContour"}); break;
    case m::ScaleContour: emit(ScaleContour{f32(p), f32(p, 4)}); break;
    case m::ContourSides: emit(ContourSides{std::max(3, i32(p))}); break;

    case m::CurrentTexture: emit(SetTexture{i32(p)}); break;
    case m::TextureVCoeff: emit(TextureVCoeff{f32(p)}); break;
    case m::Label: {
      const char* text = read<const char*>(p);
      emit(Label{text ? text : ""});
      break;
    }

    case m::SetElasticity: emit(SetElasticity{i32(p), f32(p, 4), false}); break;
    case m::IncElasticity:
    case m::DecElasticity: {
      // By the tropism's step (the view file's S:).
      const int t = i32(p);
      const bool known = t >= 1 && static_cast<std::size_t>(t) <= settings_.tropisms.size();
      const float step = known ? settings_.tropisms[static_cast<std::size_t>(t) - 1].step : 0.0f;
      emit(SetElasticity{t, id == m::IncElasticity ? step : -step, true});
      break;
    }
    case m::Elasticity: emit(SimpleElasticity{f32(p)}); break;

    case m::GetPos: emit(Query{Quantity::Position}); break;
    case m::GetHead: emit(Query{Quantity::Heading}); break;
    case m::GetLeft: emit(Query{Quantity::Left}); break;
    case m::GetUp: emit(Query{Quantity::Up}); break;

    case m::E1:
    case m::E2:
    case m::EA20: emit(Note{" (no environment: unchanged)"}); break;
    case m::Camera: emit(Camera{}); break;
    // Predefined modules the turtle does not act on: a line in the trace, no more.
    default: emit(Note{}); break;
  }
  return true;
}

template bool LpfgDecoder::decode(ModuleId, const unsigned char*, CommandRunner&) const;
template bool LpfgDecoder::decode(ModuleId, const unsigned char*, CommandRecorder&) const;

}  // namespace sylva::turtle
