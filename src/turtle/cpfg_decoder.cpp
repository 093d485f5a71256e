#include "turtle/cpfg_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "support/diagnostic.h"
#include "turtle/command_runner.h"
#include "turtle/model_error_text.h"
#include "turtle/trace.h"

namespace sylva::turtle {
namespace {

float param(const unsigned char* p, int k) {
  float v;
  std::memcpy(&v, p + 4 * k, sizeof v);
  return v;
}
int int_param(const unsigned char* p, int k) { return static_cast<int>(std::lround(param(p, k))); }
Vec3 vec_param(const unsigned char* p, int k) { return {param(p, k), param(p, k + 1), param(p, k + 2)}; }
// @L's text: the pointer before its floats.
const char* label_text(const unsigned char* p) {
  const char* text = nullptr;
  std::memcpy(&text, p, sizeof text);
  return text ? text : "";
}

}  // namespace

CpfgDecoder::CpfgDecoder(const TurtleSettings& settings, const ModuleTypes& types)
    : settings_(settings),
      types_(types),
      symbols_(settings.cpfg_symbols && settings.cpfg_symbols->size() == types.size()
                   ? settings.cpfg_symbols
                   : std::make_shared<const CpfgSymbols>(types)) {}

TurtleState CpfgDecoder::initial_state(const TurtleSettings& settings) {
  TurtleState s;
  s.width = settings.initial_width;
  s.color = settings.cpfg_initial_color;
  s.back_color = settings.cpfg_initial_back_color;
  s.scale = settings.initial_scale;
  return s;
}

void CpfgDecoder::append_text(std::string& out, ModuleId id, const unsigned char* params) const {
  append_cpfg_module(out, types_.name(id), params, symbols_->params(id), symbols_->op(id) == CpfgOp::Label);
}

CpfgOp CpfgDecoder::read_op(ModuleId id) {
  CpfgOp op = symbols_->op(id);
  // A command read a character a module: the characters so far and this one.
  // Where they make no command, cpfg reads this module on its own.
  if (!pending_.empty()) {
    const std::string joined = pending_ + types_.name(id);
    const CpfgOp whole = cpfg_op(joined);
    if (whole != CpfgOp::None && whole != CpfgOp::Label) {  // @L is never read split: its text is @L's own
      pending_.clear();
      return whole;
    }
    if (cpfg_command_prefix(joined)) {
      pending_ = joined;
      return CpfgOp::Prefix;
    }
    pending_.clear();
  }
  if (op == CpfgOp::Prefix) pending_ = types_.name(id);
  return op;
}

template <class Emit>
bool CpfgDecoder::decode(ModuleId id, const unsigned char* p, std::uint32_t source_index, Emit& emit) {
  using O = CpfgOp;
  using namespace command;
  const CpfgOp op = read_op(id);
  if (op == O::None || op == O::Prefix) return false;  // cpfg ignores symbols that are not the turtle's
  const int n = symbols_->params(id);
  // Computed only by the symbols that use them (this runs for every module).
  // A rotation symbol's angle: its parameter, or the view file's increment.
  auto angle = [&] { return n > 0 ? param(p, 0) : settings_.angle_increment; };
  // A step: its parameter or 1 (times the turtle's scale).
  auto step = [&] { return n > 0 ? param(p, 0) : 1.0f; };
  // A circle or sphere: the parameter is its diameter, the line width by default.
  auto radius = [&]() -> std::optional<float> {
    if (n > 0) return param(p, 0) / 2;
    return std::nullopt;
  };
  // A generalized cylinder's strips (@Gc, .(strips), @Ge): its parameter or 1.
  auto strips = [&] { return n > 0 ? static_cast<int>(std::lround(std::clamp(param(p, 0), 1.0f, 1000.0f))) : 1; };
  auto ignored = [&](const char* why) { emit(Note{why}); };
  switch (op) {
    case O::None:
    case O::Prefix: break;
    case O::Push: emit(Push{}); break;
    case O::Pop: emit(Pop{}); break;

    case O::Forward: emit(Forward{step(), true, true}); break;
    case O::Move: emit(Forward{step(), false, true}); break;
    case O::ForwardNoVertex: emit(Forward{step(), true, false}); break;
    case O::MoveNoVertex: emit(Forward{step(), false, false}); break;
    case O::MoveTo:
      emit(MoveTo{Vec3{n > 0 ? param(p, 0) : 0, n > 1 ? param(p, 1) : 0, n > 2 ? param(p, 2) : 0},
                       Coordinates::World, std::min(n, 3)});
      break;

    case O::Left: emit(Turn{Axis::Up, angle()}); break;
    case O::Right: emit(Turn{Axis::Up, -angle()}); break;
    case O::Down: emit(Turn{Axis::Left, angle()}); break;
    case O::Up: emit(Turn{Axis::Left, -angle()}); break;
    case O::RollLeft: emit(Turn{Axis::Heading, angle()}); break;
    case O::RollRight: emit(Turn{Axis::Heading, -angle()}); break;
    case O::TurnAround: emit(TurnAround{}); break;
    // The end of a sub-L-system: the caller's scale again. cpfg's $ does
    // nothing else (interpret.c): it never rolls the turtle.
    case O::SubLsystemReturn:
      if (n == 0) emit(ReturnFromSubLsystem{});
      else emit(Note{});
      break;
    case O::RollToVertical: emit(RollToVertical{}); break;
    case O::SetHeading:
      // The up vector given is cpfg's U, -frame.up.
      if (n >= 6) emit(SetHeadUp{vec_param(p, 0), -vec_param(p, 3)});
      else if (n >= 3) emit(SetHeading{vec_param(p, 0)});
      else emit(Note{" ignored: needs a heading", true});
      break;

    case O::WidthUp:
    case O::WidthDown:
      if (n > 0) emit(SetWidth{std::max(0.0f, param(p, 0))});
      else emit(StepWidth{op == O::WidthUp ? settings_.width_increment : -settings_.width_increment});
      break;
    case O::ColorUp:
    case O::ColorDown: {
      const bool up = op == O::ColorUp;
      if (n > 0) emit(SetColor{cpfg_color(int_param(p, 0), up)});
      else emit(StepColor{up ? settings_.color_increment : -settings_.color_increment,
                               up ? ColorWrap::CpfgUp : ColorWrap::CpfgDown});
      break;
    }

    // With a parameter (the curve type), { } and . are cpfg's generalized
    // cylinder (CPFG manual 6.7.3); without, its polygon (6.5).
    // {(type) defines no control point; one follows each F and f (4 strips)
    // and each .(strips) where the turtle has moved; }(type) adds the last
    // where it has moved.
    case O::PolygonOrCylinderStart:
      if (n > 0) {
        const int type = int_param(p, 0);
        if (type >= 1 && type <= 4) emit(StartCylinder{type});
        else emit(StartCylinder{1, true});
      } else {
        emit(StartPolygon{});
      }
      break;
    case O::PolygonOrCylinderEnd:
      if (n > 0) emit(EndCylinder{4, std::max(1, int_param(p, 0))});
      else emit(end_polygon());
      break;
    case O::VertexOrCylinderPoint:
      if (n > 0) emit(CylinderDot{strips()});
      else emit(PolygonVertex{});
      break;

    case O::CircleScreen: emit(Circle{radius(), false, true}); break;
    case O::CircleHL: emit(Circle{radius(), false, false}); break;
    case O::CircleScreenBoundary: emit(Circle{radius(), true, true}); break;
    case O::CircleHLBoundary: emit(Circle{radius(), true, false}); break;
    case O::Sphere: emit(Sphere{radius()}); break;

    case O::CylinderStart: emit(StartCylinder{}); break;
    // @Gc(strips), @Ge(strips): the bands since the previous control point.
    case O::CylinderPoint: emit(CylinderPoint{strips()}); break;
    case O::CylinderEnd: emit(EndCylinder{strips()}); break;
    // @Gt(start,end): the Hermite tangent coefficients of the stretches
    // ended by the next control points; one parameter sets both.
    case O::CylinderTangents:
      if (n == 0) ignored(" ignored: needs tangent coefficients");
      else emit(CylinderTangents{param(p, 0), n > 1 ? param(p, 1) : param(p, 0)});
      break;
    // @Gr(angle1,length1,angle2,length2): the radius's Hermite tangents
    // for the stretches ended by the next control points; @Gr(flag): the
    // adjustment to the stretch's length on or off.
    case O::CylinderRadiusTangents:
      if (n >= 4) emit(RadiusTangents{param(p, 0), param(p, 1), param(p, 2), param(p, 3)});
      else if (n >= 1) emit(RadiusAdjust{param(p, 0) != 0});
      else ignored(" ignored: needs tangents or a flag");
      break;
    case O::Contour: {
      const int c = n > 0 ? int_param(p, 0) : 0;
      emit(SetContour{c, c, 0, "@#"});
      break;
    }
    case O::ContourSides:
      if (n == 0) ignored(" ignored: needs a number of sides");
      else emit(ContourSides{std::max(3, int_param(p, 0))});
      break;

    case O::SetScale:
      if (n > 0) emit(SetScale{param(p, 0)});
      else ignored(" ignored: needs a scale");
      break;
    case O::ScaleUp:
      if (n > 0) emit(SetScale{param(p, 0)});
      else emit(MultiplyScale{settings_.scale_multiplier});
      break;
    case O::ScaleDown:
      if (n > 0) emit(SetScale{param(p, 0)});
      else if (settings_.scale_multiplier != 0) emit(DivideScale{settings_.scale_multiplier});
      else emit(Note{});
      break;

    // cpfg's textures count from 1 (0: none); the view file's from 0.
    case O::Texture: emit(SetTexture{n > 0 && int_param(p, 0) > 0 ? int_param(p, 0) - 1 : -1}); break;

    // @PS(id,type), @PC(id,r,c), @PD(id,s,t): the one L-system surface; the
    // id, the spline type and the mesh size are not kept.
    case O::SurfaceInit: emit(StartLsystemSurface{}); break;
    case O::SurfacePoint:
      if (n >= 3) emit(LsystemSurfacePoint{int_param(p, 1), int_param(p, 2)});
      else ignored(" ignored: needs id, row and column");
      break;
    case O::SurfaceDraw: emit(DrawLsystemSurface{}); break;

    case O::ElasticitySet:
      if (n >= 2) emit(SetElasticity{int_param(p, 0), param(p, 1), false});
      else ignored(" ignored: needs a tropism id and a value");
      break;
    case O::ElasticityUp:
    case O::ElasticityDown: {
      if (n == 0) {
        ignored(" ignored: needs a tropism id");
        break;
      }
      // By the second parameter, or the tropism's step (the view file's S:).
      const int t = int_param(p, 0);
      const bool known = t >= 1 && static_cast<std::size_t>(t) <= settings_.tropisms.size();
      const float v = n >= 2 ? param(p, 1) : known ? settings_.tropisms[static_cast<std::size_t>(t) - 1].step : 0.0f;
      emit(SetElasticity{t, op == O::ElasticityUp ? v : -v, true});
      break;
    }

    case O::QueryPosition: emit(Query{Quantity::Position, n}); break;
    case O::QueryHeading: emit(Query{Quantity::Heading, n}); break;
    case O::QueryLeft: emit(Query{Quantity::Left, n}); break;
    case O::QueryUp: emit(Query{Quantity::CpfgUp, n}); break;

    // ?(label,s): the sub-L-system's structure is scaled by s (CPFG manual
    // 7.2) until its $.
    case O::SubLsystemCall:
      if (n != 2) ignored(" ignored: needs a label and a scale");
      else emit(CallSubLsystem{param(p, 1)});
      break;

    // ~id, ~id(s), ~id(sx,sy,sz): the view file's surface `surface: id file.s scale`.
    case O::PredefinedSurface: {
      const std::string& name = types_.name(id);
      const std::string key = name.substr(1);
      const auto& ids = settings_.surface_ids;
      const auto found = std::find(ids.begin(), ids.end(), key);
      if (found == ids.end())
        throw ModelError(name + where({source_index, id}) + ": no surface has id '" + key +
                         "' (the view file's 'surface: " + key + " file.s scale' gives it)");
      Vec3 scale{1, 1, 1};
      if (n >= 3) scale = vec_param(p, 0);
      else if (n >= 1) scale = Vec3{param(p, 0), param(p, 0), param(p, 0)};
      emit(Surface{static_cast<int>(found - ids.begin()), scale, name.c_str(), true});
      break;
    }

    // @L("format", p1, ...): a label at the turtle's position (CPFG manual
    // 6.10), its floats after its string.
    case O::Label: {
      const unsigned char* values = p + sizeof(const char*);
      label_values_.resize(static_cast<std::size_t>(n));
      for (int k = 0; k < n; ++k) label_values_[static_cast<std::size_t>(k)] = param(values, k);
      label_ = format_cpfg_label(label_text(p), label_values_.data(), n);
      emit(Label{label_, true});
      break;
    }

    case O::MinimizeTwist: emit(MinimizeTwist{}); break;
    case O::ForceTwist: emit(ForceTwist{}); break;

    // @;(n) @,(n): the back side's colour index, stepped from the front's
    // until set. Outputs draw one side: the Scene keeps the front's colour.
    case O::BackColorUp:
    case O::BackColorDown: {
      const bool up = op == O::BackColorUp;
      if (n > 0) emit(SetColor{cpfg_color(int_param(p, 0), up), true});
      else emit(StepColor{up ? settings_.back_color_increment : -settings_.back_color_increment,
                               up ? ColorWrap::CpfgUp : ColorWrap::CpfgDown, true});
      break;
    }
  }
  return true;
}

template bool CpfgDecoder::decode(ModuleId, const unsigned char*, std::uint32_t, CommandRunner&);
template bool CpfgDecoder::decode(ModuleId, const unsigned char*, std::uint32_t, CommandRecorder&);

}  // namespace sylva::turtle
