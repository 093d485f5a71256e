// The turtle's shapes other than lines, polygons and generalized cylinders:
// circles, spheres, rhombi, triangles, the view file's Bézier surfaces and
// meshes, patches given by modules, the L-system-defined surface and labels,
// each drawn at the turtle into the Scene.
#pragma once

#include <string>

#include "geometry/placement.h"
#include "geometry/scene.h"
#include "geometry/surface.h"
#include "turtle/turtle_settings.h"
#include "turtle/turtle_state.h"

namespace sylva::turtle {

class ShapeDrawer {
 public:
  // `scene` may be null: nothing is drawn, but errors are found as when drawing.
  ShapeDrawer(const TurtleSettings& settings, geometry::Scene* scene) : settings_(settings), scene_(scene) {}

  // The shapes drawing triangles return how many (-1: no Scene).
  void circle(const TurtleState& turtle, geometry::Provenance from, float radius, float outline, bool facing_viewer);
  void sphere(const TurtleState& turtle, geometry::Provenance from, float radius);
  // A convex shape in the HL plane, corners counter-clockwise around U.
  int flat_shape(const TurtleState& turtle, geometry::Provenance from, geometry::TriangleGroup::Kind kind,
                 const Vec3* corners, int count);
  // The view file's surface or mesh `id`, scaled by `scale`; `module`
  // names the module in the error thrown when there is no such one.
  // `name` receives the surface's or mesh's name.
  int surface(const TurtleState& turtle, geometry::Provenance from, int id, Vec3 scale, const char* module,
              bool view_texture_first, const char*& name);
  int mesh(const TurtleState& turtle, geometry::Provenance from, int id, Vec3 scale, const char* module,
           const char*& name);
  // 16 control points (12 bytes each) in the turtle's frame.
  int bezier_patch(const TurtleState& turtle, geometry::Provenance from, const unsigned char* points);
  void start_lsystem_surface() { lsystem_surface_ = geometry::BezierPatch{}; }
  void lsystem_surface_point(const TurtleState& turtle, geometry::Provenance from, int row, int column);
  int draw_lsystem_surface(const TurtleState& turtle, geometry::Provenance from);
  void label(const TurtleState& turtle, geometry::Provenance from, std::string text);

 private:
  geometry::Placement placement(const TurtleState& turtle, Vec3 local_heading, Vec3 local_up, Vec3 contact,
                                Vec3 scale) const;
  // Throws a ModelError naming the module unless 0 <= id < count.
  static void require_view_file_id(const char* module, geometry::Provenance from, const char* kind, const char* kinds,
                                   int id, std::size_t count);

  const TurtleSettings& settings_;
  geometry::Scene* scene_;
  // The L-system-defined surface (InitSurface, SurfacePoint, DrawSurface).
  geometry::BezierPatch lsystem_surface_;
};

}  // namespace sylva::turtle
