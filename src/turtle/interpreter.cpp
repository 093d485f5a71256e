#include "turtle/interpreter.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "sylva/predefined_ids.h"
#include "turtle/interpreter_impl.h"
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

constexpr double kDegrees = 3.14159265358979323846 / 180.0;
// World up, for RollToVert: models grow up the screen, along +y.
constexpr Vec3 kVertical{0, 1, 0};

}  // namespace

TurtleInterpreter::Impl::Impl(const TurtleSettings& settings, const ModuleTypes& types, Scene* scene,
                              std::string* trace)
    : settings_(settings), types_(types), scene_(scene), trace_(trace) {
  state_.width = settings.initial_width;
  state_.color = settings.initial_color;
  if (types.cpfg()) {
    cpfg_ = settings.cpfg_symbols && settings.cpfg_symbols->size() == types.size()
                ? settings.cpfg_symbols
                : std::make_shared<const CpfgSymbols>(types);
    state_.color = settings.cpfg_initial_color;
    state_.back_color = settings.cpfg_initial_back_color;
    state_.scale = settings.initial_scale;
  }
  for (const Tropism& t : settings.tropisms) elasticity_.push_back(t.elasticity);
  elasticity_.push_back(settings.simple_tropism.elasticity);
  update_bending();
}

std::string TurtleInterpreter::Impl::where() const {
  return " (module " + std::to_string(from_.module_index) + " of the string)";
}

void TurtleInterpreter::Impl::note(const char* text) {
  if (trace_) *trace_ += text;
}

void TurtleInterpreter::Impl::note_position(const char* text, Vec3 p) {
  if (!trace_) return;
  *trace_ += text;
  append_vector(*trace_, p);
}

// ---- moving and drawing lines --------------------------------------------------

void TurtleInterpreter::Impl::add_segment(Vec3 from, Vec3 to) {
  if (!scene_) return;
  geometry::Segment s;
  s.start = from;
  s.end = to;
  s.up = state_.frame.up;
  s.start_width = s.end_width = state_.width;
  s.color = state_.color;
  s.from = from_;
  if (state_.texture >= 0) {
    // lpfg's cylinder lines: v runs on by TextureVCoeff per unit of length,
    // starting again below 1 (gencyltrtl.cpp).
    s.texture = state_.texture;
    s.texture_v0 = state_.texture_v_at;
    s.texture_v1 = state_.texture_v_at + length(to - from) * state_.texture_v;
    state_.texture_v_at = s.texture_v1 > 1 ? s.texture_v1 - 1 : s.texture_v1;
  }
  scene_->segments.push_back(s);
}

void TurtleInterpreter::Impl::forward(float distance, bool draw, bool polygon_vertex_too) {
  const Vec3 start = state_.position;
  const Vec3 end = start + state_.frame.heading * distance;
  state_.position = end;
  // The frame of the last drawn step, for cpfg's @Tp (F and G set it, f and g do not).
  if (draw) {
    state_.step_heading = state_.frame.heading;
    state_.step_up = state_.frame.up;
  }
  // Inside a generalized cylinder the cylinder is the drawing.
  if (draw && distance != 0 && !cylinder_open(state_)) add_segment(start, end);
  if (trace_) {
    note_position(" from ", start);
    note_position(" to ", end);
  }
  if (polygon_vertex_too && !polygons_.empty()) polygon_vertex();
  if (polygon_vertex_too && cylinder_open(state_)) cylinder_step_point();
  if (draw && bending_) apply_tropisms();
}

Vec3 TurtleInterpreter::Impl::to_world(Vec3 p) const {
  return state_.origin + state_.axis_x * p.x + state_.axis_y * p.y + state_.axis_z * p.z;
}

Vec3 TurtleInterpreter::Impl::to_world_offset(Vec3 d) const {
  return state_.axis_x * d.x + state_.axis_y * d.y + state_.axis_z * d.z;
}

void TurtleInterpreter::Impl::move_to(Vec3 target) {
  if (length(target - state_.position) < kEpsilon) {
    note(" ignored: no distance");
    return;
  }
  note_position(" from ", state_.position);
  note_position(" to ", target);
  state_.position = target;
}

void TurtleInterpreter::Impl::line(Vec3 from, Vec3 to) {
  if (length(to - from) < kEpsilon) {
    note(" ignored: no distance");
    return;
  }
  add_segment(from, to);
  note_position(" from ", from);
  note_position(" to ", to);
  state_.position = to;
}

// ---- rotations -----------------------------------------------------------------

void TurtleInterpreter::Impl::turn(float degrees, int axis) {
  float c, s;
  angles_.get(degrees, &c, &s);
  Frame& f = state_.frame;
  if (axis == 0) f.rotate_up(c, s);
  else if (axis == 1) f.rotate_left(c, s);
  else f.rotate_heading(c, s);
}

void TurtleInterpreter::Impl::apply_tropisms() {
  Frame& f = state_.frame;
  const std::size_t n = settings_.tropisms.size();
  for (std::size_t k = 0; k <= n; ++k) {
    const float e = elasticity_[k];
    if (e == 0) continue;
    const Tropism& t = k < n ? settings_.tropisms[k] : settings_.simple_tropism;
    const float strength = length(t.direction);
    if (strength < kEpsilon) continue;
    const Vec3 toward = t.direction / strength;
    const float intensity = t.intensity;
    if (t.torque) {
      // Twist around H, turning U toward T's part across H.
      const Vec3 across = toward - f.heading * dot(toward, f.heading);
      const Vec3 axis = cross(f.up, across);
      const float s = length(axis);
      if (s < 1e-7f) continue;
      const double angle = static_cast<double>(e) * intensity * strength * s;
      f.rotate(axis / s, static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
    } else {
      Vec3 axis = cross(f.heading, toward);
      const float s = length(axis);
      const double phi = std::atan2(static_cast<double>(s), static_cast<double>(dot(f.heading, toward)));
      const double angle = static_cast<double>(e) * intensity * strength * std::sin(phi - t.angle * kDegrees);
      if (s < 1e-7f) {
        if (t.angle == 0) continue;  // already along T
        axis = f.left;               // along T but meant to keep an angle to it: leave T in any direction
      } else {
        axis = axis / s;
      }
      f.rotate(axis, static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)));
    }
  }
  f.orthonormalize();
}

void TurtleInterpreter::Impl::update_bending() {
  bending_ = std::any_of(elasticity_.begin(), elasticity_.end(), [](float e) { return e != 0; });
}

void TurtleInterpreter::Impl::change_elasticity(int id, float value, bool relative) {
  const std::size_t n = settings_.tropisms.size();
  if (id < 1 || static_cast<std::size_t>(id) > n) {
    note(" ignored: no such tropism");
    return;
  }
  float& e = elasticity_[static_cast<std::size_t>(id) - 1];
  e = relative ? e + value : value;
  update_bending();
  if (trace_) {
    *trace_ += " elasticity ";
    append_number(*trace_, e);
  }
}

// ---- the turtle stack ------------------------------------------------------------

void TurtleInterpreter::Impl::push() {
  stack_.push_back(state_);
  saved_elasticity_.insert(saved_elasticity_.end(), elasticity_.begin(), elasticity_.end());
  if (trace_) *trace_ += " depth " + std::to_string(stack_.size());
}

void TurtleInterpreter::Impl::pop() {
  if (stack_.empty()) {
    note(" ignored: no branch to end");
    return;
  }
  const TurtleState& saved = stack_.back();
  // A cylinder started in this branch ends with it.
  if (cylinder_open(state_) && (state_.cylinder != saved.cylinder || state_.cylinder_serial != saved.cylinder_serial))
    close_cylinder(state_.cylinder);
  state_ = saved;
  stack_.pop_back();
  if (state_.cylinder >= 0 && !cylinder_open(state_)) state_.cylinder = -1;
  const std::size_t n = elasticity_.size();
  std::copy(saved_elasticity_.end() - static_cast<std::ptrdiff_t>(n), saved_elasticity_.end(), elasticity_.begin());
  saved_elasticity_.resize(saved_elasticity_.size() - n);
  update_bending();
  if (trace_) {
    *trace_ += " depth " + std::to_string(stack_.size());
    note_position(" at ", state_.position);
  }
}

void TurtleInterpreter::Impl::query(Vec3 value, bool in_string) {
  query_cpfg(3, value, in_string);
}

// ---- dispatch ----------------------------------------------------------------------

void TurtleInterpreter::Impl::visit(ModuleId id, const unsigned char* p, std::uint32_t source_index, bool in_string) {
  namespace m = rt::mid;
  if (id >= m::PredefinedCount) return;
  from_ = Provenance{source_index, id};
  if (trace_) append_module(*trace_, id, p);
  Frame& frame = state_.frame;
  const bool corrected = settings_.corrected_rotation;
  switch (id) {
    case m::SB: push(); break;
    case m::EB: pop(); break;
    case m::Cut: note(" (the derivation's; nothing to draw)"); break;

    case m::F: forward(f32(p), true, true); break;
    case m::f: forward(f32(p), false, true); break;
    case m::G: forward(f32(p), true, false); break;
    case m::g: forward(f32(p), false, false); break;
    case m::MoveTo: case m::MoveTo3f: move_to(to_world(v3f(p))); break;
    case m::MoveTo3d: move_to(to_world(v3d(p))); break;
    case m::MoveTo2f: move_to(to_world(v2f(p))); break;
    case m::MoveTo2d: move_to(to_world(v2d(p))); break;
    case m::MoveRel3f: move_to(state_.position + to_world_offset(v3f(p))); break;
    case m::MoveRel3d: move_to(state_.position + to_world_offset(v3d(p))); break;
    case m::MoveRel2f: move_to(state_.position + to_world_offset(v2f(p))); break;
    case m::MoveRel2d: move_to(state_.position + to_world_offset(v2d(p))); break;
    case m::LineTo: case m::LineTo3f: line(state_.position, to_world(v3f(p))); break;
    case m::LineTo3d: line(state_.position, to_world(v3d(p))); break;
    case m::LineTo2f: line(state_.position, to_world(v2f(p))); break;
    case m::LineTo2d: line(state_.position, to_world(v2d(p))); break;
    case m::LineRel3f: line(state_.position, state_.position + to_world_offset(v3f(p))); break;
    case m::LineRel3d: line(state_.position, state_.position + to_world_offset(v3d(p))); break;
    case m::LineRel2f: line(state_.position, state_.position + to_world_offset(v2f(p))); break;
    case m::LineRel2d: line(state_.position, state_.position + to_world_offset(v2d(p))); break;
    case m::Line3f: line(to_world(v3f(p)), to_world(v3f(p, 12))); break;
    case m::Line3d: line(to_world(v3d(p)), to_world(v3d(p, 24))); break;
    case m::Line2f: line(to_world(v2f(p)), to_world(v2f(p, 8))); break;
    case m::Line2d: line(to_world(v2d(p)), to_world(v2d(p, 16))); break;
    case m::SetCoordinateSystem: {
      // Local x, y, z along the turtle's right (-L), heading and up: at the
      // initial frame, the world's own axes.
      const float s = f32(p);
      state_.origin = state_.position;
      state_.axis_x = frame.left * -s;
      state_.axis_y = frame.heading * s;
      state_.axis_z = frame.up * s;
      note_position(" origin ", state_.origin);
      break;
    }

    case m::Left: turn(f32(p), 0); break;
    case m::Right: turn(-f32(p), 0); break;
    // Corrected: Up turns H toward U, Down toward -U, RollL turns U toward L,
    // RollR toward -L. lpfg's old rotations went the other way.
    case m::Up: turn(corrected ? -f32(p) : f32(p), 1); break;
    case m::Down: turn(corrected ? f32(p) : -f32(p), 1); break;
    case m::RollL: turn(corrected ? -f32(p) : f32(p), 2); break;
    case m::RollR: turn(corrected ? f32(p) : -f32(p), 2); break;
    case m::TurnAround: frame.rotate_up(-1, 0); break;
    case m::RollToVert:
      if (!frame.roll_to_vertical(kVertical, kEpsilon)) note(" ignored: heading vertical");
      break;
    case m::RotateXYZ:
    case m::RotateHLU: {
      Vec3 axis = v3f(p);
      if (id == m::RotateHLU) axis = frame.heading * axis.x + frame.left * axis.y + frame.up * axis.z;
      if (length(axis) < kEpsilon) {
        note(" ignored: no axis");
        break;
      }
      float c, s;
      angles_.get(f32(p, 12), &c, &s);
      frame.rotate(normalized(axis), c, s);
      break;
    }
    case m::SetHead:
      if (!frame.set_head_up(v3f(p), v3f(p, 12), kEpsilon)) note(" ignored: degenerate vectors");
      break;
    case m::SetHead3f:
      if (!frame.set_heading(v3f(p), kEpsilon)) note(" ignored: no heading");
      break;

    case m::IncColor: state_.color = state_.color >= 255 ? 1 : state_.color + 1; break;
    case m::DecColor: state_.color = state_.color <= 1 ? 255 : state_.color - 1; break;
    case m::SetColor: {
      const int n = i32(p);
      if (n >= 1 && n <= 255) state_.color = n;
      else note(" ignored: outside 1..255");
      break;
    }
    case m::SetWidth: {
      const float w = f32(p);
      if (w > 0) state_.width = w;
      else note(" ignored: not positive");
      break;
    }

    case m::Circle0: circle(state_.width / 2, 0, false); break;
    case m::CircleFront0: circle(state_.width / 2, 0, true); break;
    case m::Circle: circle(f32(p), 0, false); break;
    case m::CircleFront: circle(f32(p), 0, true); break;
    case m::CircleB: circle(f32(p), state_.width, false); break;
    case m::CircleFrontB: circle(f32(p), state_.width, true); break;
    case m::Sphere0: sphere(state_.width / 2); break;
    case m::Sphere: sphere(f32(p)); break;

    case m::SP: start_polygon(); break;
    case m::EP: end_polygon(); break;
    case m::PP: polygon_vertex(); break;
    case m::Rhombus: {
      // The turtle at the bottom corner; length along H, width across along L.
      const float length = f32(p), width = f32(p, 4);
      const Vec3 o = state_.position, h = frame.heading * length, l = frame.left * (width / 2);
      const Vec3 corners[4] = {o, o + h * 0.5f - l, o + h, o + h * 0.5f + l};
      flat_shape(geometry::TriangleGroup::Kind::Rhombus, corners, 4);
      break;
    }
    case m::Triangle: {
      // The turtle at the middle of the base; the apex `height` along H.
      const float width = f32(p), height = f32(p, 4);
      const Vec3 o = state_.position, l = frame.left * (width / 2);
      const Vec3 corners[3] = {o + l, o - l, o + frame.heading * height};
      flat_shape(geometry::TriangleGroup::Kind::Triangle, corners, 3);
      break;
    }

    case m::Surface: {
      const float s = f32(p, 4);
      surface(i32(p), {s, s, s}, "Surface");
      break;
    }
    case m::Surface3: surface(i32(p), v3f(p, 4), "Surface3"); break;
    case m::Mesh: {
      const float s = f32(p, 4);
      mesh(i32(p), {s, s, s}, "Mesh");
      break;
    }
    case m::Mesh3: mesh(i32(p), v3f(p, 4), "Mesh3"); break;
    case m::SetUPrecision: state_.u_precision = std::max(0, static_cast<int>(std::lround(f32(p)))); break;
    case m::SetVPrecision: state_.v_precision = std::max(0, static_cast<int>(std::lround(f32(p)))); break;
    case m::InitSurface: lsystem_surface_ = geometry::BezierPatch{}; break;
    case m::SurfacePoint: surface_point(i32(p, 4), i32(p, 8)); break;
    case m::DrawSurface: draw_lsystem_surface(); break;
    case m::DSurface: dynamic_surface(p); break;

    case m::StartGC: start_cylinder(); break;
    case m::PointGC: cylinder_point(); break;
    case m::EndGC: end_cylinder(); break;
    case m::CurrentContour: {
      const int c = i32(p);
      check_contour(c, "CurrentContour");
      state_.contour = state_.blend_contour = c;
      state_.blend = 0;
      break;
    }
    case m::BlendedContour: {
      const int a = i32(p), b = i32(p, 4);
      check_contour(a, "BlendedContour");
      check_contour(b, "BlendedContour");
      state_.contour = a;
      state_.blend_contour = b;
      state_.blend = f32(p, 8);
      break;
    }
    case m::ScaleContour:
      state_.contour_scale_left = f32(p);
      state_.contour_scale_up = f32(p, 4);
      break;
    case m::ContourSides:
      if (cylinder_open(state_)) note(" ignored: inside a generalized cylinder");
      else state_.contour_sides = std::max(3, i32(p));
      break;

    case m::CurrentTexture: state_.texture = i32(p); break;
    case m::TextureVCoeff: state_.texture_v = f32(p); break;
    case m::Label: label(p); break;

    case m::SetElasticity: change_elasticity(i32(p), f32(p, 4), false); break;
    case m::IncElasticity:
    case m::DecElasticity: {
      const int t = i32(p);
      const bool known = t >= 1 && static_cast<std::size_t>(t) <= settings_.tropisms.size();
      const float step = known ? settings_.tropisms[static_cast<std::size_t>(t) - 1].step : 0.0f;
      change_elasticity(t, id == m::IncElasticity ? step : -step, true);
      break;
    }
    case m::Elasticity:
      elasticity_.back() = f32(p);
      update_bending();
      break;

    case m::GetPos: query(state_.position, in_string); break;
    case m::GetHead: query(frame.heading, in_string); break;
    case m::GetLeft: query(frame.left, in_string); break;
    case m::GetUp: query(frame.up, in_string); break;

    case m::E1:
    case m::E2:
    case m::EA20: note(" (no environment: unchanged)"); break;
    case m::Camera:
      if (scene_) scene_->camera = geometry::CameraPose{state_.position, frame.heading, frame.up, from_};
      note_position(" at ", state_.position);
      break;
    case m::MouseIns:
    case m::MouseInsPos: break;
    default: break;
  }
  if (trace_) {
    if (id >= m::Left && id <= m::SetHead3f) {
      note_position(" H ", frame.heading);
      note_position(" L ", frame.left);
      note_position(" U ", frame.up);
    }
    trace_->push_back('\n');
  }
}

void TurtleInterpreter::Impl::finish() {
  while (!polygons_.empty()) {
    if (trace_) *trace_ += "end of string: EP";
    end_polygon();
    if (trace_) trace_->push_back('\n');
  }
  for (std::size_t k = 0; k < cylinders_.size(); ++k) {
    if (!cylinders_[k].open) continue;
    if (trace_) *trace_ += "end of string: EndGC";
    close_cylinder(static_cast<int>(k));
    if (trace_) trace_->push_back('\n');
  }
}

// ---- the public face -------------------------------------------------------------

TurtleInterpreter::TurtleInterpreter(const TurtleSettings& settings, const ModuleTypes& types,
                                     geometry::Scene* scene, std::string* trace)
    : impl_(new Impl(settings, types, scene, trace)) {}

TurtleInterpreter::~TurtleInterpreter() { delete impl_; }

void TurtleInterpreter::visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string) {
  if (impl_->cpfg_) impl_->visit_cpfg(id, params, source_index, in_string);
  else impl_->visit(id, params, source_index, in_string);
}

void TurtleInterpreter::finish() { impl_->finish(); }

TurtleInterpreter::Pose TurtleInterpreter::pose() const {
  const TurtleState& s = impl_->state_;
  return Pose{s.position, s.frame.heading, s.frame.left, s.frame.up, s.width, s.scale};
}

const derive::ParameterWrites& TurtleInterpreter::query_answers() const { return impl_->query_answers_; }

geometry::Scene interpret_scene(derive::Derivation& derivation, int view, const TurtleSettings& settings,
                                std::string* trace) {
  geometry::Scene scene;
  TurtleInterpreter turtle(settings, derivation.types(), &scene, trace);
  derivation.interpret(view, turtle);
  turtle.finish();
  return scene;
}

void walk_string(const ModuleString& string, const ModuleTypes& types, const TurtleSettings& settings,
                 geometry::Scene* scene, std::string* trace, derive::ParameterWrites* query_answers) {
  TurtleInterpreter turtle(settings, types, scene, trace);
  const StringView view = string.view(types);
  std::uint32_t index = 0;
  for (std::size_t at = view.begin; at < view.end; at = view.next(at))
    turtle.visit(view.id_at(at), module_params(view.data, at), index++, true);
  turtle.finish();
  if (query_answers) *query_answers = turtle.query_answers();
}

derive::ParameterWrites query_answers(derive::Derivation& derivation, const TurtleSettings& settings) {
  TurtleInterpreter turtle(settings, derivation.types(), nullptr);
  derivation.interpret(0, turtle);
  turtle.finish();
  return turtle.query_answers();
}

}  // namespace sylva::turtle
