// The view file reader: every command read from a hand-written file and
// checked by hand, the preprocessor, the defaults, and errors at the file,
// line and column of the original text.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "inputs/input_files.h"
#include "inputs/input_test_helpers.h"
#include "inputs/view_file.h"

namespace sylva {
namespace {

using geometry::Vec3;
using test::error_of;
using test::expect_vec;
using test::input;
using test::write_file;

TEST(ViewFileTest, ReadsTheCameraOfView0AndTheGlobalCommands) {
  io::ViewFile view = io::read_view_file(input("plant.v"));
  const geometry::ViewParameters& v = view.view(0);
  EXPECT_TRUE(v.perspective);
  expect_vec(v.dir, {0, 0, -1});
  expect_vec(v.up, {0, 1, 0});
  expect_vec(v.pan, {0.5f, 1, 0});
  EXPECT_FLOAT_EQ(v.fov, 30);
  EXPECT_FLOAT_EQ(v.shift, 2);
  EXPECT_FLOAT_EQ(v.scale, 0.8f);
  ASSERT_TRUE(v.box.has_value());
  expect_vec(v.box->min, {-1, 0, -2});
  expect_vec(v.box->max, {1, 5, 2});
  // Both distances are given, so both hold.
  EXPECT_EQ(v.front_distance, -10.0f);
  EXPECT_EQ(v.back_distance, 10.0f);
  // A view without its own commands gets the global ones only.
  const geometry::ViewParameters& other = view.view(3);
  EXPECT_TRUE(other.perspective);
  EXPECT_FLOAT_EQ(other.scale, 0.9f);
  EXPECT_FALSE(other.box.has_value());
}

TEST(ViewFileTest, ReadsRenderingLightsAndGeometryPresentation) {
  io::ViewFile view = io::read_view_file(input("plant.v"));
  EXPECT_TRUE(view.render.z_buffer);
  EXPECT_EQ(view.render.mode, geometry::RenderMode::Shaded);
  EXPECT_EQ(view.render.shadow_map.size, 2048);
  EXPECT_EQ(view.render.shadow_map.color, (geometry::Rgb{0.1f, 0.2f, 0.3f}));
  EXPECT_FLOAT_EQ(view.render.shadow_map.offset_factor, 2);
  EXPECT_FLOAT_EQ(view.render.shadow_map.offset_units, 4);
  EXPECT_EQ(view.render.antialiasing, 4);
  EXPECT_EQ(view.render.line_style, geometry::LineStyle::Cylinder);
  EXPECT_FLOAT_EQ(view.render.wireframe_line_width, 2.5f);
  EXPECT_TRUE(view.render.auto_normals);
  EXPECT_EQ(view.render.ps_linecap, 1);
  EXPECT_EQ(view.contour_sides, 12);  // SIDES, #defined
  EXPECT_FALSE(view.corrected_rotation);

  ASSERT_EQ(view.lights.size(), 2u);
  const geometry::Light& sun = view.lights[0];
  EXPECT_EQ(sun.kind, geometry::Light::Kind::Directional);
  expect_vec(sun.direction, {1, 1, 1});
  EXPECT_EQ(sun.diffuse, (geometry::Rgb{0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(sun.ambient, (geometry::Rgb{1, 1, 1}));
  const geometry::Light& spot = view.lights[1];
  EXPECT_EQ(spot.kind, geometry::Light::Kind::Spot);
  expect_vec(spot.position, {0, 10, 0});
  expect_vec(spot.direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(spot.spot_exponent, 2);
  EXPECT_FLOAT_EQ(spot.spot_cutoff, 45);
  EXPECT_FLOAT_EQ(spot.linear_attenuation, 0.1f);
  EXPECT_FLOAT_EQ(spot.quadratic_attenuation, 0.01f);

  EXPECT_EQ(view.winfont.name, "Times New Roman");
  EXPECT_EQ(view.winfont.size, 14);
  EXPECT_TRUE(view.winfont.bold);
  EXPECT_TRUE(view.winfont.italic);
}

TEST(ViewFileTest, ReadsTropismsAndTheTurtleSettings) {
  io::ViewFile view = io::read_view_file(input("plant.v"));
  ASSERT_EQ(view.tropisms.size(), 2u);
  turtle::TurtleSettings t = view.turtle_settings();
  ASSERT_EQ(t.tropisms.size(), 2u);
  expect_vec(t.tropisms[0].direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(t.tropisms[0].angle, 10);
  EXPECT_FLOAT_EQ(t.tropisms[0].intensity, 2);
  EXPECT_FLOAT_EQ(t.tropisms[0].elasticity, 0.1f);
  EXPECT_FLOAT_EQ(t.tropisms[0].step, 0.05f);
  EXPECT_FALSE(t.tropisms[0].torque);
  expect_vec(t.tropisms[1].direction, {1, 0, 0});
  EXPECT_FLOAT_EQ(t.tropisms[1].elasticity, 0.3f);
  EXPECT_FLOAT_EQ(t.tropisms[1].intensity, 1);  // the default
  EXPECT_TRUE(t.tropisms[1].torque);
  expect_vec(t.simple_tropism.direction, {0, 1, 0});
  EXPECT_FLOAT_EQ(t.simple_tropism.elasticity, 0.25f);
  EXPECT_EQ(t.contour_sides, 12);
  EXPECT_FALSE(t.corrected_rotation);
  EXPECT_TRUE(t.auto_normals);
  EXPECT_EQ(t.surfaces, nullptr);
}

TEST(ViewFileTest, ReadsExternalFilesRelativeToTheViewFile) {
  io::ViewFile view = io::read_view_file(input("plant.v"));
  ASSERT_EQ(view.surfaces.size(), 2u);
  EXPECT_EQ(view.surfaces[0].file, "leaf.s");
  EXPECT_EQ(view.surfaces[0].path, input("leaf.s"));
  EXPECT_FLOAT_EQ(view.surfaces[0].scale, 1.5f);  // LEAF_SCALE
  EXPECT_EQ(view.surfaces[0].s_divisions, 6);
  EXPECT_EQ(view.surfaces[0].t_divisions, 4);
  EXPECT_EQ(view.surfaces[0].texture, -1);
  EXPECT_EQ(view.surfaces[1].path, input("surfaces/petal.s"));
  EXPECT_FLOAT_EQ(view.surfaces[1].scale, 1);
  EXPECT_EQ(view.surfaces[1].s_divisions, 0);
  ASSERT_EQ(view.textures.size(), 1u);
  EXPECT_EQ(view.textures[0], input("bark.png"));
  ASSERT_EQ(view.meshes.size(), 1u);
  EXPECT_EQ(view.meshes[0].path, input("cone.obj"));
  EXPECT_FLOAT_EQ(view.meshes[0].scale, 2);
  expect_vec(view.meshes[0].contact, {0, 1, 0});
}

TEST(ViewFileTest, UnknownAndCpfgCommandsAreWarningsAtTheirLine) {
  io::ViewFile view = io::read_view_file(input("plant.v"));
  // lpfg does not read cpfg's "angle increment:" (line 35): it says so and
  // goes on, as it does for a command it does not know (line 36).
  EXPECT_FLOAT_EQ(view.angle_increment, 45);
  ASSERT_EQ(view.warnings.size(), 2u);
  EXPECT_EQ(view.warnings[0], input("plant.v") + ":35:1: warning: cpfg command 'angle increment' ignored: lpfg does not read it");
  EXPECT_EQ(view.warnings[1], input("plant.v") + ":36:1: warning: unknown command 'no such command' ignored");
}

TEST(ViewFileTest, DefaultsWhenCommandsAreAbsent) {
  std::string dir = test::make_temp_dir("view-defaults");
  io::ViewFile view = io::read_view_file(write_file(dir, "empty.v", "/* nothing */\n// at all\n"));
  const geometry::ViewParameters& v = view.view(0);
  EXPECT_FALSE(v.perspective);
  expect_vec(v.dir, {0, 0, -1});
  expect_vec(v.up, {0, 1, 0});
  expect_vec(v.pan, {0, 0, 0});
  EXPECT_FLOAT_EQ(v.fov, 45);
  EXPECT_FLOAT_EQ(v.shift, 1);
  EXPECT_FLOAT_EQ(v.scale, 0.9f);
  EXPECT_FALSE(v.box || v.front_distance || v.back_distance);
  EXPECT_FALSE(view.render.z_buffer);
  EXPECT_EQ(view.render.mode, geometry::RenderMode::Filled);
  EXPECT_EQ(view.render.line_style, geometry::LineStyle::Pixel);
  EXPECT_EQ(view.contour_sides, 16);
  EXPECT_TRUE(view.corrected_rotation);
  EXPECT_TRUE(view.lights.empty());
  ASSERT_EQ(view.lights_or_default().size(), 1u);
  expect_vec(view.lights_or_default()[0].direction, {0, 0, 1});
  EXPECT_TRUE(view.tropisms.empty());
  EXPECT_FALSE(view.simple_tropism);
  EXPECT_TRUE(view.surfaces.empty());
  EXPECT_TRUE(view.warnings.empty());
  turtle::TurtleSettings t = view.turtle_settings();
  EXPECT_FLOAT_EQ(t.initial_width, 1);
  EXPECT_EQ(t.initial_color, 1);
  EXPECT_EQ(t.contour_sides, 16);
  EXPECT_TRUE(t.corrected_rotation);
}

TEST(ViewFileTest, PreprocessorConditionalsAndMultiLineComments) {
  std::string dir = test::make_temp_dir("view-preprocessor");
  std::string path = write_file(dir, "pp.v",
                                "#define WIDE\n"
                                "/* a comment\n"
                                "   over lines: scale: nonsense */\n"
                                "#ifdef WIDE\n"
                                "scale: 0.5\n"
                                "#else\n"
                                "scale: nonsense\n"
                                "#endif\n"
                                "#if 0\n"
                                "render mode: nonsense\n"
                                "#endif\n"
                                "#define DIR(x) dir: x 0 0\n"
                                "view: 0 DIR(1)\n");
  io::ViewFile view = io::read_view_file(path);
  EXPECT_FLOAT_EQ(view.view(0).scale, 0.5f);
  expect_vec(view.view(0).dir, {1, 0, 0});
  EXPECT_EQ(view.render.mode, geometry::RenderMode::Filled);
  EXPECT_TRUE(view.warnings.empty());
}

// lpfg prints "Error in command: ..." for a value it cannot read and goes on
// with the next line (DrawParams::Load; seen running lpfg on "line style:
// wireframe" and "render mode: glossy"): a warning here, the command without
// effect.
TEST(ViewFileTest, MalformedValueIsAWarningAtTheOriginalLineAndColumn) {
  std::string dir = test::make_temp_dir("view-malformed");
  // The comment lines before it and the one inside it must not move the position.
  std::string path = write_file(dir, "bad.v",
                                "/* one\n"
                                "   two */\n"
                                "#define N 3\n"
                                "line style: /* why not */ cylinder\n"
                                "contour sides: many\n"
                                "z buffer: /* on or */ maybe\n"
                                "box: 0 -1 1 -1 1 -1\n"
                                "render mode: shaded\n");
  io::ViewFile view = io::read_view_file(path);
  ASSERT_EQ(view.warnings.size(), 3u);
  EXPECT_EQ(view.warnings[0], path + ":5:16: warning: expected the number of sides, found 'many'; 'contour sides:' ignored");
  EXPECT_EQ(view.warnings[1], path + ":6:23: warning: expected on or off, found 'maybe'; 'z buffer:' ignored");
  EXPECT_EQ(view.warnings[2], path + ":7:20: warning: expected zmax, found the end of the line; 'box:' ignored");
  EXPECT_EQ(view.contour_sides, 16);
  EXPECT_FALSE(view.render.z_buffer);
  EXPECT_FALSE(view.view(0).box);
  // The lines around them are read.
  EXPECT_EQ(view.render.line_style, geometry::LineStyle::Cylinder);
  EXPECT_EQ(view.render.mode, geometry::RenderMode::Shaded);
}

TEST(ViewFileTest, MalformedCommandsOfEveryKind) {
  std::string dir = test::make_temp_dir("view-kinds");
  struct Case {
    std::string text, expected;
  };
  std::vector<Case> cases = {
      {"projection: fisheye", ":1:13: warning: expected a projection (parallel, perspective), found 'fisheye'; 'projection:' ignored"},
      {"view: 0 dir: 0 0 0", ":1:14: warning: expected the view direction of non-zero length, found 0 0 0; 'view:' ignored"},
      {"view: 0 zoom: 2", ":1:9: warning: expected dir:, up:, pan:, fov:, shift: or scale:, found 'zoom:'; 'view:' ignored"},
      {"view: main dir: 0 0 1", ":1:7: warning: expected a view id (a number, or a name given by an earlier window: command), found 'main'; 'view:' ignored"},
      {"view: 2 dir: 0 0 1", ":1:7: warning: expected a view id (0, the windows counted from 0), found '2'; 'view:' ignored"},
      {"light: Q: 1", ":1:8: warning: expected V:, O:, P:, A:, D:, S: or T:, found 'Q:'; 'light:' ignored"},
      {"light: Diffuse: 1 1 1", ":1:8: warning: expected V:, O:, P:, A:, D:, S: or T:, found 'Diffuse:'; 'light:' ignored"},
      {"torque: T: 0 1 0 A: 10", ":1:18: warning: lpfg allows no angle A: in a torque; 'torque:' ignored"},
      {"stropism: 0 1 0", ":1:16: warning: expected the elasticity, found the end of the line; 'stropism:' ignored"},
      {"surface:", ":1:9: warning: expected a surface file name, found the end of the line; 'surface:' ignored"},
      {"surface: a.s 1 4", ":1:17: warning: expected the subdivisions along t (sdiv and tdiv go together), found the end of the line; 'surface:' ignored"},
      {"scale: -1", ":1:8: warning: expected the scale greater than 0, found '-1'; 'scale:' ignored"},
      {"antialiasing: 11", ":1:15: warning: expected a number of samples from 0 to 10, found '11'; 'antialiasing:' ignored"},
      {"line style: wireframe", ":1:13: warning: expected a line style (pixel, polygon, cylinder), found 'wireframe'; 'line style:' ignored"},
      {"box: x: -16,16 y: -16,16 z: -1,1", ":1:6: warning: expected a view id (a number, or a name given by an earlier window: command), found 'x:'; 'box:' ignored"},
      {"box: 0 1 1 0 1 0 1", ":1:8: warning: expected xmin xmax ymin ymax zmin zmax with each minimum below its maximum; 'box:' ignored"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string path = write_file(dir, "case" + std::to_string(i) + ".v", cases[i].text + "\n");
    io::ViewFile view;
    EXPECT_EQ(error_of([&] { view = io::read_view_file(path); }), "") << cases[i].text;
    ASSERT_EQ(view.warnings.size(), 1u) << cases[i].text;
    EXPECT_EQ(view.warnings[0], path + cases[i].expected) << cases[i].text;
    EXPECT_TRUE(view.lights.empty() && view.tropisms.empty() && view.surfaces.empty() && !view.view(0).box &&
                !view.simple_tropism)
        << cases[i].text;
  }
}

TEST(ViewFileTest, WarningsInsideAnIncludedFileNameThatFile) {
  std::string dir = test::make_temp_dir("view-include");
  std::string part = write_file(dir, "part.v", "z buffer: on\nrender mode: glossy\n");
  std::string path = write_file(dir, "main.v", "// main\n#include \"part.v\"\nline style: polygon\n");
  io::ViewFile view = io::read_view_file(path);
  ASSERT_EQ(view.warnings.size(), 1u);
  EXPECT_EQ(view.warnings[0],
            part + ":2:14: warning: expected a render mode (filled, wireframe, shaded, shadows), found 'glossy'; 'render mode:' ignored");
  EXPECT_TRUE(view.render.z_buffer);
}

// lpfg's light: a part is a letter and one more character ("D:", "D "), the
// numbers after it; the last of V: and O: says where the light is
// (LightSource::_Load).
TEST(ViewFileTest, LightPartsAsLpfgReadsThem) {
  std::string dir = test::make_temp_dir("view-lights");
  io::ViewFile view = io::read_view_file(write_file(dir, "l.v",
                                                    "light: V 1 1 1 D 0.5 0.5 0.5\n"
                                                    "light: V: 0 0 1 O: 1 2 3\n"
                                                    "light: O: 1 2 3 V: 0 1 0\n"
                                                    "light: P: 0 -1 0 2 45\n"));
  ASSERT_EQ(view.lights.size(), 4u);
  EXPECT_EQ(view.lights[0].diffuse, (geometry::Rgb{0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(view.lights[1].kind, geometry::Light::Kind::Point);
  expect_vec(view.lights[1].position, {1, 2, 3});
  EXPECT_EQ(view.lights[2].kind, geometry::Light::Kind::Directional);
  expect_vec(view.lights[2].direction, {0, 1, 0});
  // Without O: lpfg's light is directional along +z, and OpenGL makes no
  // spotlight of a directional light.
  EXPECT_EQ(view.lights[3].kind, geometry::Light::Kind::Directional);
  expect_vec(view.lights[3].direction, {0, 0, 1});
  EXPECT_TRUE(view.warnings.empty());
}

// lpfg's tropism without T: bends toward (0,-1,0) (Tropism::_Default).
TEST(ViewFileTest, TropismDirectionDefaultsDown) {
  std::string dir = test::make_temp_dir("view-tropism");
  io::ViewFile view = io::read_view_file(write_file(dir, "t.v", "tropism: E: 0.5\n"));
  ASSERT_EQ(view.tropisms.size(), 1u);
  expect_vec(view.tropisms[0].direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(view.tropisms[0].elasticity, 0.5f);
}

// Commands lpfg knows but Sylva does not reproduce, and cpfg's commands,
// are warnings; nothing stops.
TEST(ViewFileTest, CommandsOfTheOtherProgramAndUnreproducedOnesAreWarnings) {
  std::string dir = test::make_temp_dir("view-other");
  io::ViewFile view = io::read_view_file(write_file(dir, "o.v",
                                                    "viewpoint: 0,0,1\n"
                                                    "terrain: ground.t\n"
                                                    "function: f.func\n"
                                                    "initial line width: 3 s\n"));
  ASSERT_EQ(view.warnings.size(), 4u);
  EXPECT_NE(view.warnings[0].find(":1:1: warning: cpfg command 'viewpoint' ignored: lpfg does not read it"), std::string::npos);
  EXPECT_NE(view.warnings[1].find(":2:1: warning: 'terrain:' ignored: terrains are not supported"), std::string::npos);
  EXPECT_NE(view.warnings[2].find(":3:1: warning: 'function:' ignored"), std::string::npos);
  EXPECT_NE(view.warnings[3].find("cpfg command 'initial line width' ignored"), std::string::npos);
  EXPECT_EQ(view.render.line_style, geometry::LineStyle::Pixel);
  EXPECT_FALSE(view.initial_line_width);
  EXPECT_FALSE(view.view(0).cpfg);
}

TEST(ViewFileTest, PreprocessorErrorsNameTheirLine) {
  std::string dir = test::make_temp_dir("view-cpp-error");
  std::string path = write_file(dir, "err.v", "scale: 1\n\n#error the view is unfinished\n");
  std::string message = error_of([&] { io::read_view_file(path); });
  EXPECT_EQ(message.rfind(path + ":3:", 0), 0u) << message;
  EXPECT_NE(message.find("the view is unfinished"), std::string::npos) << message;

  std::string missing_include = write_file(dir, "inc.v", "#include \"nowhere.v\"\n");
  message = error_of([&] { io::read_view_file(missing_include); });
  EXPECT_EQ(message.rfind(missing_include + ":1:", 0), 0u) << message;
  EXPECT_NE(message.find("nowhere.v"), std::string::npos) << message;

  EXPECT_EQ(error_of([&] { io::read_view_file(path, "/nonexistent/cxx"); }).rfind(path + ": error: cannot run", 0), 0u);
}

TEST(ViewFileTest, MissingFileIsNamed) {
  std::string path = test::make_temp_dir("view-missing") + "/absent.v";
  EXPECT_EQ(error_of([&] { io::read_view_file(path); }), path + ": error: cannot open the view file");
}

TEST(ViewFileTest, GlobalCommandsHoldForEveryViewAndTheLastOneWins) {
  std::string dir = test::make_temp_dir("view-views");
  std::string path = write_file(dir, "multi.v",
                                "window: Top 0 0 1 0.5\n"
                                "window: Bottom 0 0.5 1 0.5\n"
                                "view: Bottom dir: 1 0 0 scale: 0.5\n"
                                "box: Top -1 1 -1 1 -1 1\n"
                                "projection: perspective\n"
                                "scale factor: 0.6\n"
                                "front distance: 1\n"
                                "window border: 3 255 0 51\n");
  io::ViewFile view = io::read_view_file(path);
  ASSERT_EQ(view.windows.size(), 2u);
  EXPECT_EQ(view.windows[1].name, "Bottom");
  EXPECT_FLOAT_EQ(view.windows[1].top, 0.5f);
  // Windows are views 1 and 2 (view 0 is no window, LPFG manual 5.12).
  expect_vec(view.view(2).dir, {1, 0, 0});
  EXPECT_TRUE(view.view(2).perspective);
  EXPECT_FLOAT_EQ(view.view(2).scale, 0.6f);  // the later global scale wins
  ASSERT_TRUE(view.view(1).box.has_value());
  expect_vec(view.view(1).box->max, {1, 1, 1});
  EXPECT_FALSE(view.view(1).front_distance);  // no back distance: no effect
  EXPECT_EQ(view.window_border_width, 3);
  EXPECT_EQ(view.window_border_color, (geometry::Rgb{1, 0, 0.2f}));
  EXPECT_TRUE(view.warnings.empty());
}

// lpfg's view ids index its windows from 0 (DrawParams::IsValidViewId); Sylva
// numbers window k as view k + 1, and lpfg's id 0 also sets view 0.
TEST(ViewFileTest, NumericViewIdsCountTheWindowsFromZero) {
  std::string dir = test::make_temp_dir("view-ids");
  io::ViewFile view = io::read_view_file(write_file(dir, "ids.v",
                                                    "window: Left 0 0 0.5 1\n"
                                                    "window: Right 0.5 0 0.5 1\n"
                                                    "box: 0 -1 1 -1 1 -1 1\n"
                                                    "box: 1 -2 2 -2 2 -2 2\n"));
  ASSERT_TRUE(view.view(1).box && view.view(0).box && view.view(2).box);
  expect_vec(view.view(1).box->max, {1, 1, 1});
  expect_vec(view.view(0).box->max, {1, 1, 1});
  expect_vec(view.view(2).box->max, {2, 2, 2});
}

// lpfg's deprecated "view: id rx ry rz scale px py pz" (DrawParams::
// _ReadViewModifier; the manual gives another order): q = qx(rx) qy(ry)
// qz(rz) turns dir and up as q^-1 v q. rx = 30: dir (0,0,-1) turns by -30
// degrees about x to (0, -sin 30, -cos 30), up (0,1,0) to (0, cos 30, -sin 30).
TEST(ViewFileTest, DeprecatedViewFormAsLpfgReadsIt) {
  std::string dir = test::make_temp_dir("view-old");
  io::ViewFile view = io::read_view_file(write_file(dir, "old.v", "view: 0 30 0 0 2 1 2 3\n"));
  const geometry::ViewParameters& v = view.view(0);
  expect_vec(v.dir, {0, -0.5f, -std::sqrt(3.0f) / 2});
  expect_vec(v.up, {0, std::sqrt(3.0f) / 2, -0.5f});
  expect_vec(v.pan, {1, 2, 3});
  EXPECT_FLOAT_EQ(v.scale, 0.5f);  // a zoom of 2 is the new form's scale: 0.5
}

TEST(ViewFileTest, ContourSidesBelowThreeAreClamped) {
  std::string dir = test::make_temp_dir("view-sides");
  io::ViewFile view = io::read_view_file(write_file(dir, "s.v", "contour sides: 1\n"));
  EXPECT_EQ(view.contour_sides, 3);
  ASSERT_EQ(view.warnings.size(), 1u);
  EXPECT_NE(view.warnings[0].find("1 contour sides cannot be drawn; 3 are used, as in lpfg"), std::string::npos);
}

// Neither lpfg nor cpfg keeps a surface whose file it cannot open (lpfg:
// "WARNING: Can't open file missing.s - using defaults.", and the surface is
// not added; cpfg checks the file exists first).
TEST(ViewFileTest, AMissingSurfaceIsLeftOutWithAWarning) {
  std::string dir = test::make_temp_dir("inputs-surface");
  std::filesystem::copy_file(input("leaf.s"), dir + "/leaf.s");
  std::string view = write_file(dir, "v.v", "// surfaces\nsurface:   missing.s 2\nsurface: leaf.s\n");
  io::InputFiles in = io::read_input_files({view});
  ASSERT_EQ(in.surfaces.size(), 1u);  // Surface(0) is leaf.s
  EXPECT_EQ(in.surfaces[0].name, "leaf");
  ASSERT_EQ(in.view->surfaces.size(), 1u);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_EQ(in.warnings[0], view + ":2:12: warning: cannot open the surface file " + dir +
                                "/missing.s; the surface is left out, as in lpfg and cpfg");
}

}  // namespace
}  // namespace sylva
