// Surfaces, curves and parameters a model changes or reads while it runs
// (LPFG manual 6.2, 7.1): GetSurface reshaped with SurfaceObj and drawn by
// DSurface; curveSetPoint, curveRecalculate, curveScale and curveReset
// changing what curveX returns and the generalized cylinders drawn with the
// contour; val reading a .vset file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "geometry/contour_edit.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using geometry::Vec3;

void expect_near(Vec3 actual, Vec3 expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
  EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
  EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

struct Run {
  std::string dir;
  std::string messages;
  std::unique_ptr<Simulation> simulation;
};

// `body` after #include <lpfgall.h>, with input files written beside it.
std::unique_ptr<Run> load(const std::string& name, const std::string& body,
                          const std::vector<std::pair<std::string, std::string>>& files) {
  auto run = std::make_unique<Run>();
  run->dir = make_temp_dir("dynamic-" + name);
  std::ofstream(run->dir + "/model.l") << "#include <lpfgall.h>\n" << body << "\n";
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  for (const auto& [file, text] : files) {
    std::ofstream(run->dir + "/" + file) << text;
    // Surfaces are named in the view file; the rest are given as inputs.
    if (!file.ends_with(".s")) options.input_files.push_back(run->dir + "/" + file);
  }
  Run* raw = run.get();
  run->simulation = std::make_unique<Simulation>(run->dir + "/model.l", options,
                                                 [raw](const std::string& text) { raw->messages += text; });
  return run;
}

// One patch, rows r = 0..3 of four columns c = 0..3 (point 4r + c).
const char* const kPatch =
    "-1 1 0 2 0 0\n"
    "CONTACT POINT  X: 0 Y: 0 Z: 0\n"
    "END POINT  X: 0 Y: 2 Z: 0\n"
    "HEADING  X: 0 Y: 1 Z: 0\n"
    "UP  X: 0 Y: 0 Z: 1\n"
    "SIZE: 2\n"
    "left\n"
    "TOP COLOR: 0 DIFFUSE: 0 BOTTOM COLOR: 0 DIFFUSE: 0\n"
    "AL: ~ A: ~ AR: ~\n"
    "L: ~ R: ~\n"
    "BL: ~ B: ~ BR: ~\n"
    "-1.0 0.0 0.0 -0.6 0.0 0.0 -0.3 0.0 0.0 0.0 0.0 0.0\n"
    "-1.0 0.7 0.1 -0.6 0.7 0.1 -0.3 0.7 0.1 0.0 0.7 0.0\n"
    "-1.0 1.3 0.1 -0.6 1.3 0.1 -0.3 1.3 0.1 0.0 1.3 0.0\n"
    "-1.0 2.0 0.0 -0.6 2.0 0.0 -0.3 2.0 0.0 0.0 2.0 0.0\n";

// GetSurface(0), scaled by (2, 1, 3), its last point set to (5, 6, 7), drawn
// by DSurface at the initial turtle (the patch's own coordinates) with 2 x 2
// divisions: a 3 x 3 grid whose middle vertex is the patch at u = v = 1/2,
// the sum of the points weighted (1/8, 3/8, 3/8, 1/8) along rows and
// columns:
//   x: columns -2, -1.2, -0.6, 0: -0.25 - 0.45 - 0.225 = -0.925; point 15's
//      x from 0 to 5 adds 5/64: -0.846875.
//   y: rows 0, 0.7, 1.3, 2: 0.2625 + 0.4875 + 0.25 = 1; point 15's y from 2
//      to 6 adds 4/64: 1.0625.
//   z: rows 1 and 2 have 0.3 (0.1 x 3) in columns 0..2: 2 x 3/8 x 7/8 x 0.3
//      = 0.196875; point 15's z from 0 to 7 adds 7/64: 0.30625.
// Then the same patch halfway between it and itself times 3 (young * 0.5 +
// mature * 0.5 with mature = young * 3): twice every point.
TEST(DynamicSurface, ReshapedPredefinedSurfaceIsDrawn) {
  auto run = load("surface",
                  "derivation length: 0;\n"
                  "module Leaf(float);\n"
                  "axiom: Leaf(1) Leaf(2);\n"
                  "interpretation:\n"
                  "Leaf(k) : {\n"
                  "  SurfaceObj s = GetSurface(0);\n"
                  "  s.Scale(V3f(2, 1, 3));\n"
                  "  s.Set(15, V3f(5, 6, 7));\n"
                  "  if (k == 2) { SurfaceObj mature = s * 3; s = s * 0.5f + 0.5f * mature; }\n"
                  "  produce SetUPrecision(2) SetVPrecision(2) DSurface(s);\n"
                  "}\n",
                  {{"view.v", "surface: flat.s\n"}, {"flat.s", kPatch}});
  run->simulation->run(0);
  geometry::Scene scene = run->simulation->scene();
  ASSERT_EQ(scene.groups.size(), 2u);
  ASSERT_EQ(scene.positions.size(), 18u);
  expect_near(scene.positions[0], {-2, 0, 0});
  expect_near(scene.positions[4], {-0.846875f, 1.0625f, 0.30625f});
  expect_near(scene.positions[8], {5, 6, 7});
  expect_near(scene.positions[9], {-4, 0, 0});
  expect_near(scene.positions[9 + 4], {-1.69375f, 2.125f, 0.6125f});
  expect_near(scene.positions[9 + 8], {10, 12, 14});
}

// A closed square contour, symmetric about its centre.
const char* const kSquare =
    "cver 1 1\n"
    "name: square\n"
    "points: 4 4\n"
    "1 1 0 1\n"
    "-1 1 0 1\n"
    "-1 -1 0 1\n"
    "1 -1 0 1\n"
    "type: cr\n";

// A B-spline is affine invariant and arc-length fractions survive uniform
// scaling, so a contour whose control points are all doubled is the same
// curve twice as large: curveX doubles (after curveRecalculate, not before),
// and so do the first ring's points of a cylinder starting at the origin.
TEST(DynamicCurve, ChangedContourReachesCurveFunctionsAndCylinders) {
  auto run = load("curve",
                  "derivation length: 3;\n"
                  "module A();\n"
                  "StartEach: {\n"
                  "  if (StepNo() == 1) {\n"
                  "    Printf(\"%.6f\\n\", curveX(1, 0.1f));\n"
                  "    curveSetPoint(1, 0, 2, 2, 0); curveSetPoint(1, 1, -2, 2, 0);\n"
                  "    curveSetPoint(1, 2, -2, -2, 0); curveSetPoint(1, 3, 2, -2, 0);\n"
                  "    Printf(\"%.6f\\n\", curveX(1, 0.1f));\n"
                  "    curveRecalculate(1);\n"
                  "    Printf(\"%.6f\\n\", curveX(1, 0.1f));\n"
                  "  }\n"
                  "  if (StepNo() == 2) { curveReset(1); curveScale(1, 3, 3, 3); Printf(\"%.6f\\n\", curveX(1, 0.1f)); }\n"
                  "  if (StepNo() == 3) { curveReset(1); Printf(\"%.6f\\n\", curveX(1, 0.1f)); }\n"
                  "}\n"
                  "axiom: ContourSides(8) CurrentContour(1) SetWidth(2) StartGC F(1) EndGC;\n",
                  {{"square.con", kSquare}});
  Simulation& d = *run->simulation;
  d.begin();
  const geometry::Scene original = run->simulation->scene();
  ASSERT_EQ(original.positions.size(), 16u);
  std::vector<geometry::Scene> scenes;
  for (int k = 0; k < 3; ++k) {
    d.step();
    scenes.push_back(run->simulation->scene());
  }
  const float factors[] = {2, 3, 1};
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(scenes[static_cast<std::size_t>(k)].positions.size(), 16u);
    for (std::size_t i = 0; i < 8; ++i)
      expect_near(scenes[static_cast<std::size_t>(k)].positions[i], original.positions[i] * factors[k]);
  }
  std::vector<double> printed;
  std::istringstream lines(run->messages);
  for (double v; lines >> v;) printed.push_back(v);
  ASSERT_EQ(printed.size(), 5u) << run->messages;
  EXPECT_GT(std::abs(printed[0]), 0.1);
  EXPECT_DOUBLE_EQ(printed[1], printed[0]);              // set, not yet recalculated
  EXPECT_NEAR(printed[2], 2 * printed[0], 2e-6);         // recalculated
  EXPECT_NEAR(printed[3], 3 * printed[0], 3e-6);         // reset, then scaled
  EXPECT_NEAR(printed[4], printed[0], 1e-6);             // reset
}

// curveSetPoint counts the file's control points: one of multiplicity 2 is
// two entries of the B-spline's points, moved together.
TEST(DynamicCurve, SetPointMovesEveryCopyOfAMultiplePoint) {
  geometry::Contour c;
  c.points = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  c.multiplicities = {1, 2, 1};
  ASSERT_TRUE(geometry::set_contour_point(c, 1, {5, 6, 7}));
  expect_near(c.points[1], {5, 6, 7});
  expect_near(c.points[2], {5, 6, 7});
  ASSERT_TRUE(geometry::set_contour_point(c, 2, {8, 8, 8}));
  expect_near(c.points[3], {8, 8, 8});
  expect_near(c.points[0], {0, 0, 0});
  EXPECT_FALSE(geometry::set_contour_point(c, 3, {0, 0, 0}));
  EXPECT_FALSE(geometry::set_contour_point(c, -1, {0, 0, 0}));
  geometry::scale_contour(c, {2, 3, 4});
  expect_near(c.points[1], {10, 18, 28});
}

// val(name): the .vset file's value, the name #defined to its id.
TEST(Parameters, ValReadsTheParameterFile) {
  auto run = load("val",
                  "derivation length: 1;\n"
                  "module A(float);\n"
                  "axiom: A(0);\n"
                  "A(x) : { float len = val(LENGTH), a = val(ANGLE); produce A(len * 100 + a); }\n",
                  {{"panel.vset", "#define LENGTH 2.5\n\n#define ANGLE 60\n"}});
  run->simulation->run();
  std::string text = io::format_string(run->simulation->string(), run->simulation->types());
  EXPECT_EQ(text, "A(310)\n");
}

}  // namespace
}  // namespace sylva::test
