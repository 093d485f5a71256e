// cpfg's turtle symbols (CPFG manual, chapter 6) drawn by the same turtle as
// L+C's predefined modules, with cpfg's defaults from the view file (8.1.1):
// small cpfg models whose scenes are worked out by hand, the query pass for
// ?P, the golden models' view files, and the snowflake through `sylva run`.
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "inputs/view_file.h"
#include "io/string_text.h"
#include "turtle/cpfg_symbols.h"
#include "turtle/turtle_fixture.h"

namespace sylva::test::turtle_tests {
namespace {
namespace fs = std::filesystem;

struct CpfgModel {
  std::unique_ptr<Simulation> simulation;
  Scene scene;
};

// A cpfg model with `axiom` and `productions`, its view file holding `view`,
// derived `steps` steps and drawn.
CpfgModel cpfg_model(const std::string& name, const std::string& axiom, const std::string& view,
                     const std::string& productions = "", int steps = 0) {
  const std::string dir = make_temp_dir("cpfg-turtle-" + name);
  std::ofstream(dir + "/lsystem.l") << "Lsystem: 1\nderivation length: " << steps << "\nAxiom: " << axiom << "\n"
                                    << productions << (productions.empty() ? "" : "\n") << "endlsystem\n";
  std::ofstream(dir + "/view.v") << view << "\n";
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  CpfgModel m;
  m.simulation = std::make_unique<Simulation>(dir + "/lsystem.l", SimulationOptions{build, {dir + "/view.v"}});
  m.simulation->run(steps);
  m.scene = m.simulation->scene();
  return m;
}

Scene draw_cpfg(const std::string& name, const std::string& axiom, const std::string& view = "angle increment: 90") {
  return cpfg_model(name, axiom, view).scene;
}

// ---- position and rotations -----------------------------------------------------

TEST(CpfgTurtle, TurnsByTheViewFilesAngleIncrementOrTheirParameter) {
  // H = (0,1,0) and L = (-1,0,0) at first; + turns H toward L.
  Scene s = draw_cpfg("turns", "F+F-F-F+(30)F");
  ASSERT_EQ(s.segments.size(), 5u);
  expect_near(s.segments[0].start, {0, 0, 0});
  expect_near(s.segments[0].end, {0, 1, 0});
  expect_near(s.segments[1].end, {-1, 1, 0});
  expect_near(s.segments[2].end, {-1, 2, 0});
  expect_near(s.segments[3].end, {0, 2, 0});
  // +(30) from heading +x: 30 degrees toward +y.
  expect_near(s.segments[4].end, {0.8660254f, 2.5f, 0});
}

TEST(CpfgTurtle, DefaultAngleIs45WithoutAnAngleIncrement) {
  Scene s = draw_cpfg("default-angle", "F+F", "initial color: 1");
  ASSERT_EQ(s.segments.size(), 2u);
  const float h = 0.70710678f;
  expect_near(s.segments[1].end, {-h, 1 + h, 0});
}

TEST(CpfgTurtle, AngleFactorIsAFractionOfAFullTurn) {
  Scene s = draw_cpfg("angle-factor", "F-F", "angle factor: 4");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[1].end, {1, 1, 0});
}

TEST(CpfgTurtle, StepsDefaultToOneAndTakeTheirParameter) {
  // f and g move without drawing; G draws.
  Scene s = draw_cpfg("steps", "F f(2) G(0.5) g F(3)");
  ASSERT_EQ(s.segments.size(), 3u);
  expect_near(s.segments[0].end, {0, 1, 0});
  expect_near(s.segments[1].start, {0, 3, 0});
  expect_near(s.segments[1].end, {0, 3.5f, 0});
  expect_near(s.segments[2].start, {0, 4.5f, 0});
  expect_near(s.segments[2].end, {0, 7.5f, 0});
}

TEST(CpfgTurtle, PitchRollAndTurnAround) {
  // The ends are the reference cpfg's ?P after each branch's F's (angle
  // factor 4): F&F (0,1,-1), F^F (0,1,1), F/+F (0,1,-1), F\+F (0,1,1), F|F (0,0,0).
  Scene s = draw_cpfg("pitch", "[F&F][F^F][F/+F][F\\+F][F|F]");
  ASSERT_EQ(s.segments.size(), 10u);
  expect_near(s.segments[1].end, {0, 1, -1});
  expect_near(s.segments[3].end, {0, 1, 1});
  // cpfg's U starts at -z: / rolls L towards it, so + then heads along -z.
  expect_near(s.segments[5].end, {0, 1, -1});
  expect_near(s.segments[7].end, {0, 1, 1});
  // | turns around: back to the start.
  expect_near(s.segments[9].end, {0, 0, 0});
}

TEST(CpfgTurtle, BranchesRestoreTheTurtle) {
  Scene s = draw_cpfg("branches", "F[+F]F");
  ASSERT_EQ(s.segments.size(), 3u);
  expect_near(s.segments[1].end, {-1, 1, 0});
  expect_near(s.segments[2].start, {0, 1, 0});
  expect_near(s.segments[2].end, {0, 2, 0});
}

TEST(CpfgTurtle, MoveToAndSetHeading) {
  Scene s = draw_cpfg("moveto", "@M(2,3,4)F@R(1,0,0)F(2)");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[0].start, {2, 3, 4});
  expect_near(s.segments[0].end, {2, 4, 4});
  expect_near(s.segments[1].end, {4, 4, 4});
}

TEST(CpfgTurtle, RollToVerticalKeepsUpOnTheUpperSide) {
  // After pitching 45 degrees and rolling, @v brings U into the vertical
  // plane of H: the reference cpfg gives ?U(0,-0.707107,-0.707107) after
  // &(45)/(70)@v. A segment's up is the frame's, cpfg's U negated.
  Scene s = draw_cpfg("vertical-at", "&(45)/(70)@vF", "angle increment: 90");
  ASSERT_EQ(s.segments.size(), 1u);
  expect_near(s.segments[0].up, {0, 0.707107f, 0.707107f});
}

TEST(CpfgTurtle, DollarDoesNotRoll) {
  // cpfg's $ only ends a sub-L-system (interpret.c); the reference cpfg
  // gives the same ?H after +(30)&(20)$ as after +(30)&(20): (-0.469846,0.813798,-0.34202).
  Scene s = draw_cpfg("dollar", "+(30)&(20)$F", "angle increment: 90");
  ASSERT_EQ(s.segments.size(), 1u);
  expect_near(s.segments[0].end, {-0.469846f, 0.813798f, -0.34202f});
}

// ---- width and colour -------------------------------------------------------------

TEST(CpfgTurtle, WidthSymbolsStepByTheIncrementOrSetTheirParameter) {
  Scene s = draw_cpfg("width", "F#F!!F!(5)F#(3)F!!!!!!!!F",
                      "initial line width: 2\nline width increment: 0.5");
  ASSERT_EQ(s.segments.size(), 6u);
  EXPECT_FLOAT_EQ(s.segments[0].start_width, 2);
  EXPECT_FLOAT_EQ(s.segments[1].start_width, 2.5f);
  EXPECT_FLOAT_EQ(s.segments[2].start_width, 1.5f);
  EXPECT_FLOAT_EQ(s.segments[3].start_width, 5);
  EXPECT_FLOAT_EQ(s.segments[4].start_width, 3);
  EXPECT_FLOAT_EQ(s.segments[5].start_width, 0);  // not below zero
}

TEST(CpfgTurtle, WidthIncrementDefaultsToZero) {
  Scene s = draw_cpfg("width-default", "F#F", "initial line width: 3");
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_FLOAT_EQ(s.segments[1].start_width, 3);
}

TEST(CpfgTurtle, ColourSymbolsStepByTheIncrementOrSetTheirParameter) {
  Scene s = draw_cpfg("colour", "F;F,,F;(7)F,(9)F", "initial color: 3\ncolor increment: 2");
  ASSERT_EQ(s.segments.size(), 5u);
  EXPECT_EQ(s.segments[0].color, 3);
  EXPECT_EQ(s.segments[1].color, 5);
  EXPECT_EQ(s.segments[2].color, 1);
  EXPECT_EQ(s.segments[3].color, 7);
  EXPECT_EQ(s.segments[4].color, 9);
}

// ' is The Algorithmic Beauty of Plants' colour increment: 3, then 3+2, then 5+2.
TEST(CpfgTurtle, ApostropheIncrementsTheColour) {
  Scene s = draw_cpfg("apostrophe", "F'F'F", "initial color: 3\ncolor increment: 2");
  ASSERT_EQ(s.segments.size(), 3u);
  EXPECT_EQ(s.segments[0].color, 3);
  EXPECT_EQ(s.segments[1].color, 5);
  EXPECT_EQ(s.segments[2].color, 7);
}

TEST(CpfgTurtle, ColourWrapsAroundTheColourMapAndDefaultsTo128) {
  Scene wrapped = draw_cpfg("colour-wrap", "F,F", "initial color: 1\ncolor increment: 2");
  ASSERT_EQ(wrapped.segments.size(), 2u);
  EXPECT_EQ(wrapped.segments[1].color, 255);
  Scene plain = draw_cpfg("colour-default", "F;F");
  ASSERT_EQ(plain.segments.size(), 2u);
  EXPECT_EQ(plain.segments[0].color, 128);  // the manual's default initial color
  EXPECT_EQ(plain.segments[1].color, 129);
}

// cpfg keeps a colour as 256 * colormap + entry, the turtle's ;(n) as 256 + n
// (colormap 1) wrapped once: ; subtracts 256 past 256 + 255, , adds 256
// below 256 (cpfg/interpret.c). So ;(300) is 300: colormap 1, entry 44 (44
// here); ;(600) is 600: colormap 2, entry 88 (344 here); ,(-20) is 492:
// colormap 1, entry 236; ,(600) is 856: colormap 3, entry 88 (600 here).
TEST(CpfgTurtle, ColourIndicesPastTheFirstColormapWrapOnceAsCpfgWrapsThem) {
  Scene s = draw_cpfg("colour-banks", "F;(300)F;(600)F,(-20)F,(600)F;(255)F;F", "initial color: 1");
  ASSERT_EQ(s.segments.size(), 7u);
  EXPECT_EQ(s.segments[1].color, 44);
  EXPECT_EQ(s.segments[2].color, 344);
  EXPECT_EQ(geometry::Palette::bank_of(344), 2);
  EXPECT_EQ(geometry::Palette::entry_of(344), 88);
  EXPECT_EQ(s.segments[3].color, 236);
  EXPECT_EQ(s.segments[4].color, 600);
  EXPECT_EQ(geometry::Palette::bank_of(600), 3);
  EXPECT_EQ(s.segments[5].color, 255);
  EXPECT_EQ(s.segments[6].color, 0);  // 256 + 256 > 511: back to 256, entry 0
}

TEST(CpfgTurtle, ScaleMultipliesSteps) {
  Scene s = draw_cpfg("scale", "F@D(0.5)F@DiF@DdF", "initial scale: 2\nscale multiplier: 3");
  ASSERT_EQ(s.segments.size(), 4u);
  EXPECT_NEAR(length(s.segments[0].end - s.segments[0].start), 2, 1e-5);
  EXPECT_NEAR(length(s.segments[1].end - s.segments[1].start), 0.5, 1e-5);
  EXPECT_NEAR(length(s.segments[2].end - s.segments[2].start), 1.5, 1e-5);
  EXPECT_NEAR(length(s.segments[3].end - s.segments[3].start), 0.5, 1e-5);
}

// ---- polygons, circles, spheres, cylinders -------------------------------------------

TEST(CpfgTurtle, PolygonsAreFilledFromTheirVertices) {
  // A unit square from four . vertices (g moves without adding one), and a
  // triangle from f steps, which add their end points.
  Scene s = draw_cpfg("polygons", "{.g+.g+.g+.}[-(90)f(3){.+(120)f+(120)f}]");
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[0].kind, geometry::TriangleGroup::Kind::Polygon);
  EXPECT_EQ(s.groups[0].index_count, 6u);  // 4 vertices: 2 triangles
  EXPECT_NEAR(group_area(s, s.groups[0]), 1, 1e-5);
  EXPECT_EQ(s.groups[1].index_count, 3u);
  EXPECT_NEAR(group_area(s, s.groups[1]), std::sqrt(3.0) / 4, 1e-5);
  EXPECT_TRUE(s.segments.empty());
}

TEST(CpfgTurtle, CirclesAndSpheresTakeTheirDiameter) {
  Scene s = draw_cpfg("circles", "@o(2)@c(4)@O(3)#(6)@o@O@bo(2)", "initial line width: 1");
  ASSERT_EQ(s.circles.size(), 4u);
  EXPECT_FLOAT_EQ(s.circles[0].radius, 1);
  EXPECT_TRUE(s.circles[0].facing_viewer);
  EXPECT_FLOAT_EQ(s.circles[1].radius, 2);
  EXPECT_FALSE(s.circles[1].facing_viewer);
  EXPECT_FLOAT_EQ(s.circles[2].radius, 3);  // the line width, 6, as diameter
  EXPECT_FLOAT_EQ(s.circles[3].radius, 1);
  EXPECT_FLOAT_EQ(s.circles[3].outline, 6);
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_FLOAT_EQ(s.spheres[0].radius, 1.5f);
  EXPECT_FLOAT_EQ(s.spheres[1].radius, 3);
}

// @Gs F @Gc(2) F @Ge(3): three control points (the start, each @G), so two
// stretches (a group each). {(1) F .(2) F }(1) (CPFG manual 6.7.3): { is no
// point; the first F makes one (y = 1); .(2) finds the turtle there, so it
// only sets that point's strips; the second F makes the second (y = 2, 4
// strips); } finds the turtle there and adds none: two points, one stretch
// of 4 strips, so 5 rings of 8 sides.
TEST(CpfgTurtle, GeneralizedCylinders) {
  for (const char* axiom : {"@Gs F @Gc(2) F @Ge(3)", "{(1) F .(2) F }(1)"}) {
    const bool at = axiom[0] == '@';
    Scene s = draw_cpfg(std::string("cylinder-") + (at ? "at" : "brace"), axiom);
    ASSERT_EQ(s.groups.size(), at ? 2u : 1u) << axiom;
    for (const geometry::TriangleGroup& g : s.groups)
      EXPECT_EQ(g.kind, geometry::TriangleGroup::Kind::GeneralizedCylinder) << axiom;
    EXPECT_TRUE(s.segments.empty()) << axiom;  // the cylinder is the drawing
    if (!at) {
      ASSERT_FALSE(s.positions.empty());
      EXPECT_EQ(s.positions.size() % 5, 0u) << "5 rings";
      const std::size_t sides = s.positions.size() / 5;
      EXPECT_EQ(s.groups[0].index_count, 4 * sides * 2 * 3);
    }
  }
}

TEST(CpfgTurtle, UnknownSymbolsAreIgnored) {
  Scene s = draw_cpfg("unknown", "A F B(1,2) X @L ?E(1) F");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[1].end, {0, 2, 0});
}

// ---- query modules ---------------------------------------------------------------------

TEST(CpfgTurtle, QueryModulesReceiveTheTurtleAfterEveryStep) {
  CpfgModel m = cpfg_model("query", "F(2)+?P(0,0,0)?H(0,0,0)", "angle increment: 90",
                           "?P(x,y,z) --> F(1)?P(x,y,z)", 1);
  const Simulation& d = *m.simulation;
  EXPECT_TRUE(d.fills_query_modules());
  const ModuleId p = *d.types().find("?P");
  const ModuleId h = *d.types().find("?H");
  // The step's F(1) heads along -x after the turn: the query pass after the
  // step wrote the new position.
  expect_near(module_floats(d, p, 0, 3), {-1, 2, 0});
  expect_near(module_floats(d, h, 0, 3), {-1, 0, 0});
}

TEST(CpfgTurtle, QueryWithTwoParametersGetsXAndY) {
  CpfgModel m = cpfg_model("query2", "-F(3)?P(0,0)", "angle increment: 90", "?P(x,y) --> ?P(x,y)", 1);
  const Simulation& d = *m.simulation;
  EXPECT_TRUE(d.fills_query_modules());
  const std::vector<float> xy = module_floats(d, *d.types().find("?P"), 0, 2);
  ASSERT_EQ(xy.size(), 2u);
  EXPECT_NEAR(xy[0], 3, 1e-5);
  EXPECT_NEAR(xy[1], 0, 1e-5);
}

TEST(CpfgTurtle, QueriesAreFilledWithoutAProductionReadingThem) {
  // cpfg fills ?P wherever it occurs: the reference cpfg gives F?P(0,1,0).
  CpfgModel m = cpfg_model("no-query", "A", "", "A --> F?P(0,0,0)", 1);
  EXPECT_TRUE(m.simulation->fills_query_modules());
  EXPECT_EQ(io::format_string(m.simulation->string(), m.simulation->types()), "F?P(0,1,0)\n");
}

TEST(CpfgTurtle, SymbolTableIsByModuleId) {
  CpfgModel m = cpfg_model("table", "F F(2) +(1) [ ] ?P(1,2,3) A", "");
  const ModuleTypes& types = m.simulation->types();
  turtle::CpfgSymbols table(types);
  EXPECT_EQ(table.size(), types.size());
  EXPECT_EQ(table.op(rt::mid::SB), turtle::CpfgOp::Push);
  EXPECT_EQ(table.op(rt::mid::EB), turtle::CpfgOp::Pop);
  // The predefined L+C F never occurs in a cpfg string.
  EXPECT_EQ(table.op(rt::mid::F), turtle::CpfgOp::None);
  int forwards = 0;
  for (std::size_t id = 0; id < types.size(); ++id)
    if (table.op(static_cast<ModuleId>(id)) == turtle::CpfgOp::Forward) {
      ++forwards;
      EXPECT_EQ(types.name(static_cast<ModuleId>(id)), "F");
    }
  EXPECT_EQ(forwards, 2);  // F and F(2) are two module types
  EXPECT_EQ(table.query_modules().size(), 1u);
  EXPECT_EQ(table.op(*types.find("A")), turtle::CpfgOp::None);
}

// ---- view files -------------------------------------------------------------------------

TEST(CpfgTurtleViewFile, GoldenCpfgViewFilesReadWithoutWarnings) {
  int read = 0;
  for (const auto& entry : fs::directory_iterator(data_path("golden-cpfg"))) {
    const fs::path view = entry.path() / "view.v";
    if (!fs::exists(view)) continue;
    io::ViewFile v = io::read_view_file(view.string(), "", io::ViewDialect::Cpfg);
    EXPECT_TRUE(v.warnings.empty()) << view << ": " << (v.warnings.empty() ? "" : v.warnings[0]);
    ++read;
  }
  EXPECT_EQ(read, 36);
}

TEST(CpfgTurtleViewFile, TurtleCommandsReachTheTurtleSettings) {
  const std::string dir = make_temp_dir("cpfg-view-settings");
  std::ofstream(dir + "/v.v") << "angle increment: 30\ncolor increment: 4 2\nline width increment: 0.25\n"
                                 "initial scale: 2\nscale multiplier: 1.5\ninitial color: 9\nviewpoint: 0,0,1\n";
  io::ViewFile v = io::read_view_file(dir + "/v.v", "", io::ViewDialect::Cpfg);
  turtle::TurtleSettings t = v.turtle_settings();
  EXPECT_FLOAT_EQ(t.angle_increment, 30);
  EXPECT_EQ(t.color_increment, 4);
  EXPECT_FLOAT_EQ(t.width_increment, 0.25f);
  EXPECT_FLOAT_EQ(t.initial_scale, 2);
  EXPECT_FLOAT_EQ(t.scale_multiplier, 1.5f);
  EXPECT_EQ(t.initial_color, 9);
  EXPECT_EQ(t.cpfg_initial_color, 9);
  EXPECT_TRUE(v.warnings.empty()) << v.warnings[0];
  // An lpfg model's view file does not set them: lpfg does not read them.
  turtle::TurtleSettings l = io::read_view_file(dir + "/v.v").turtle_settings();
  EXPECT_FLOAT_EQ(l.angle_increment, 45);
  EXPECT_EQ(l.initial_color, 1);
  // Without the commands: the manual's defaults.
  std::ofstream(dir + "/empty.v") << "/* nothing */\n";
  turtle::TurtleSettings d = io::read_view_file(dir + "/empty.v", "", io::ViewDialect::Cpfg).turtle_settings();
  EXPECT_FLOAT_EQ(d.angle_increment, 45);
  EXPECT_FLOAT_EQ(d.width_increment, 0);
  EXPECT_EQ(d.color_increment, 1);
  EXPECT_EQ(d.cpfg_initial_color, 128);
  EXPECT_EQ(d.initial_color, 1);  // an L+C model's stays lpfg's
}

// ---- end to end ----------------------------------------------------------------------------

TEST(CpfgTurtleEndToEnd, SnowflakeHasThreeTimesFourToTheNSegments) {
  const std::string dir = data_path("golden-cpfg/notes-snowflake");
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(dir + "/lsystem.l", SimulationOptions{build, {dir + "/view.v"}});
  simulation.begin();
  for (int n = 0; n <= 3; ++n) {
    if (n > 0) simulation.step();
    Scene s = simulation.scene();
    std::size_t expected = 3;
    for (int k = 0; k < n; ++k) expected *= 4;
    ASSERT_EQ(s.segments.size(), expected) << "step " << n;
    // A closed curve: it ends where it began.
    expect_near(s.segments.back().end, s.segments.front().start, 1e-4f);
  }
}

TEST(CpfgTurtleEndToEnd, SylvaRunDrawsTheSnowflakeToPngAndSvg) {
  const std::string out = make_temp_dir("cpfg-snowflake-run");
  const std::string dir = data_path("golden-cpfg/notes-snowflake");
  ProcessResult r = run_sylva({"run", dir + "/lsystem.l", dir + "/view.v", "-o", out + "/snowflake.png", "-o",
                               out + "/snowflake.svg"},
                              out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load((out + "/snowflake.png").c_str(), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr) << stbi_failure_reason();
  const unsigned char* corner = data;  // the background
  std::size_t drawn = 0;
  for (int k = 0; k < w * h; ++k)
    if (data[3 * k] != corner[0] || data[3 * k + 1] != corner[1] || data[3 * k + 2] != corner[2]) ++drawn;
  stbi_image_free(data);
  EXPECT_GT(drawn, 100u);
  EXPECT_LT(drawn, static_cast<std::size_t>(w) * h / 2);
  // "initial line width: 1" without a style draws polygons in cpfg (its
  // ReadViewData sets the polygon line style), one per F.
  const std::string svg = read_text(out + "/snowflake.svg");
  std::size_t polygons = 0;
  for (std::size_t at = svg.find("<polygon"); at != std::string::npos; at = svg.find("<polygon", at + 1)) ++polygons;
  EXPECT_GT(polygons, 0u) << svg.substr(0, 400);
}

}  // namespace
}  // namespace sylva::test::turtle_tests
