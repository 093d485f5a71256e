// Generalized cylinders (LPFG manual 5.8, CPFG manual 6.7.3): StartGC,
// PointGC and EndGC (cpfg's @Gs @Gc @Ge, {(t) .(s) }(t)) record control
// points (the turtle's position, frame, width and contour at each); the
// cylinder is drawn when it ends (cylinder_builder.cpp says how).
//
// A turtle state names the cylinder its branch adds to (TurtleState::cylinder
// and cylinder_serial); a state saved on the stack may name one that has
// ended since, and whose slot another cylinder reuses.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "geometry/contour.h"
#include "geometry/scene.h"
#include "turtle/frame.h"
#include "turtle/turtle_settings.h"
#include "turtle/turtle_state.h"

namespace sylva::turtle {

class CylinderBuilder {
 public:
  CylinderBuilder(const TurtleSettings& settings, geometry::Scene* scene);

  // Throws a ModelError naming `module` unless contour `id` is the circle (0)
  // or one of the contour files'.
  void check_contour(int id, const char* module, geometry::Provenance from) const;

  // Whether `state`'s cylinder is still open.
  bool open(const TurtleState& state) const {
    if (state.cylinder < 0) return false;
    const Cylinder& c = cylinders_[static_cast<std::size_t>(state.cylinder)];
    return c.open && c.serial == state.cylinder_serial;
  }

  // A cylinder that ended: its rings and sides (rings -1: none ended).
  struct Closed {
    int rings = -1, sides = 0;
  };
  // Starts a cylinder of `type` (as command::StartCylinder's) that `state`
  // adds to from now on. One cylinder at a time per branch: the branch's
  // own open cylinder ends first; one it shares with `parent` (the state
  // its branch started from, if any) stays open.
  Closed start(TurtleState& state, const TurtleState* parent, int type, geometry::Provenance from);
  // Adds a control point (`strips` bands from the previous one); returns its
  // number, 0 when `state` has no open cylinder.
  int add_point(const TurtleState& state, geometry::Provenance from, int strips);
  // cpfg's .(strips): a control point, or the strips of the last one where
  // the turtle has not moved since it (then `strips_only`).
  struct Dot {
    int point = 0;  // 0: no open cylinder
    bool strips_only = false;
  };
  Dot dot(const TurtleState& state, geometry::Provenance from, int strips);
  // The control point after an F or f in a {(type) cylinder; returns its
  // number, 0 when none is added.
  int step_point(const TurtleState& state, geometry::Provenance from);
  // Ends `state`'s cylinder (which must be open) with a last point;
  // `type`: }(type)'s, 0 for EndGC and @Ge.
  struct Ended {
    Closed closed;
    int opened_type = 0;  // the ended cylinder's own type
  };
  Ended end(TurtleState& state, geometry::Provenance from, int strips, int type);
  // The end of a branch: `state`'s cylinder ends unless `saved` (the state
  // the branch goes back to) adds to it too; `saved` forgets a cylinder
  // that has ended.
  Closed end_branch(const TurtleState& state, TurtleState& saved) {
    Closed closed;
    if (open(state) && (state.cylinder != saved.cylinder || state.cylinder_serial != saved.cylinder_serial))
      closed = close(state.cylinder);
    if (saved.cylinder >= 0 && !open(saved)) saved.cylinder = -1;
    return closed;
  }
  // The slots, for closing what the string left open.
  int slots() const { return static_cast<int>(cylinders_.size()); }
  bool slot_open(int slot) const { return cylinders_[static_cast<std::size_t>(slot)].open; }
  Closed close(int slot);

 private:
  struct ControlPoint {
    Vec3 position;
    Frame frame;
    float width = 1;
    int contour = 0, blend_contour = 0;
    float blend = 0;
    float scale_left = 1, scale_up = 1;
    int color = 1, back_color = -1;
    geometry::Provenance from;
    // The stretch from the previous control point to this one: its bands
    // (rings at the Hermite parameters k / strips) and tangent coefficients.
    int strips = 1;
    float tangent_start = 1.2f, tangent_end = 1.2f;
    geometry::RadiusTangents radius_tangents;
  };
  static ControlPoint control_point(const TurtleState& state, geometry::Provenance from, int strips);

  const geometry::Contour& contour(int id) const;
  const Vec3* contour_points(int id, int blend_id, float blend, int sides);
  void draw(int slot);

  const TurtleSettings& settings_;
  geometry::Scene* scene_;

  // Slots reused once drawn, so their point vectors keep their capacity.
  struct Cylinder {
    std::vector<ControlPoint> points;
    int sides = 8;
    int type = 0;  // as command::StartCylinder's
    bool open = false;
    std::uint32_t serial = 0;
  };
  std::vector<Cylinder> cylinders_;
  std::uint32_t next_serial_ = 1;
  struct ResampledContour {
    int id = 0;
    int sides = 0;
    std::vector<Vec3> points;
  };
  std::deque<ResampledContour> resampled_;  // references stay valid as it grows
  std::vector<Vec3> blended_;
  std::vector<Vec3> ring_from_, ring_to_, ring_between_;  // contours of a stretch's inner rings
  std::vector<Frame> stretch_frames_;  // a stretch's frames, carried along its curve
};

}  // namespace sylva::turtle
