// The one executor of turtle commands (command.h), whichever language they
// were decoded from: it keeps the turtle's state and stack, moves, turns and
// draws lines itself, and hands polygons, generalized cylinders and other
// shapes to their builders.
#pragma once

#include <cstddef>
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
  CommandResult execute(const TurtleCommand& command);

  const TurtleState& state() const { return state_; }
  std::size_t depth() const { return stack_.size(); }
  bool in_string() const { return in_string_; }
  bool polygon_open() const { return polygons_.any_open(); }
  const CylinderBuilder& cylinders() const { return cylinders_; }
  const derive::ParameterWrites& query_answers() const { return query_answers_; }

 private:
  CommandResult run(const command::Note& c);
  CommandResult run(const command::Push&);
  CommandResult run(const command::Pop&);
  CommandResult run(const command::Forward& c);
  CommandResult run(const command::MoveTo& c);
  CommandResult run(const command::LineTo& c);
  CommandResult run(const command::Line& c);
  CommandResult run(const command::SetCoordinateSystem& c);
  CommandResult run(const command::Turn& c);
  CommandResult run(const command::TurnAround&);
  CommandResult run(const command::RollToVertical&);
  CommandResult run(const command::Rotate& c);
  CommandResult run(const command::SetHeadUp& c);
  CommandResult run(const command::SetHeading& c);
  CommandResult run(const command::MinimizeTwist&);
  CommandResult run(const command::ForceTwist&);
  CommandResult run(const command::SetWidth& c);
  CommandResult run(const command::StepWidth& c);
  CommandResult run(const command::SetColor& c);
  CommandResult run(const command::StepColor& c);
  CommandResult run(const command::SetScale& c);
  CommandResult run(const command::MultiplyScale& c);
  CommandResult run(const command::DivideScale& c);
  CommandResult run(const command::CallSubLsystem& c);
  CommandResult run(const command::ReturnFromSubLsystem&);
  CommandResult run(const command::Circle& c);
  CommandResult run(const command::Sphere& c);
  CommandResult run(const command::Rhombus& c);
  CommandResult run(const command::Triangle& c);
  CommandResult run(const command::Surface& c);
  CommandResult run(const command::Mesh& c);
  CommandResult run(const command::SurfacePrecision& c);
  CommandResult run(const command::StartLsystemSurface&);
  CommandResult run(const command::LsystemSurfacePoint& c);
  CommandResult run(const command::DrawLsystemSurface&);
  CommandResult run(const command::BezierPatch& c);
  CommandResult run(const command::Label& c);
  CommandResult run(const command::Camera&);
  CommandResult run(const command::StartPolygon&);
  CommandResult run(const command::PolygonVertex&);
  CommandResult run(const command::EndPolygon& c);
  CommandResult run(const command::StartCylinder& c);
  CommandResult run(const command::CylinderPoint& c);
  CommandResult run(const command::CylinderDot& c);
  CommandResult run(const command::EndCylinder& c);
  CommandResult run(const command::CloseCylinder& c);
  CommandResult run(const command::SetContour& c);
  CommandResult run(const command::ScaleContour& c);
  CommandResult run(const command::ContourSides& c);
  CommandResult run(const command::CylinderTangents& c);
  CommandResult run(const command::RadiusTangents& c);
  CommandResult run(const command::RadiusAdjust& c);
  CommandResult run(const command::SetTexture& c);
  CommandResult run(const command::TextureVCoeff& c);
  CommandResult run(const command::SetElasticity& c);
  CommandResult run(const command::SimpleElasticity& c);
  CommandResult run(const command::Query& c);

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
