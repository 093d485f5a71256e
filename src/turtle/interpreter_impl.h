// The turtle's working state, shared by the files that implement it:
// interpreter.cpp (dispatch, moves, rotations, the stack, query modules),
// shapes.cpp (circles, polygons, surfaces, meshes) and cylinders.cpp
// (generalized cylinders).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "geometry/contour.h"
#include "geometry/placement.h"
#include "geometry/scene.h"
#include "geometry/surface.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/frame.h"
#include "turtle/interpreter.h"
#include "turtle/turtle_settings.h"
#include "turtle/turtle_state.h"

namespace sylva::turtle {

using geometry::Provenance;
using geometry::Scene;

// Points closer than this are the same point (LPFG manual 5.1).
inline constexpr float kEpsilon = 1e-5f;

struct TurtleInterpreter::Impl {
  Impl(const TurtleSettings& settings, const ModuleTypes& types, Scene* scene, std::string* trace);

  void visit(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string);
  // ---- cpfg_symbols.cpp: a cpfg model's modules, through its symbol table.
  void visit_cpfg(ModuleId id, const unsigned char* params, std::uint32_t source_index, bool in_string);
  void query_cpfg(int count, Vec3 value, bool in_string);
  void finish();

  // ---- interpreter.cpp
  void forward(float distance, bool draw, bool polygon_vertex);
  void move_to(Vec3 target);
  // A drawn line with the turtle's width, colour and up vector.
  void add_segment(Vec3 from, Vec3 to);
  void line(Vec3 from, Vec3 to);
  Vec3 to_world(Vec3 p) const;
  Vec3 to_world_offset(Vec3 d) const;
  void turn(float degrees, int axis);  // 0: around U, 1: around L, 2: around H
  void push();
  void pop();
  void apply_tropisms();
  void change_elasticity(int id, float value, bool relative);
  void update_bending();  // bending_ from elasticity_
  void query(Vec3 value, bool in_string);
  void note(const char* text);
  // " (module N of the string)", for errors.
  std::string where() const;
  void note_position(const char* text, Vec3 p);

  // ---- shapes.cpp
  void circle(float radius, float outline, bool facing_viewer);
  void sphere(float radius);
  void start_polygon();
  void polygon_vertex();
  void end_polygon();
  void draw_polygon(std::size_t first, const Frame& first_frame);
  // cpfg's texture coordinates of a polygon's `count` vertices from `base`.
  void texture_polygon(std::uint32_t base, std::size_t count, const Frame& first_frame);
  void flat_shape(geometry::TriangleGroup::Kind kind, const Vec3* corners, int count);
  // Throws a ModelError naming the module unless 0 <= id < count (surfaces, meshes of the view file).
  void require_view_file_id(const char* module, const char* kind, const char* kinds, int id,
                            std::size_t count) const;
  void surface(int id, Vec3 scale, const char* module);
  void mesh(int id, Vec3 scale, const char* module);
  void dynamic_surface(const unsigned char* params);
  void surface_point(int row, int column);
  void draw_lsystem_surface();
  void label(const unsigned char* params);
  // A label with the turtle's position and colour.
  void add_label(std::string text);
  geometry::Placement placement(Vec3 local_heading, Vec3 local_up, Vec3 contact, Vec3 scale) const;
  void begin_group();
  // The group takes group_texture_ (then reset to none).
  void end_group(geometry::TriangleGroup::Kind kind);
  int group_texture_ = -1;

  // ---- cylinders.cpp
  void check_contour(int id, const char* module) const;
  const geometry::Contour& contour(int id) const;
  const Vec3* contour_points(int id, int blend_id, float blend, int sides);
  struct CylinderPoint;
  CylinderPoint control_point(int strips) const;
  // `type` 0: @Gs or StartGC, whose start is the first control point;
  // 1..4: cpfg's {(type) (CPFG manual 6.7.3), which defines no point, adds
  // one after each F and f, and whose type 2 and 4 close the axis and 3 and
  // 4 make it a uniform cubic B-spline.
  void start_cylinder(int type = 0);
  // `strips`: the bands between this control point and the previous one
  // (cpfg's @Gc(strips), .(strips), @Ge(strips)); L+C's are always 1.
  void cylinder_point(int strips = 1);
  // cpfg's .(strips) in a {(type) cylinder: a point, or the strips of the
  // last one when the turtle has not moved since.
  void cylinder_dot(int strips);
  // The point after an F or f in a {(type) cylinder (4 strips).
  void cylinder_step_point();
  // `type`: }(type)'s, checked against {(type)'s; 0 for @Ge and EndGC.
  void end_cylinder(int strips = 1, int type = 0);
  bool cylinder_open(const TurtleState& s) const;
  void close_cylinder(int index);
  void draw_cylinder(int index);

  const TurtleSettings& settings_;
  const ModuleTypes& types_;
  // A cpfg model's symbol table (the settings' own, or built here); null for L+C.
  std::shared_ptr<const CpfgSymbols> cpfg_;
  // A cpfg command read a character a module (@ G c(3)): the characters so far.
  std::string cpfg_pending_;
  Scene* scene_;
  std::string* trace_;
  // What the query modules in the string receive (written after the walk).
  derive::ParameterWrites query_answers_;

  TurtleState state_;
  std::vector<TurtleState> stack_;
  // cpfg's ?(label,s): the scales to go back to at each open call's $.
  std::vector<float> sub_lsystem_scales_;
  Provenance from_;  // the module being interpreted
  AngleCache angles_;

  // Elasticities of the view file's tropisms (ids 1..n at 0..n-1) and of the
  // simple tropism (at n); saved with the state at SB.
  std::vector<float> elasticity_;
  std::vector<float> saved_elasticity_;
  bool bending_ = false;  // some elasticity is not zero

  // Open polygons (SP ... EP nest); their vertices, with the turtle's up at
  // each, in one pool.
  struct OpenPolygon {
    std::size_t first = 0;
    Provenance from;
    Frame first_frame;  // the turtle's at the first vertex (cpfg's texture axes)
  };
  std::vector<OpenPolygon> polygons_;
  std::vector<Vec3> polygon_points_, polygon_ups_;
  std::vector<std::uint32_t> triangles_, triangulation_work_;
  std::size_t group_first_index_ = 0;

  // Generalized cylinders: slots reused once drawn, so their point vectors
  // keep their capacity.
  struct CylinderPoint {
    Vec3 position;
    Frame frame;
    float width = 1;
    int contour = 0, blend_contour = 0;
    float blend = 0;
    float scale_left = 1, scale_up = 1;
    int color = 1, back_color = -1;
    Provenance from;
    // The stretch from the previous control point to this one: its bands
    // (rings at the Hermite parameters k / strips) and tangent coefficients.
    int strips = 1;
    float tangent_start = 1.2f, tangent_end = 1.2f;
    geometry::RadiusTangents radius_tangents;
  };
  struct Cylinder {
    std::vector<CylinderPoint> points;
    int sides = 8;
    int type = 0;  // as start_cylinder's
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

  // The L-system-defined surface (InitSurface, SurfacePoint, DrawSurface).
  geometry::BezierPatch lsystem_surface_;
};

}  // namespace sylva::turtle
