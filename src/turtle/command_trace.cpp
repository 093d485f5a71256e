// What the trace tells of each command after the module's text: the one
// place that formats commands.
#include <string>

#include "turtle/dispatcher.h"
#include "turtle/trace.h"

namespace sylva::turtle {
namespace {

using namespace command;

class CommandText {
 public:
  CommandText(std::string& out, const CommandResult& result, const CommandDispatcher& turtle)
      : out_(out), r_(result), turtle_(turtle), state_(turtle.state()) {}

  // Rotations end with the frame, even when ignored.
  void operator()(const Turn&) { frame(); }
  void operator()(const TurnAround&) { frame(); }
  void operator()(const RollToVertical&) { frame(); }
  void operator()(const Rotate&) { frame(); }
  void operator()(const SetHeadUp&) { frame(); }
  void operator()(const SetHeading&) { frame(); }
  void operator()(const MinimizeTwist&) { frame(); }
  void operator()(const Note& c) {
    out_ += c.text;
    if (c.shows_frame) frame();
  }

  // The other commands tell nothing more when ignored (their note says why).
  template <class Command>
  void operator()(const Command& c) {
    if (r_.note) return;
    done(c);
  }

 private:
  void frame() {
    vector(" H ", state_.frame.heading);
    vector(" L ", state_.frame.left);
    vector(" U ", state_.frame.up);
  }
  void vector(const char* text, Vec3 v) {
    out_ += text;
    append_vector(out_, v);
  }
  void at() { vector(" at ", state_.position); }
  void number(const char* text, int n) {
    out_ += text;
    out_ += std::to_string(n);
  }
  void moved() {
    vector(" from ", r_.from);
    vector(" to ", r_.to);
  }
  void triangles() {
    if (r_.triangles < 0) return;
    out_ += ", " + std::to_string(r_.triangles) + " triangles";
  }
  void closed_cylinder() {
    if (r_.closed_rings < 0) return;
    out_ += " cylinder of " + std::to_string(r_.closed_rings) + " rings x " + std::to_string(r_.closed_sides) + " sides";
  }
  void depth() { number(" depth ", static_cast<int>(turtle_.depth())); }
  void back_colour(bool back_side) {
    if (back_side) number(" back colour ", state_.back_color);
  }

  void done(const Push&) { depth(); }
  void done(const Pop&) {
    closed_cylinder();
    depth();
    at();
  }
  void done(const Forward&) {
    moved();
    if (r_.polygon > 0) number(" vertex ", r_.polygon);
    if (r_.cylinder_point > 0) number(" point ", r_.cylinder_point);
  }
  void done(const MoveTo&) { moved(); }
  void done(const LineTo&) { moved(); }
  void done(const Line&) { moved(); }
  void done(const SetCoordinateSystem&) { vector(" origin ", state_.origin); }
  void done(const SetColor& c) { back_colour(c.back_side); }
  void done(const StepColor& c) { back_colour(c.back_side); }
  void done(const Circle& c) { round_shape(c.radius); }
  void done(const Sphere& c) { round_shape(c.radius); }
  void round_shape(const std::optional<float>& radius) {
    at();
    out_ += " radius ";
    append_number(out_, CommandDispatcher::radius(state_, radius));
  }
  void done(const Rhombus&) { shape(); }
  void done(const Triangle&) { shape(); }
  void done(const BezierPatch&) { shape(); }
  void done(const Camera&) { at(); }
  void shape() {
    at();
    triangles();
  }
  void done(const Surface&) { named_shape(); }
  void done(const Mesh&) { named_shape(); }
  void named_shape() {
    out_ += " \"";
    out_ += r_.name;
    out_ += '"';
    shape();
  }
  void done(const LsystemSurfacePoint&) { vector(" = ", state_.position); }
  void done(const DrawLsystemSurface&) { triangles(); }
  void done(const Label& c) {
    if (c.shown) {
      out_ += " \"";
      out_ += c.text;
      out_ += '"';
    }
    at();
  }
  void done(const StartPolygon&) { number(" polygon depth ", r_.polygon); }
  void done(const PolygonVertex&) { number(" vertex ", r_.polygon); }
  void done(const EndPolygon&) {
    out_ += " polygon of " + std::to_string(r_.polygon) + " vertices";
    triangles();
  }
  void done(const StartCylinder& c) {
    if (c.unknown_type) out_ += " (unknown cylinder type; 1 used)";
    closed_cylinder();
    if (c.type > 0) number(" type ", c.type);
    at();
  }
  void done(const CylinderPoint&) {
    number(" point ", r_.cylinder_point);
    at();
  }
  void done(const CylinderDot&) {
    if (r_.strips_only) return number(" strips of point ", r_.cylinder_point);
    number(" point ", r_.cylinder_point);
    at();
  }
  void done(const EndCylinder& c) {
    if (r_.opened_type > 0 && c.type > 0 && c.type != r_.opened_type)
      out_ += " (type " + std::to_string(c.type) + " does not match {(" + std::to_string(r_.opened_type) + "))";
    closed_cylinder();
  }
  void done(const CloseCylinder&) { closed_cylinder(); }
  void done(const SetElasticity&) {
    out_ += " elasticity ";
    append_number(out_, r_.elasticity);
  }
  void done(const Query& c) {
    out_ += turtle_.in_string() ? " = " : " not in the string: ";
    append_vector(out_, CommandDispatcher::quantity(state_, c.quantity));
  }
  // The rest change the turtle's settings only.
  template <class Command>
  void done(const Command&) {}

  std::string& out_;
  const CommandResult& r_;
  const CommandDispatcher& turtle_;
  const TurtleState& state_;
};

}  // namespace

void append_command(std::string& out, const TurtleCommand& command, const CommandResult& result,
                    const CommandDispatcher& turtle) {
  if (result.note) out += result.note;
  std::visit(CommandText(out, result, turtle), command);
}

}  // namespace sylva::turtle
