// The one executor of turtle commands (command.h), whichever language they
// were decoded from: it keeps the turtle's state and stack, moves, turns and
// draws lines itself, and hands polygons, generalized cylinders and other
// shapes to their builders.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "derive/parameter_writes.h"
#include "geometry/scene.h"
#include "turtle/command.h"
#include "turtle/cylinder_builder.h"
#include "turtle/frame.h"
#include "turtle/polygon_builder.h"
#include "turtle/shape_drawer.h"
#include "turtle/tropisms.h"
#include "turtle/turtle_settings.h"
#include "turtle/turtle_state.h"

namespace sylva::turtle {

class CommandDispatcher {
 public:
  // `scene` may be null (only the turtle's state and the query answers matter).
  CommandDispatcher(const TurtleSettings& settings, const TurtleState& initial, geometry::Scene* scene);

  // The module the next commands come from: what they draw is its, and its
  // query answers are written for it unless it is not in the string (a
  // module an interpretation rule produced).
  void at_module(geometry::Provenance from, bool in_string) {
    from_ = from;
    in_string_ = in_string;
  }
  const TurtleState& state() const { return state_; }
  std::size_t depth() const { return stack_.size(); }
  bool in_string() const { return in_string_; }
  bool polygon_open() const { return polygons_.any_open(); }
  const CylinderBuilder& cylinders() const { return cylinders_; }
  const derive::ParameterWrites& query_answers() const { return query_answers_; }
  // What a query module asking for `quantity` is told.
  static Vec3 quantity(const TurtleState& turtle, command::Quantity quantity);
  // The radius of a circle or sphere of `radius` (none: half the width).
  static float radius(const TurtleState& turtle, const std::optional<float>& radius);

  // Execute a command (command.h says what each does); those that may be
  // ignored, or have more to tell than the turtle shows, say what they did.
  // The few that every plant repeats millions of times are defined here, so
  // that the decoders' switches run them without a call.
  void run(const command::Note& c);
  void run(const command::Push&) {
    stack_.push_back(state_);
    tropisms_.push();
  }
  CommandResult run(const command::Pop&);
  CommandResult run(const command::Forward& c);
  CommandResult run(const command::MoveTo& c);
  CommandResult run(const command::LineTo& c);
  CommandResult run(const command::Line& c);
  void run(const command::SetCoordinateSystem& c);
  void run(const command::Turn& c) {
    float cosine, sine;
    angles_.get(c.degrees, &cosine, &sine);
    Frame& f = state_.frame;
    switch (c.axis) {
      case command::Axis::Up: f.rotate_up(cosine, sine); break;
      case command::Axis::Left: f.rotate_left(cosine, sine); break;
      case command::Axis::Heading: f.rotate_heading(cosine, sine); break;
    }
  }
  void run(const command::TurnAround&);
  CommandResult run(const command::RollToVertical&);
  CommandResult run(const command::Rotate& c);
  CommandResult run(const command::SetHeadUp& c);
  CommandResult run(const command::SetHeading& c);
  CommandResult run(const command::MinimizeTwist&);
  void run(const command::ForceTwist&);
  void run(const command::SetWidth& c) { state_.width = c.width; }
  void run(const command::StepWidth& c);
  void run(const command::SetColor& c) { (c.back_side ? state_.back_color : state_.color) = c.index; }
  void run(const command::StepColor& c);
  void run(const command::SetScale& c);
  void run(const command::MultiplyScale& c);
  void run(const command::DivideScale& c);
  void run(const command::CallSubLsystem& c);
  void run(const command::ReturnFromSubLsystem&);
  void run(const command::Circle& c);
  void run(const command::Sphere& c);
  CommandResult run(const command::Rhombus& c);
  CommandResult run(const command::Triangle& c);
  CommandResult run(const command::Surface& c);
  CommandResult run(const command::Mesh& c);
  void run(const command::SurfacePrecision& c);
  void run(const command::StartLsystemSurface&);
  void run(const command::LsystemSurfacePoint& c);
  CommandResult run(const command::DrawLsystemSurface&);
  CommandResult run(const command::BezierPatch& c);
  void run(const command::Label& c);
  void run(const command::Camera&);
  CommandResult run(const command::StartPolygon&);
  CommandResult run(const command::PolygonVertex&);
  CommandResult run(const command::EndPolygon& c);
  CommandResult run(const command::StartCylinder& c);
  CommandResult run(const command::CylinderPoint& c);
  CommandResult run(const command::CylinderDot& c);
  CommandResult run(const command::EndCylinder& c);
  CommandResult run(const command::CloseCylinder& c);
  void run(const command::SetContour& c);
  void run(const command::ScaleContour& c);
  CommandResult run(const command::ContourSides& c);
  void run(const command::CylinderTangents& c);
  void run(const command::RadiusTangents& c);
  void run(const command::RadiusAdjust& c);
  void run(const command::SetTexture& c);
  void run(const command::TextureVCoeff& c);
  CommandResult run(const command::SetElasticity& c);
  void run(const command::SimpleElasticity& c);
  void run(const command::Query& c);

 private:
  // A drawn line with the turtle's width, colour and up vector.
  void add_segment(Vec3 from, Vec3 to);
  // Point `p` in the coordinates `coordinates` (command::Coordinates), in the world.
  Vec3 to_world(Vec3 p, command::Coordinates coordinates) const;
  CommandResult move_to(Vec3 target);
  CommandResult line(Vec3 from, Vec3 to);

  const TurtleSettings& settings_;
  geometry::Scene* scene_;
  TurtleState state_;
  std::vector<TurtleState> stack_;
  // cpfg's ?(label,s): the scales to go back to at each open call's $.
  std::vector<float> sub_lsystem_scales_;
  geometry::Provenance from_;
  bool in_string_ = true;
  AngleCache angles_;
  Tropisms tropisms_;
  PolygonBuilder polygons_;
  CylinderBuilder cylinders_;
  ShapeDrawer shapes_;
  // What the query modules in the string receive (written after the walk).
  derive::ParameterWrites query_answers_;
};

}  // namespace sylva::turtle
