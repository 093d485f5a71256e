// Widths, colours, circles, spheres, polygons, rhombi, triangles, surfaces,
// meshes and labels (LPFG manual 5.3, 5.5-5.7, 5.10, 5.14). Expected values
// are worked out by hand; the initial frame is H = (0,1,0), L = (-1,0,0),
// U = (0,0,1).
#include "turtle/turtle_fixture.h"

#include "support/diagnostic.h"

namespace sylva::test::turtle_tests {
namespace {

using geometry::TriangleGroup;

// Widths and colours as the segments get them; invalid values are ignored;
// the colour index wraps within 1..255.
TEST(TurtleDisplay, WidthsAndColours) {
  turtle::TurtleSettings settings;
  settings.initial_width = 2;
  settings.initial_color = 7;
  Scene s = draw("display",
                 "F(1) SetWidth(0.5) SetColor(3) F(1) IncColor F(1) DecColor DecColor F(1) SetColor(0) "
                 "SetWidth(-1) F(1) SetColor(255) IncColor F(1) DecColor F(1)",
                 settings);
  ASSERT_EQ(s.segments.size(), 7u);
  const float widths[] = {2, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
  const int colors[] = {7, 3, 4, 2, 2, 1, 255};
  for (std::size_t k = 0; k < 7; ++k) {
    EXPECT_FLOAT_EQ(s.segments[k].start_width, widths[k]) << k;
    EXPECT_FLOAT_EQ(s.segments[k].end_width, widths[k]) << k;
    EXPECT_EQ(s.segments[k].color, colors[k]) << k;
  }
}

// Circle0 and Sphere0 have the width as diameter; Circle(r), CircleFront(r)
// and Sphere(r) a radius; the B circles an outline as wide as the line.
TEST(TurtleDisplay, CirclesAndSpheres) {
  Scene s = draw("circles",
                 "SetWidth(0.4) Circle0 F(1) Circle(1.5) CircleFront(2) CircleFront0 CircleB(1) CircleFrontB(3) "
                 "SetColor(4) Sphere0 Sphere(3)");
  ASSERT_EQ(s.circles.size(), 6u);
  EXPECT_FLOAT_EQ(s.circles[0].radius, 0.2f);
  expect_near(s.circles[0].center, {0, 0, 0});
  expect_near(s.circles[0].normal, {0, 0, 1});
  EXPECT_FALSE(s.circles[0].facing_viewer);
  EXPECT_FLOAT_EQ(s.circles[1].radius, 1.5f);
  expect_near(s.circles[1].center, {0, 1, 0});
  EXPECT_TRUE(s.circles[2].facing_viewer);
  EXPECT_FLOAT_EQ(s.circles[2].radius, 2);
  EXPECT_FLOAT_EQ(s.circles[3].radius, 0.2f);
  EXPECT_TRUE(s.circles[3].facing_viewer);
  EXPECT_FLOAT_EQ(s.circles[4].outline, 0.4f);
  EXPECT_FALSE(s.circles[4].facing_viewer);
  EXPECT_FLOAT_EQ(s.circles[5].outline, 0.4f);
  EXPECT_TRUE(s.circles[5].facing_viewer);
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 0.2f);
  EXPECT_FLOAT_EQ(s.spheres[1].radius, 3);
  expect_near(s.spheres[1].center, {0, 1, 0});
  EXPECT_EQ(s.spheres[1].color, 4);
}

// The bounds of F(2) at width 1 and a sphere of radius 1 at (0,2,0):
// x, z within [-1, 1] (the sphere), y from -0.5 (the line's width) to 3.
TEST(TurtleDisplay, BoundingBox) {
  Scene s = draw("bounds", "F(2) Sphere(1)");
  geometry::Box b = s.bounds();
  expect_near(b.min, {-1, -0.5f, -1});
  expect_near(b.max, {1, 3, 1});
}

// A unit square by f moves: PP at the origin, then (0,1,0), (1,1,0),
// (1,0,0). Four vertices, two triangles, area 1, all facing U = (0,0,1).
TEST(TurtlePolygon, SquareFromMoves) {
  Scene s = draw("square", "SP PP f(1) Right(90) f(1) Right(90) f(1) EP");
  EXPECT_TRUE(s.segments.empty());
  ASSERT_EQ(s.groups.size(), 1u);
  const TriangleGroup& g = s.groups[0];
  EXPECT_EQ(g.kind, TriangleGroup::Kind::Polygon);
  EXPECT_EQ(s.positions.size(), 4u);
  EXPECT_EQ(g.index_count, 6u);
  EXPECT_NEAR(group_area(s, g), 1.0, 1e-5);
  for (std::uint32_t k = 0; k < 2; ++k) EXPECT_GT(triangle_normal(s, g, k).z, 0) << k;
  for (const Vec3& n : s.normals) expect_near(n, {0, 0, 1});
  EXPECT_EQ(g.from.module_index, 0u);  // the SP
}

// F both draws and records a vertex; G draws without recording. A square
// closed back onto its first point (as ABOP's leaves are) still makes two
// triangles: the repeated point is one vertex.
TEST(TurtlePolygon, ForwardRecordsVerticesAndClosingPointIsOne) {
  Scene s = draw("square-closed", "SP PP F(1) Right(90) F(1) Right(90) G(1) PP Right(90) f(1) EP");
  EXPECT_EQ(s.segments.size(), 3u);
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].index_count, 6u);
  EXPECT_NEAR(group_area(s, s.groups[0]), 1.0, 1e-5);
}

// A concave L-shape (0,0) (2,0) (2,1) (1,1) (1,2) (0,2): area 3, four
// triangles, none over the notch [1,2] x [1,2].
TEST(TurtlePolygon, ConcaveByEarClipping) {
  Scene s = draw("concave",
                 "SP PP MoveTo(2,0,0) PP MoveTo(2,1,0) PP MoveTo(1,1,0) PP MoveTo(1,2,0) PP MoveTo(0,2,0) PP EP");
  ASSERT_EQ(s.groups.size(), 1u);
  const TriangleGroup& g = s.groups[0];
  EXPECT_EQ(g.index_count, 12u);
  EXPECT_NEAR(group_area(s, g), 3.0, 1e-5);
  for (std::uint32_t k = 0; k < g.index_count; k += 3) {
    Vec3 c = (s.positions[s.indices[g.first_index + k]] + s.positions[s.indices[g.first_index + k + 1]] +
              s.positions[s.indices[g.first_index + k + 2]]) / 3;
    EXPECT_FALSE(c.x > 1 && c.y > 1) << "triangle " << k / 3 << " over the notch";
    EXPECT_GT(triangle_normal(s, g, k / 3).z, 0);
  }
}

// A square the other way round (counter-clockwise seen from U): the
// triangles face U all the same.
// With auto normals the normal comes from the first two edges instead:
// (0,1,0) then (-1,0,0) -> (0,1,0) x (-1,0,0) = (0,0,1).
TEST(TurtlePolygon, NormalsFromUpOrFromEdges) {
  Scene s = draw("square-left", "SP PP f(1) Left(90) f(1) Left(90) f(1) EP");
  ASSERT_EQ(s.groups.size(), 1u);
  for (std::uint32_t k = 0; k < 2; ++k) EXPECT_GT(triangle_normal(s, s.groups[0], k).z, 0);
  turtle::TurtleSettings settings;
  settings.auto_normals = true;
  Scene a = draw("square-left", "SP PP f(1) Left(90) f(1) Left(90) f(1) EP", settings);
  for (const Vec3& n : a.normals) expect_near(n, {0, 0, 1});
}

// Nested polygons, and one the string leaves open (drawn at the end).
// The outer polygon gets (0,0,0), (0,1,0), then - the inner polygon's moves
// being the inner one's vertices - (1,0,0) after the inner polygon's
// (0,1,0), (2,1,0), (2,0,0): a right triangle of area 1 inside, one of area
// 0.5 outside. The turtle then heads -x with L = (0,-1,0); the open polygon
// (1,0,0), (0,0,0), (0,-1,0) has area 0.5.
TEST(TurtlePolygon, NestedAndLeftOpen) {
  Scene s = draw("nested",
                 "SP PP f(1) SP PP Right(90) f(2) Right(90) f(1) EP Right(90) f(1) EP SP PP f(1) Left(90) f(1)");
  ASSERT_EQ(s.groups.size(), 3u);
  EXPECT_NEAR(group_area(s, s.groups[0]), 1.0, 1e-5);
  EXPECT_NEAR(group_area(s, s.groups[1]), 0.5, 1e-5);
  EXPECT_NEAR(group_area(s, s.groups[2]), 0.5, 1e-5);
}

// Rhombus(2, 1): corners (0,0,0), (0.5,1,0), (0,2,0), (-0.5,1,0): area 1.
// Triangle(2, 3): base (-1,0,0)..(1,0,0), apex (0,3,0): area 3.
TEST(TurtleShapes, RhombusAndTriangle) {
  Scene s = draw("rhombus", "Rhombus(2, 1) Triangle(2, 3)");
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[0].kind, TriangleGroup::Kind::Rhombus);
  EXPECT_EQ(s.groups[1].kind, TriangleGroup::Kind::Triangle);
  EXPECT_EQ(s.groups[0].index_count, 6u);
  EXPECT_EQ(s.groups[1].index_count, 3u);
  EXPECT_NEAR(group_area(s, s.groups[0]), 1.0, 1e-5);
  EXPECT_NEAR(group_area(s, s.groups[1]), 3.0, 1e-5);
  geometry::Box b = s.bounds();
  expect_near(b.min, {-1, 0, 0});
  expect_near(b.max, {1, 3, 0});
  EXPECT_GT(triangle_normal(s, s.groups[0], 0).z, 0);
  EXPECT_GT(triangle_normal(s, s.groups[1], 0).z, 0);
}

// A flat patch with control points (c/3, r/3, 0): corners (0,0,0), (1,0,0),
// (0,1,0), (1,1,0) in its own coordinates; its heading (0,1,0), up (0,0,1).
geometry::BezierSurface flat_surface() {
  geometry::BezierSurface s;
  s.name = "flat";
  geometry::BezierPatch p;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) p.points[static_cast<std::size_t>(4 * r + c)] = {c / 3.0f, r / 3.0f, 0};
  s.patches.push_back(p);
  s.u_divisions = 4;
  s.v_divisions = 2;
  return s;
}

// After F(1) Left(90): position (0,1,0), H = (-1,0,0), L = (0,-1,0).
// The surface's x goes to -L = (0,1,0), y to H, z to U, scaled by 2:
// corner (1,0,0) -> (0,3,0), (0,1,0) -> (-2,1,0), (1,1,0) -> (-2,3,0).
// 4 x 2 divisions: 5 x 3 vertices, 16 triangles, normals along U.
TEST(TurtleSurface, PlacedScaledAndTessellated) {
  std::vector<geometry::BezierSurface> surfaces = {flat_surface()};
  turtle::TurtleSettings settings;
  settings.surfaces = &surfaces;
  Scene s = draw("surface", "F(1) Left(90) Surface(0, 2)", settings);
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].kind, TriangleGroup::Kind::Surface);
  ASSERT_EQ(s.positions.size(), 15u);
  EXPECT_EQ(s.groups[0].index_count, 16u * 3);
  expect_near(s.positions[0], {0, 1, 0});    // u = 0, v = 0
  expect_near(s.positions[4], {0, 3, 0});    // u = 1, v = 0
  expect_near(s.positions[10], {-2, 1, 0});  // u = 0, v = 1
  expect_near(s.positions[14], {-2, 3, 0});  // u = 1, v = 1
  for (const Vec3& n : s.normals) expect_near(n, {0, 0, 1});
  EXPECT_NEAR(group_area(s, s.groups[0]), 4.0, 1e-4);
  EXPECT_GT(triangle_normal(s, s.groups[0], 0).z, 0);
}

// Surface3 scales the surface's own axes: x by 1, y by 2 at the initial
// frame puts corner (1,1,0) at (1,2,0). The contact point (0.5,0,0) goes to
// the turtle, and size 2 halves everything: (1,0,0) -> (0.25,0,0).
// SetUPrecision / SetVPrecision override the divisions: 3 x 4 vertices.
TEST(TurtleSurface, PerAxisScaleContactSizeAndPrecision) {
  std::vector<geometry::BezierSurface> surfaces = {flat_surface(), flat_surface()};
  surfaces[1].contact = {0.5f, 0, 0};
  surfaces[1].size = 2;
  turtle::TurtleSettings settings;
  settings.surfaces = &surfaces;
  Scene s = draw("surface3", "Surface3(0, 1, 2, 3) SetUPrecision(2) SetVPrecision(3) Surface(1, 1)", settings);
  ASSERT_EQ(s.groups.size(), 2u);
  expect_near(s.positions[14], {1, 2, 0});
  ASSERT_EQ(s.positions.size(), 15u + 12u);
  expect_near(s.positions[15], {-0.25f, 0, 0});
  expect_near(s.positions[17], {0.25f, 0, 0});
  expect_near(s.positions[26], {0.25f, 0.5f, 0});
}

TEST(TurtleSurface, UnknownIdIsAClearError) {
  std::vector<geometry::BezierSurface> surfaces = {flat_surface()};
  turtle::TurtleSettings settings;
  settings.surfaces = &surfaces;
  try {
    draw("surface-missing", "F(1) Surface(5, 1)", settings);
    FAIL() << "expected a ModelError";
  } catch (const ModelError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Surface(5"), std::string::npos) << what;
    EXPECT_NE(what.find("no surface 5"), std::string::npos) << what;
    EXPECT_NE(what.find("module 1 of the string"), std::string::npos) << what;
  }
  EXPECT_THROW(draw("surface-none", "Surface(0, 1)"), ModelError);
}

// DSurface: the model's own 16 points (c/3, r/3, 0), at the turtle with the
// initial frame: corners where the points say. After Right(90) (H = (1,0,0),
// L = (0,1,0)) the x axis goes to -L = (0,-1,0) and y to H: corner (1,1,0)
// lands at (1,-1,0).
TEST(TurtleSurface, DynamicSurface) {
  const std::string flat =
      "SurfaceObj Flat() { SurfaceObj s; for (int r = 0; r < 4; ++r) for (int c = 0; c < 4; ++c) "
      "s.Set(4 * r + c, V3f(c / 3.0f, r / 3.0f, 0)); return s; }";
  Scene s = draw("dsurface", "DSurface(Flat()) Right(90) DSurface(Flat())", {}, nullptr, flat);
  ASSERT_EQ(s.groups.size(), 2u);
  // 8 x 8 divisions by default: 81 vertices each.
  ASSERT_EQ(s.positions.size(), 162u);
  expect_near(s.positions[0], {0, 0, 0});
  expect_near(s.positions[80], {1, 1, 0});
  expect_near(s.positions[81 + 80], {1, -1, 0});
}

// The L-system-defined surface: control point (r, c) at the turtle's
// position (c, r, 0) / 3 by MoveTo; drawn where the points are.
TEST(TurtleSurface, LsystemDefinedSurface) {
  std::string axiom = "InitSurface(0)";
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      axiom += " MoveTo(" + std::to_string(c) + "/3.0," + std::to_string(r) + "/3.0,1) SurfacePoint(0," +
               std::to_string(r) + "," + std::to_string(c) + ")";
  axiom += " SetUPrecision(1) SetVPrecision(1) DrawSurface(0)";
  Scene s = draw("lsurface", axiom);
  ASSERT_EQ(s.groups.size(), 1u);
  ASSERT_EQ(s.positions.size(), 4u);
  expect_near(s.positions[0], {0, 0, 1});
  expect_near(s.positions[1], {1, 0, 1});
  expect_near(s.positions[2], {0, 1, 1});
  expect_near(s.positions[3], {1, 1, 1});
  EXPECT_THROW(draw("lsurface-bad", "SurfacePoint(0, 4, 0)"), ModelError);
}

// A predefined mesh, one triangle (0,0,0) (1,0,0) (0,1,0), drawn by
// Mesh(0, 2) after Right(90): x to -L = (0,-1,0), y to H = (1,0,0), so
// (0,-2,0) and (2,0,0); the normal from the face is U = (0,0,1).
TEST(TurtleShapes, PredefinedMesh) {
  std::vector<geometry::PredefinedMesh> meshes(1);
  meshes[0].positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  meshes[0].indices = {0, 1, 2};
  turtle::TurtleSettings settings;
  settings.meshes = &meshes;
  Scene s = draw("mesh", "Right(90) Mesh(0, 2)", settings);
  ASSERT_EQ(s.groups.size(), 1u);
  EXPECT_EQ(s.groups[0].kind, TriangleGroup::Kind::Mesh);
  expect_near(s.positions[0], {0, 0, 0});
  expect_near(s.positions[1], {0, -2, 0});
  expect_near(s.positions[2], {2, 0, 0});
  for (const Vec3& n : s.normals) expect_near(n, {0, 0, 1});
  EXPECT_THROW(draw("mesh", "Right(90) Mesh(1, 2)", settings), ModelError);
}

TEST(TurtleShapes, LabelAndCamera) {
  Scene s = draw("label", "F(2) SetColor(6) Label(\"apex\") Right(90) Camera F(1)");
  ASSERT_EQ(s.labels.size(), 1u);
  EXPECT_EQ(s.labels[0].text, "apex");
  EXPECT_EQ(s.labels[0].color, 6);
  expect_near(s.labels[0].position, {0, 2, 0});
  ASSERT_TRUE(s.camera.has_value());
  expect_near(s.camera->position, {0, 2, 0});
  expect_near(s.camera->heading, {1, 0, 0});
  expect_near(s.camera->up, {0, 0, 1});
}

}  // namespace
}  // namespace sylva::test::turtle_tests
