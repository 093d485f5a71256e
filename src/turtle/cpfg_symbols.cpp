#include "turtle/cpfg_symbols.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "support/diagnostic.h"
#include "sylva/predefined_ids.h"
#include "turtle/interpreter_impl.h"
#include "turtle/trace.h"

namespace sylva::turtle {

namespace {

const std::unordered_map<std::string_view, CpfgOp>& command_table() {
  using O = CpfgOp;
  static const std::unordered_map<std::string_view, CpfgOp> table = {
      {"F", O::Forward}, {"f", O::Move}, {"G", O::ForwardNoVertex}, {"g", O::MoveNoVertex},
      {"@M", O::MoveTo},
      {"+", O::Left}, {"-", O::Right}, {"&", O::Down}, {"^", O::Up}, {"\\", O::RollLeft}, {"/", O::RollRight},
      {"|", O::TurnAround},
      // $ ends a sub-L-system's ?(label,s), and does nothing else.
      {"@v", O::RollToVertical}, {"$", O::SubLsystemReturn}, {"?", O::SubLsystemCall},
      {"@R", O::SetHeading},
      {"#", O::WidthUp}, {"!", O::WidthDown},
      {";", O::ColorUp}, {",", O::ColorDown},
      // The Algorithmic Beauty of Plants' increment of the colour index.
      {"'", O::ColorUp},
      {"{", O::PolygonOrCylinderStart}, {"}", O::PolygonOrCylinderEnd}, {".", O::VertexOrCylinderPoint},
      {"@o", O::CircleScreen}, {"@c", O::CircleHL}, {"@bo", O::CircleScreenBoundary}, {"@bc", O::CircleHLBoundary},
      {"@O", O::Sphere},
      {"@Gs", O::CylinderStart}, {"@Gc", O::CylinderPoint}, {"@Ge", O::CylinderEnd},
      {"@Gt", O::CylinderTangents}, {"@Gr", O::CylinderRadiusTangents},
      {"@#", O::Contour}, {"@!", O::ContourSides},
      {"@D", O::SetScale}, {"@Di", O::ScaleUp}, {"@Dd", O::ScaleDown},
      {"@Tx", O::Texture},
      {"@PS", O::SurfaceInit}, {"@PC", O::SurfacePoint}, {"@PD", O::SurfaceDraw},
      {"@Ts", O::ElasticitySet}, {"@T", O::ElasticityUp}, {"@Td", O::ElasticityDown},
      {"?P", O::QueryPosition}, {"?H", O::QueryHeading}, {"?L", O::QueryLeft}, {"?U", O::QueryUp},
      {"@L", O::Label}, {"@Tp", O::MinimizeTwist}, {"@Tf", O::ForceTwist},
      {"@;", O::BackColorUp}, {"@,", O::BackColorDown},
  };
  return table;
}

}  // namespace

CpfgOp cpfg_op(const std::string& symbol) {
  auto it = command_table().find(symbol);
  if (it != command_table().end()) return it->second;
  if (symbol.size() == 2 && symbol[0] == '~') return CpfgOp::PredefinedSurface;  // ~id (CPFG manual 6.7.1)
  return CpfgOp::None;
}

bool cpfg_command_prefix(const std::string& start) {
  if (start == "~") return true;
  for (const auto& [symbol, op] : command_table())
    if (symbol.size() > start.size() && symbol.compare(0, start.size(), start) == 0) return true;
  return false;
}

CpfgSymbols::CpfgSymbols(const ModuleTypes& types) : ops_(types.size(), CpfgOp::None), params_(types.size(), 0) {
  // [ and ] keep the predefined ids; the other predefined modules of L+C
  // never occur in a cpfg string (cpfg's F is its own module type).
  if (ops_.size() > rt::mid::EB) {
    ops_[rt::mid::SB] = CpfgOp::Push;
    ops_[rt::mid::EB] = CpfgOp::Pop;
  }
  for (std::size_t id = rt::mid::PredefinedCount; id < types.size(); ++id) {
    const auto m = static_cast<ModuleId>(id);
    ops_[id] = cpfg_op(types.name(m));
    std::uint32_t size = types[m].param_size;
    if (ops_[id] == CpfgOp::Label) {
      // @L("format", p1, ...): the string's pointer, then the floats.
      if (size < sizeof(const char*)) ops_[id] = CpfgOp::None;
      else size -= sizeof(const char*);
    }
    params_[id] = static_cast<std::uint8_t>(std::min<std::uint32_t>(size / 4, 255));
    const std::string& name = types.name(m);
    if (size == 0 && (name == "@" || name == "?" || name == "~")) ops_[id] = CpfgOp::Prefix;
  }
  // Queries read split: ? then P(x,y,z) (P H L U with two or three parameters).
  bool split_query = false;
  for (std::size_t id = rt::mid::PredefinedCount; id < types.size(); ++id)
    split_query = split_query || (ops_[id] == CpfgOp::Prefix && types.name(static_cast<ModuleId>(id)) == "?");
  for (std::size_t id = rt::mid::PredefinedCount; split_query && id < types.size(); ++id) {
    const std::string& name = types.name(static_cast<ModuleId>(id));
    if ((name == "P" || name == "H" || name == "L" || name == "U") && params_[id] >= 2)
      split_queries_.push_back(static_cast<ModuleId>(id));
  }
}

std::string format_cpfg_label(std::string_view format, const float* values, int count) {
  std::string out;
  int used = 0;
  const std::size_t size = format.size();
  auto digits = [&](std::size_t& j) {
    const std::size_t from = j;
    while (j < size && format[j] >= '0' && format[j] <= '9') ++j;
    return j - from;
  };
  std::size_t i = 0;
  while (i < size) {
    if (format[i] != '%') {
      out += format[i++];
      continue;
    }
    if (i + 1 < size && format[i + 1] == '%') {
      out += '%';
      i += 2;
      continue;
    }
    // %[flags][width][.precision][length]conversion; the length (h l ll L q j
    // z t) is dropped: the value is passed as a double or a long long.
    std::string spec = "%";
    std::size_t j = i + 1;
    while (j < size && std::string_view("-+ #0").find(format[j]) != std::string_view::npos) spec += format[j++];
    std::size_t at = j;
    bool fits = digits(j) <= 3;
    spec += format.substr(at, j - at);
    if (j < size && format[j] == '.') {
      at = j++;
      fits = fits && digits(j) <= 3;
      spec += format.substr(at, j - at);
    }
    while (j < size && std::string_view("hlLqjzt").find(format[j]) != std::string_view::npos) ++j;
    const char conversion = j < size ? format[j] : '\0';
    const bool real = conversion != '\0' && std::string_view("fFeEgGaA").find(conversion) != std::string_view::npos;
    const bool integer = conversion != '\0' && std::string_view("diouxX").find(conversion) != std::string_view::npos;
    const double v = used < count ? static_cast<double>(values[used]) : 0.0;
    // A value too large for a long long is printed as a number, not converted.
    const bool representable = real || (std::isfinite(v) && std::fabs(v) < 9.2e18);
    if (!fits || !(real || integer) || used >= count || !representable) {
      const std::size_t end = std::min(size, j + 1);
      out += format.substr(i, end - i);
      i = end;
      continue;
    }
    ++used;
    int n;
    char buffer[64];
    std::string text;
    if (real) {
      spec += conversion;
      n = std::snprintf(buffer, sizeof buffer, spec.c_str(), v);
      if (n >= static_cast<int>(sizeof buffer)) {
        text.resize(static_cast<std::size_t>(n) + 1);
        std::snprintf(text.data(), text.size(), spec.c_str(), v);
      }
    } else {
      spec += "ll";
      spec += conversion;
      const long long whole = static_cast<long long>(v);  // cpfg's C truncates toward 0
      n = conversion == 'd' || conversion == 'i'
              ? std::snprintf(buffer, sizeof buffer, spec.c_str(), whole)
              : std::snprintf(buffer, sizeof buffer, spec.c_str(), static_cast<unsigned long long>(whole));
      if (n >= static_cast<int>(sizeof buffer)) {
        text.resize(static_cast<std::size_t>(n) + 1);
        if (conversion == 'd' || conversion == 'i') std::snprintf(text.data(), text.size(), spec.c_str(), whole);
        else std::snprintf(text.data(), text.size(), spec.c_str(), static_cast<unsigned long long>(whole));
      }
    }
    if (n > 0) out.append(text.empty() ? buffer : text.data(), static_cast<std::size_t>(n));
    i = j + 1;
  }
  return out;
}

std::vector<ModuleId> CpfgSymbols::query_modules() const {
  std::vector<ModuleId> ids = split_queries_;
  for (std::size_t id = 0; id < ops_.size(); ++id)
    if (is_query(ops_[id])) ids.push_back(static_cast<ModuleId>(id));
  return ids;
}

// ---- interpretation -----------------------------------------------------------

namespace {

float param(const unsigned char* p, int k) {
  float v;
  std::memcpy(&v, p + 4 * k, sizeof v);
  return v;
}
int int_param(const unsigned char* p, int k) { return static_cast<int>(std::lround(param(p, k))); }
// @L's string: the pointer before its floats.
const char* label_text(const unsigned char* p) {
  const char* text = nullptr;
  std::memcpy(&text, p, sizeof text);
  return text ? text : "";
}
Vec3 vec_param(const unsigned char* p, int k) { return {param(p, k), param(p, k + 1), param(p, k + 2)}; }

// World up, for @v: models grow up the screen, along +y.
constexpr Vec3 kVertical{0, 1, 0};

// cpfg's colour map has 256 entries; increments wrap around it.
int wrap_color(int c) { return ((c % 256) + 256) % 256; }

// cpfg's ; and , (cpfg/interpret.c): the colour is wrapped once, upward past
// 255 by ; and downward below 0 by , so ;(600) names entry 88 of colormap 2
// (-m2) while ;(300) is entry 44 of colormap 1. Colormap 0 (a colour below 0
// after ;) is not kept: such colours wrap into colormap 1.
int step_color(int c, bool up) {
  if (up && c > 255) c -= 256;
  if (!up && c < 0) c += 256;
  return c < 0 ? wrap_color(c) : c;
}

}  // namespace

void TurtleInterpreter::Impl::query_cpfg(int count, Vec3 value, bool in_string) {
  // ?P(x,y) receives x and y, ?P(x,y,z) all three.
  const int n = std::min(count, 3);
  if (in_string && n > 0) {
    const float xyz[3] = {value.x, value.y, value.z};
    query_answers_.set_floats(from_.module_index, 0, xyz, n);
  }
  if (trace_) {
    *trace_ += in_string ? " = " : " not in the string: ";
    append_vector(*trace_, value);
  }
}

void TurtleInterpreter::Impl::visit_cpfg(ModuleId id, const unsigned char* p, std::uint32_t source_index, bool in_string) {
  using O = CpfgOp;
  CpfgOp op = cpfg_->op(id);
  // A command read a character a module: the characters so far and this one.
  // Where they make no command, cpfg reads this module on its own.
  if (!cpfg_pending_.empty()) {
    const std::string joined = cpfg_pending_ + types_.name(id);
    const CpfgOp whole = cpfg_op(joined);
    if (whole != O::None && whole != O::Label) {  // @L is never read split: its text is @L's own
      op = whole;
      cpfg_pending_.clear();
    } else if (cpfg_command_prefix(joined)) {
      cpfg_pending_ = joined;
      return;
    } else {
      cpfg_pending_.clear();
    }
  }
  if (op == O::Prefix) {
    cpfg_pending_ = types_.name(id);
    return;
  }
  if (op == O::None) return;  // cpfg ignores symbols that are not the turtle's
  const int n = cpfg_->params(id);
  from_ = Provenance{source_index, id};
  // @L's floats follow its string.
  const unsigned char* label_values = op == O::Label ? p + sizeof(const char*) : nullptr;
  if (trace_ && label_values) {
    *trace_ += types_.name(id);
    *trace_ += "(\"";
    *trace_ += label_text(p);
    *trace_ += '"';
    for (int k = 0; k < n; ++k) {
      *trace_ += ',';
      append_number(*trace_, param(label_values, k));
    }
    *trace_ += ')';
  } else if (trace_) {
    *trace_ += types_.name(id);
    if (n > 0) {
      *trace_ += '(';
      for (int k = 0; k < n; ++k) {
        if (k) *trace_ += ',';
        append_number(*trace_, param(p, k));
      }
      *trace_ += ')';
    }
  }
  Frame& frame = state_.frame;
  // Computed only by the symbols that use them (this runs for every module).
  // A rotation symbol's angle: its parameter, or the view file's increment.
  auto angle = [&] { return n > 0 ? param(p, 0) : settings_.angle_increment; };
  // A step: its parameter or 1, times the turtle scale.
  auto step = [&] { return (n > 0 ? param(p, 0) : 1.0f) * state_.scale; };
  // A circle or sphere: the parameter is its diameter, the line width by default.
  auto radius = [&] { return (n > 0 ? param(p, 0) : state_.width) * state_.scale / 2; };
  // A generalized cylinder's strips (@Gc, .(strips), @Ge): its parameter or 1.
  auto strips = [&] { return n > 0 ? static_cast<int>(std::lround(std::clamp(param(p, 0), 1.0f, 1000.0f))) : 1; };
  switch (op) {
    case O::None:
    case O::Prefix: break;
    case O::Push: push(); break;
    case O::Pop: pop(); break;

    case O::Forward: forward(step(), true, true); break;
    case O::Move: forward(step(), false, true); break;
    case O::ForwardNoVertex: forward(step(), true, false); break;
    case O::MoveNoVertex: forward(step(), false, false); break;
    case O::MoveTo: {
      // Coordinates left out keep their value.
      Vec3 to = state_.position;
      if (n > 0) to.x = param(p, 0);
      if (n > 1) to.y = param(p, 1);
      if (n > 2) to.z = param(p, 2);
      move_to(to);
      break;
    }

    // cpfg's turtle (interpret.c) starts with H = +y, L = -x and U = -z: its
    // frame is left-handed (U = L x H). The frame here is lpfg's, with U =
    // H x L, so cpfg's U is -frame.up throughout. Turns and pitches come out
    // as lpfg's corrected + - & ^ do; cpfg's / rolls L towards its U, the
    // other way from lpfg's corrected /. lpfg's "corrected rotation" does
    // not apply: cpfg has no such setting.
    case O::Left: turn(angle(), 0); break;
    case O::Right: turn(-angle(), 0); break;
    case O::Down: turn(angle(), 1); break;
    case O::Up: turn(-angle(), 1); break;
    case O::RollLeft: turn(angle(), 2); break;
    case O::RollRight: turn(-angle(), 2); break;
    case O::TurnAround: frame.rotate_up(-1, 0); break;
    case O::SubLsystemReturn:
      // The end of a sub-L-system: the caller's scale again. cpfg's $ does
      // nothing else (interpret.c): it never rolls the turtle.
      if (n == 0 && !sub_lsystem_scales_.empty()) {
        state_.scale = sub_lsystem_scales_.back();
        sub_lsystem_scales_.pop_back();
      }
      break;
    case O::RollToVertical:
      if (!frame.roll_to_vertical(kVertical, kEpsilon)) note(" ignored: heading vertical");
      break;
    case O::SetHeading:
      if (n >= 6) {
        // The up vector given is cpfg's U, -frame.up.
        if (!frame.set_head_up(vec_param(p, 0), -vec_param(p, 3), kEpsilon)) note(" ignored: degenerate vectors");
      } else if (n >= 3) {
        if (!frame.set_heading(vec_param(p, 0), kEpsilon)) note(" ignored: no heading");
      } else {
        note(" ignored: needs a heading");
      }
      break;

    case O::WidthUp:
    case O::WidthDown: {
      float w = n > 0 ? param(p, 0)
                      : state_.width + (op == O::WidthUp ? settings_.width_increment : -settings_.width_increment);
      state_.width = std::max(0.0f, w);
      break;
    }
    case O::ColorUp:
    case O::ColorDown:
      state_.color = step_color(n > 0 ? int_param(p, 0)
                                      : state_.color + (op == O::ColorUp ? settings_.color_increment
                                                                         : -settings_.color_increment),
                                op == O::ColorUp);
      break;

    // With a parameter (the curve type), { } and . are cpfg's generalized
    // cylinder (CPFG manual 6.7.3); without, its polygon (6.5).
    // {(type) defines no control point; one follows each F and f (4 strips)
    // and each .(strips) where the turtle has moved; }(type) adds the last
    // where it has moved.
    case O::PolygonOrCylinderStart:
      if (n > 0) {
        const int type = int_param(p, 0);
        if (type >= 1 && type <= 4) {
          start_cylinder(type);
        } else {
          note(" (unknown cylinder type; 1 used)");
          start_cylinder(1);
        }
      } else {
        start_polygon();
      }
      break;
    case O::PolygonOrCylinderEnd:
      if (n > 0) end_cylinder(4, std::max(1, int_param(p, 0)));
      else end_polygon();
      break;
    case O::VertexOrCylinderPoint:
      if (n > 0) cylinder_dot(strips());
      else polygon_vertex();
      break;

    case O::CircleScreen: circle(radius(), 0, true); break;
    case O::CircleHL: circle(radius(), 0, false); break;
    case O::CircleScreenBoundary: circle(radius(), state_.width, true); break;
    case O::CircleHLBoundary: circle(radius(), state_.width, false); break;
    case O::Sphere: sphere(radius()); break;

    case O::CylinderStart: start_cylinder(); break;
    // @Gc(strips), @Ge(strips): the bands since the previous control point.
    case O::CylinderPoint: cylinder_point(strips()); break;
    case O::CylinderEnd: end_cylinder(strips()); break;
    case O::CylinderTangents:
      // @Gt(start,end): the Hermite tangent coefficients of the stretches
      // ended by the next control points; one parameter sets both.
      if (n == 0) {
        note(" ignored: needs tangent coefficients");
        break;
      }
      state_.cylinder_tangent_start = param(p, 0);
      state_.cylinder_tangent_end = n > 1 ? param(p, 1) : param(p, 0);
      break;
    case O::CylinderRadiusTangents:
      // @Gr(angle1,length1,angle2,length2): the radius's Hermite tangents
      // for the stretches ended by the next control points; @Gr(flag): the
      // adjustment to the stretch's length on or off.
      if (n >= 4) {
        state_.radius_tangents.given = true;
        state_.radius_tangents.angle1 = param(p, 0);
        state_.radius_tangents.length1 = param(p, 1);
        state_.radius_tangents.angle2 = param(p, 2);
        state_.radius_tangents.length2 = param(p, 3);
      } else if (n >= 1) {
        state_.radius_tangents.adjust = param(p, 0) != 0;
      } else {
        note(" ignored: needs tangents or a flag");
      }
      break;
    case O::Contour: {
      const int c = n > 0 ? int_param(p, 0) : 0;
      check_contour(c, "@#");
      state_.contour = state_.blend_contour = c;
      state_.blend = 0;
      break;
    }
    case O::ContourSides:
      if (n == 0) note(" ignored: needs a number of sides");
      else if (cylinder_open(state_)) note(" ignored: inside a generalized cylinder");
      else state_.contour_sides = std::max(3, int_param(p, 0));
      break;

    case O::SetScale:
      if (n > 0) state_.scale = param(p, 0);
      else note(" ignored: needs a scale");
      break;
    case O::ScaleUp: state_.scale = n > 0 ? param(p, 0) : state_.scale * settings_.scale_multiplier; break;
    case O::ScaleDown:
      state_.scale = n > 0 ? param(p, 0)
                           : settings_.scale_multiplier != 0 ? state_.scale / settings_.scale_multiplier
                                                             : state_.scale;
      break;

    // cpfg's textures count from 1 (0: none); the view file's from 0.
    case O::Texture: state_.texture = n > 0 && int_param(p, 0) > 0 ? int_param(p, 0) - 1 : -1; break;

    // @PS(id,type), @PC(id,r,c), @PD(id,s,t): the one L-system surface; the
    // id, the spline type and the mesh size are not kept.
    case O::SurfaceInit: lsystem_surface_ = geometry::BezierPatch{}; break;
    case O::SurfacePoint:
      if (n >= 3) surface_point(int_param(p, 1), int_param(p, 2));
      else note(" ignored: needs id, row and column");
      break;
    case O::SurfaceDraw: draw_lsystem_surface(); break;

    case O::ElasticitySet:
      if (n >= 2) change_elasticity(int_param(p, 0), param(p, 1), false);
      else note(" ignored: needs a tropism id and a value");
      break;
    case O::ElasticityUp:
    case O::ElasticityDown: {
      if (n == 0) {
        note(" ignored: needs a tropism id");
        break;
      }
      const int t = int_param(p, 0);
      const bool known = t >= 1 && static_cast<std::size_t>(t) <= settings_.tropisms.size();
      float v = n >= 2 ? param(p, 1) : known ? settings_.tropisms[static_cast<std::size_t>(t) - 1].step : 0.0f;
      change_elasticity(t, op == O::ElasticityUp ? v : -v, true);
      break;
    }

    case O::QueryPosition: query_cpfg(n, state_.position, in_string); break;
    case O::QueryHeading: query_cpfg(n, frame.heading, in_string); break;
    case O::QueryLeft: query_cpfg(n, frame.left, in_string); break;
    case O::QueryUp: query_cpfg(n, -frame.up, in_string); break;  // cpfg's U

    // ?(label,s): the sub-L-system's structure is scaled by s (CPFG manual
    // 7.2) until its $.
    case O::SubLsystemCall:
      if (n != 2) {
        note(" ignored: needs a label and a scale");
        break;
      }
      sub_lsystem_scales_.push_back(state_.scale);
      state_.scale *= param(p, 1);
      break;

    // ~id, ~id(s), ~id(sx,sy,sz): the view file's surface `surface: id file.s scale`.
    case O::PredefinedSurface: {
      const std::string name = types_.name(id);
      const std::string key = name.substr(1);
      const auto& ids = settings_.surface_ids;
      const auto found = std::find(ids.begin(), ids.end(), key);
      if (found == ids.end())
        throw ModelError(name + where() + ": no surface has id '" + key + "' (the view file's 'surface: " + key +
                         " file.s scale' gives it)");
      Vec3 scale{1, 1, 1};
      if (n >= 3) scale = vec_param(p, 0);
      else if (n >= 1) scale = Vec3{param(p, 0), param(p, 0), param(p, 0)};
      surface(static_cast<int>(found - ids.begin()), scale * state_.scale, name.c_str());
      break;
    }

    // @L("format", p1, ...): a label at the turtle's position (CPFG manual 6.10).
    case O::Label: {
      std::vector<float> values(static_cast<std::size_t>(n));
      for (int k = 0; k < n; ++k) values[static_cast<std::size_t>(k)] = param(label_values, k);
      std::string text = format_cpfg_label(label_text(p), values.data(), n);
      if (trace_) *trace_ += " \"" + text + "\"";
      add_label(std::move(text));
      break;
    }

    // @Tp: up and left carried from the last step's to the current heading
    // by the smallest rotation between the two headings (parallel
    // transport), which undoes the twist (/ \) since that step.
    // @Tp (cpfg's adjust_up_and_left): the up vector of the last F or G,
    // carried by the rotation from that step's heading to this one. Where
    // the heading has not turned (or turned right round), nothing changes.
    case O::MinimizeTwist: {
      const Vec3 from = state_.step_heading, to = frame.heading;
      const Vec3 axis = cross(from, to);
      const float s = length(axis), c = dot(from, to);
      if (s <= 1e-6f) {
        note(" (the heading has not turned since the last step)");
        break;
      }
      Vec3 up = rotated(state_.step_up, axis / s, c, s);
      // Exactly across the heading (it may have drifted from it).
      up = up - to * dot(up, to);
      if (length(up) < kEpsilon || !frame.set_head_up(to, up, kEpsilon)) note(" ignored: up along the heading");
      break;
    }
    // @Tf: the twist so far is wanted; @Tp starts from here.
    case O::ForceTwist:
      state_.step_heading = frame.heading;
      state_.step_up = frame.up;
      break;

    // @;(n) @,(n): the back side's colour index, stepped from the front's
    // until set. Outputs draw one side: the Scene keeps the front's colour.
    case O::BackColorUp:
    case O::BackColorDown: {
      const int current = state_.back_color >= 0 ? state_.back_color : state_.color;
      const int by = op == O::BackColorUp ? settings_.back_color_increment : -settings_.back_color_increment;
      state_.back_color = step_color(n > 0 ? int_param(p, 0) : current + by, op == O::BackColorUp);
      if (trace_) *trace_ += " back colour " + std::to_string(state_.back_color);
      break;
    }
  }
  if (trace_) {
    if ((op >= O::Left && op <= O::SetHeading) || op == O::MinimizeTwist) {
      note_position(" H ", frame.heading);
      note_position(" L ", frame.left);
      note_position(" U ", frame.up);
    }
    trace_->push_back('\n');
  }
}

}  // namespace sylva::turtle
