// The dispatcher's own commands: the stack, moves and lines, rotations,
// widths, colours and the scale, tropisms and query modules. Shapes,
// polygons and cylinders are in dispatcher_drawing.cpp.
#include "turtle/dispatcher.h"

#include <algorithm>
#include <cmath>

namespace sylva::turtle {

using namespace command;

namespace {

// World up, for RollToVert and cpfg's @v: models grow up the screen, along +y.
constexpr Vec3 kVertical{0, 1, 0};

}  // namespace

CommandDispatcher::CommandDispatcher(const TurtleSettings& settings, const TurtleState& initial, geometry::Scene* scene)
    : settings_(settings),
      scene_(scene),
      state_(initial),
      tropisms_(settings),
      cylinders_(settings, scene),
      shapes_(settings, scene) {}

void CommandDispatcher::run(const Note&) {}

// ---- the stack ------------------------------------------------------------------

CommandResult CommandDispatcher::run(const Pop&) {
  if (stack_.empty()) return noted(" ignored: no branch to end");
  CommandResult r;
  TurtleState& saved = stack_.back();
  const CylinderBuilder::Closed closed = cylinders_.end_branch(state_, saved);
  r.closed_rings = closed.rings;
  r.closed_sides = closed.sides;
  state_ = saved;
  stack_.pop_back();
  tropisms_.pop();
  return r;
}

// ---- moving and drawing lines ---------------------------------------------------

void CommandDispatcher::add_segment(Vec3 from, Vec3 to) {
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

CommandResult CommandDispatcher::run(const Forward& c) {
  const float distance = c.distance * state_.scale;
  CommandResult r;
  r.from = state_.position;
  r.to = r.from + state_.frame.heading * distance;
  state_.position = r.to;
  // The frame of the last drawn step, for cpfg's @Tp (F and G set it, f and g do not).
  if (c.draw) {
    state_.step_heading = state_.frame.heading;
    state_.step_up = state_.frame.up;
  }
  // Inside a generalized cylinder the cylinder is the drawing.
  const bool in_cylinder = cylinders_.open(state_);
  if (c.draw && distance != 0 && !in_cylinder) add_segment(r.from, r.to);
  if (c.records_vertex && polygons_.any_open()) r.polygon = polygons_.add_vertex(state_.position, state_.frame);
  if (c.records_vertex && in_cylinder) r.cylinder_point = cylinders_.step_point(state_, from_);
  if (c.draw && tropisms_.bending()) tropisms_.bend(state_.frame);
  return r;
}

Vec3 CommandDispatcher::to_world(Vec3 p, Coordinates coordinates) const {
  const TurtleState& s = state_;
  switch (coordinates) {
    case Coordinates::Local: return s.origin + s.axis_x * p.x + s.axis_y * p.y + s.axis_z * p.z;
    case Coordinates::LocalOffset: return s.position + (s.axis_x * p.x + s.axis_y * p.y + s.axis_z * p.z);
    case Coordinates::World: break;
  }
  return p;
}

CommandResult CommandDispatcher::move_to(Vec3 target) {
  if (length(target - state_.position) < kEpsilon) return noted(" ignored: no distance");
  CommandResult r;
  r.from = state_.position;
  r.to = target;
  state_.position = target;
  return r;
}

CommandResult CommandDispatcher::line(Vec3 from, Vec3 to) {
  if (length(to - from) < kEpsilon) return noted(" ignored: no distance");
  add_segment(from, to);
  CommandResult r;
  r.from = from;
  r.to = to;
  state_.position = to;
  return r;
}

CommandResult CommandDispatcher::run(const MoveTo& c) {
  if (c.coordinates != Coordinates::World) return move_to(to_world(c.point, c.coordinates));
  // Coordinates left out keep their value.
  Vec3 target = state_.position;
  if (c.given > 0) target.x = c.point.x;
  if (c.given > 1) target.y = c.point.y;
  if (c.given > 2) target.z = c.point.z;
  return move_to(target);
}

CommandResult CommandDispatcher::run(const LineTo& c) { return line(state_.position, to_world(c.point, c.coordinates)); }

CommandResult CommandDispatcher::run(const Line& c) {
  return line(to_world(c.from, Coordinates::Local), to_world(c.to, Coordinates::Local));
}

void CommandDispatcher::run(const SetCoordinateSystem& c) {
  // Local x, y, z along the turtle's right (-L), heading and up: at the
  // initial frame, the world's own axes.
  const Frame& f = state_.frame;
  state_.origin = state_.position;
  state_.axis_x = f.left * -c.scale;
  state_.axis_y = f.heading * c.scale;
  state_.axis_z = f.up * c.scale;
}

// ---- rotations --------------------------------------------------------------------

void CommandDispatcher::run(const TurnAround&) { state_.frame.rotate_up(-1, 0); }

CommandResult CommandDispatcher::run(const RollToVertical&) {
  if (!state_.frame.roll_to_vertical(kVertical, kEpsilon)) return noted(" ignored: heading vertical");
  return {};
}

CommandResult CommandDispatcher::run(const Rotate& c) {
  Frame& f = state_.frame;
  const Vec3 axis = c.turtle_axes ? f.heading * c.axis.x + f.left * c.axis.y + f.up * c.axis.z : c.axis;
  if (length(axis) < kEpsilon) return noted(" ignored: no axis");
  float cosine, sine;
  angles_.get(c.degrees, &cosine, &sine);
  f.rotate(normalized(axis), cosine, sine);
  return {};
}

CommandResult CommandDispatcher::run(const SetHeadUp& c) {
  if (!state_.frame.set_head_up(c.heading, c.up, kEpsilon)) return noted(" ignored: degenerate vectors");
  return {};
}

CommandResult CommandDispatcher::run(const SetHeading& c) {
  if (!state_.frame.set_heading(c.heading, kEpsilon)) return noted(" ignored: no heading");
  return {};
}

// cpfg's adjust_up_and_left: the up vector of the last F or G, carried by
// the smallest rotation from that step's heading to this one (parallel
// transport), which undoes the twist (/ \) since that step. Where the
// heading has not turned (or turned right round), nothing changes.
CommandResult CommandDispatcher::run(const MinimizeTwist&) {
  Frame& f = state_.frame;
  const Vec3 from = state_.step_heading, to = f.heading;
  const Vec3 axis = cross(from, to);
  const float s = length(axis), c = dot(from, to);
  if (s <= 1e-6f) return noted(" (the heading has not turned since the last step)");
  Vec3 up = rotated(state_.step_up, axis / s, c, s);
  // Exactly across the heading (it may have drifted from it).
  up = up - to * dot(up, to);
  if (length(up) < kEpsilon || !f.set_head_up(to, up, kEpsilon)) return noted(" ignored: up along the heading");
  return {};
}

void CommandDispatcher::run(const ForceTwist&) {
  state_.step_heading = state_.frame.heading;
  state_.step_up = state_.frame.up;
}

// ---- widths, colours and the scale ----------------------------------------------------

void CommandDispatcher::run(const StepWidth& c) {
  state_.width = std::max(0.0f, state_.width + c.by);
}

void CommandDispatcher::run(const StepColor& c) {
  int& color = c.back_side ? state_.back_color : state_.color;
  if (c.wrap == ColorWrap::Lpfg) {
    color = c.by > 0 ? (color >= 255 ? 1 : color + 1) : (color <= 1 ? 255 : color - 1);
  } else {
    // The back side's colour starts from the front's until it is set.
    const int current = c.back_side && state_.back_color < 0 ? state_.color : color;
    color = cpfg_color(current + c.by, c.wrap == ColorWrap::CpfgUp);
  }
}

void CommandDispatcher::run(const SetScale& c) {
  state_.scale = c.scale;
}

void CommandDispatcher::run(const MultiplyScale& c) {
  state_.scale = state_.scale * c.by;
}

void CommandDispatcher::run(const DivideScale& c) {
  state_.scale = state_.scale / c.by;
}

void CommandDispatcher::run(const CallSubLsystem& c) {
  sub_lsystem_scales_.push_back(state_.scale);
  state_.scale *= c.scale;
}

void CommandDispatcher::run(const ReturnFromSubLsystem&) {
  if (!sub_lsystem_scales_.empty()) {
    state_.scale = sub_lsystem_scales_.back();
    sub_lsystem_scales_.pop_back();
  }
}

// ---- tropisms ---------------------------------------------------------------------------

CommandResult CommandDispatcher::run(const SetElasticity& c) {
  const std::optional<float> elasticity = tropisms_.set(c.tropism, c.value, c.relative);
  if (!elasticity) return noted(" ignored: no such tropism");
  CommandResult r;
  r.elasticity = *elasticity;
  return r;
}

void CommandDispatcher::run(const SimpleElasticity& c) {
  tropisms_.set_simple(c.value);
}

// ---- query modules -------------------------------------------------------------------

Vec3 CommandDispatcher::quantity(const TurtleState& turtle, Quantity quantity) {
  switch (quantity) {
    case Quantity::Position: return turtle.position;
    case Quantity::Heading: return turtle.frame.heading;
    case Quantity::Left: return turtle.frame.left;
    case Quantity::Up: return turtle.frame.up;
    case Quantity::CpfgUp: return -turtle.frame.up;
  }
  return {};
}

void CommandDispatcher::run(const Query& c) {
  const Vec3 answer = quantity(state_, c.quantity);
  // cpfg's ?P(x,y) receives x and y, ?P(x,y,z) all three.
  const int n = std::min(c.count, 3);
  if (in_string_ && n > 0) {
    const float xyz[3] = {answer.x, answer.y, answer.z};
    query_answers_.set_floats(from_.module_index, 0, xyz, n);
  }
}

}  // namespace sylva::turtle
