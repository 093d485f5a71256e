// View files read as cpfg reads them (ViewDialect::Cpfg): each rule from the
// CPFG manual (8.1) or, where the manual says nothing, from what cpfg's
// ReadViewData, read_light (irisGL.c) and read_movement (movements.c) do.
#include <gtest/gtest.h>

#include <string>

#include "inputs/input_files.h"
#include "inputs/input_test_helpers.h"
#include "inputs/view_file.h"

namespace sylva {
namespace {

using geometry::LineStyle;
using geometry::Vec3;
using test::expect_vec;
using test::write_file;

io::ViewFile read_cpfg(const std::string& dir, const std::string& name, const std::string& text) {
  return io::read_view_file(write_file(dir, name, text), "", io::ViewDialect::Cpfg);
}

bool has_warning(const io::ViewFile& v, const std::string& part) {
  for (const std::string& w : v.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

TEST(CpfgViewFileTest, CameraCommandsAndCpfgsDefaults) {
  std::string dir = test::make_temp_dir("cpfg-view-camera");
  io::ViewFile d = read_cpfg(dir, "empty.v", "/* nothing */\n");
  ASSERT_TRUE(d.view(0).cpfg.has_value());
  const geometry::CpfgView& none = *d.view(0).cpfg;
  // The manual's defaults (8.1.2).
  expect_vec(none.viewpoint, {0, 0, 1});
  expect_vec(none.reference_point, {0, 0, 0});
  EXPECT_EQ(none.twist, 0);
  EXPECT_FLOAT_EQ(none.viewing_angle, 45);
  EXPECT_FLOAT_EQ(none.scale, 1);
  EXPECT_FLOAT_EQ(none.front_distance, -100000);
  EXPECT_FLOAT_EQ(none.back_distance, 100000);
  EXPECT_FALSE(none.box || d.view(0).perspective);
  EXPECT_TRUE(d.render.z_buffer);  // on in cpfg (8.1.4)
  EXPECT_TRUE(d.warnings.empty());

  io::ViewFile v = read_cpfg(dir, "camera.v",
                             "viewpoint: 0,5,20\n"
                             "view reference point: 0, 7 ,0\n"
                             "twist: 450\n"
                             "projection: parallel\n"
                             "viewing angle: 40\n"
                             "front distance: -10.0\n"
                             "back distance: 40\n"
                             "scale factor: 0.98\n"
                             "box: x: -16,16 y: -50,70 z: -1,1\n");
  const geometry::CpfgView& c = *v.view(0).cpfg;
  expect_vec(c.viewpoint, {0, 5, 20});
  expect_vec(c.reference_point, {0, 7, 0});
  EXPECT_EQ(c.twist, 450);
  EXPECT_FLOAT_EQ(c.viewing_angle, 40);
  EXPECT_FLOAT_EQ(c.front_distance, -10);
  EXPECT_FLOAT_EQ(c.back_distance, 40);
  EXPECT_FLOAT_EQ(c.scale, 0.98f);
  ASSERT_TRUE(c.box.has_value());
  expect_vec(c.box->min, {-16, -50, -1});
  expect_vec(c.box->max, {16, 70, 1});
  EXPECT_TRUE(v.warnings.empty()) << v.warnings[0];
}

TEST(CpfgViewFileTest, LpfgsFormsAreNotCpfgs) {
  std::string dir = test::make_temp_dir("cpfg-view-lpfg-forms");
  // cpfg reads "box: x: ..." only, and knows no "scale:" (only "scale factor:").
  io::ViewFile v = read_cpfg(dir, "lpfg.v", "box: 0 -1 1 -1 1 -1 1\nscale: 0.5\nscale factor: 0\n");
  EXPECT_FALSE(v.view(0).cpfg->box);
  EXPECT_FLOAT_EQ(v.view(0).cpfg->scale, 1);  // cpfg takes a scale factor of 0 as 1
  ASSERT_EQ(v.warnings.size(), 2u);
  EXPECT_NE(v.warnings[0].find(":1:6: warning: expected 'x:', found '0'; 'box:' ignored"), std::string::npos) << v.warnings[0];
  EXPECT_NE(v.warnings[1].find(":2:1: warning: lpfg command 'scale' ignored: cpfg does not read it"), std::string::npos)
      << v.warnings[1];
}

TEST(CpfgViewFileTest, PerspectiveClippingIsCorrectedAsCpfgDoes) {
  std::string dir = test::make_temp_dir("cpfg-view-clip");
  // After the file: a negative front distance becomes 0.1, and a front beyond
  // the back makes them 1 and 100 (the end of ReadViewData).
  io::ViewFile negative = read_cpfg(dir, "neg.v", "projection: perspective\nback distance: 50\n");
  EXPECT_FLOAT_EQ(negative.view(0).cpfg->front_distance, 0.1f);
  EXPECT_FLOAT_EQ(negative.view(0).cpfg->back_distance, 50);
  io::ViewFile crossed = read_cpfg(dir, "crossed.v", "projection: perspective\nfront distance: 60\nback distance: 50\n");
  EXPECT_FLOAT_EQ(crossed.view(0).cpfg->front_distance, 1);
  EXPECT_FLOAT_EQ(crossed.view(0).cpfg->back_distance, 100);
  // In parallel projection they stay as given.
  io::ViewFile parallel = read_cpfg(dir, "par.v", "front distance: 60\nback distance: 50\n");
  EXPECT_FLOAT_EQ(parallel.view(0).cpfg->front_distance, 60);
  // The same viewpoint and reference point: cpfg's fallback view.
  io::ViewFile same = read_cpfg(dir, "same.v", "viewpoint: 1,1,1\nview reference point: 1,1,1\n");
  expect_vec(same.view(0).cpfg->viewpoint, {0, 0, -1});
  EXPECT_TRUE(has_warning(same, "the viewpoint and the view reference point are the same"));
}

TEST(CpfgViewFileTest, LineStylesRenderModesAndShadeModes) {
  std::string dir = test::make_temp_dir("cpfg-view-render");
  // "wireframe" is no line style: cpfg keeps the one it had (and so does lpfg).
  io::ViewFile wire = read_cpfg(dir, "wire.v", "line style: cylinder\nline style: wireframe\n");
  EXPECT_EQ(wire.render.line_style, LineStyle::Cylinder);
  ASSERT_EQ(wire.warnings.size(), 1u);
  EXPECT_NE(wire.warnings[0].find(":2:13: warning: expected a line style (pixel, polygon, cylinder), found 'wireframe'"),
            std::string::npos)
      << wire.warnings[0];
  // Styles and modes by their numbers from 1.
  EXPECT_EQ(read_cpfg(dir, "ls3.v", "line style: 3\n").render.line_style, LineStyle::Cylinder);
  EXPECT_EQ(read_cpfg(dir, "ls2.v", "line style: 2\n").render.line_style, LineStyle::Polygon);
  using M = geometry::RenderMode;
  const std::pair<const char*, M> modes[] = {{"fast", M::Filled},        {"interpolated", M::Filled}, {"flat", M::Shaded},
                                            {"wireframe", M::Wireframe}, {"shadows", M::Shadows},     {"1", M::Wireframe},
                                            {"5", M::Shaded}};
  for (const auto& [word, mode] : modes)
    EXPECT_EQ(read_cpfg(dir, "rm.v", std::string("render mode: ") + word + "\n").render.mode, mode) << word;
  // The deprecated shade mode: 3 is Gouraud shading, 7 wireframe, 1 filled;
  // a NURBS sampling number may follow.
  EXPECT_EQ(read_cpfg(dir, "sm3.v", "shade mode: 3\n").render.mode, M::Shaded);
  EXPECT_EQ(read_cpfg(dir, "sm7.v", "shade mode: 7 0.5\n").render.mode, M::Wireframe);
  EXPECT_EQ(read_cpfg(dir, "sm1.v", "render mode: shaded\nshade mode: 1\n").render.mode, M::Filled);
  // cpfg's flags: anything but a word starting with "on" is off.
  EXPECT_FALSE(read_cpfg(dir, "zb.v", "z buffer: yes\n").render.z_buffer);
}

TEST(CpfgViewFileTest, InitialLineWidthSetsTheLineStyle) {
  std::string dir = test::make_temp_dir("cpfg-view-width");
  // Without a style word the lines are polygons; p... pixels, s... cylinders.
  io::ViewFile plain = read_cpfg(dir, "a.v", "line style: cylinder\ninitial line width: 4\n");
  EXPECT_EQ(plain.render.line_style, LineStyle::Polygon);
  EXPECT_FLOAT_EQ(*plain.initial_line_width, 4);
  EXPECT_EQ(read_cpfg(dir, "b.v", "initial line width: 4 pixels\n").render.line_style, LineStyle::Pixel);
  EXPECT_EQ(read_cpfg(dir, "c.v", "initial line width: 4 pixel\n").render.line_style, LineStyle::Pixel);
  EXPECT_EQ(read_cpfg(dir, "d.v", "initial line width: 2 s\n").render.line_style, LineStyle::Cylinder);
  // A later line style wins.
  EXPECT_EQ(read_cpfg(dir, "e.v", "initial line width: 2 p\nline style: cylinder\n").render.line_style,
            LineStyle::Cylinder);
}

TEST(CpfgViewFileTest, LightsAsCpfgReadsThem) {
  std::string dir = test::make_temp_dir("cpfg-view-lights");
  io::ViewFile v = read_cpfg(dir, "l.v",
                             "light: V: -0.5,-1.0,-2.0 A: 0.6 0.6 0.6 D 0.6 0.6 0.6 S: 0 0 0\n"
                             "light: O: 4.0 5.0 8.0 A 0 0 0 D 1 0.3 0.3 P -4 -4 -8 0 4\n"
                             "light: A: 0.2 0.2 0.2\n"
                             "light: Diffuse: 0.5 0.5 0.5 V 0 1 0 O: 1 2 3\n");
  ASSERT_EQ(v.lights.size(), 4u) << v.warnings[0];
  EXPECT_EQ(v.lights[0].kind, geometry::Light::Kind::Directional);
  expect_vec(v.lights[0].direction, {-0.5f, -1, -2});
  EXPECT_EQ(v.lights[0].diffuse, (geometry::Rgb{0.6f, 0.6f, 0.6f}));
  EXPECT_EQ(v.lights[0].specular, (geometry::Rgb{0, 0, 0}));
  EXPECT_EQ(v.lights[1].kind, geometry::Light::Kind::Spot);
  expect_vec(v.lights[1].position, {4, 5, 8});
  expect_vec(v.lights[1].direction, {-4, -4, -8});
  EXPECT_FLOAT_EQ(v.lights[1].spot_cutoff, 4);
  EXPECT_EQ(v.lights[1].diffuse, (geometry::Rgb{1, 0.3f, 0.3f}));
  // Without V: or O:, cpfg's light is a point at (0,0,1).
  EXPECT_EQ(v.lights[2].kind, geometry::Light::Kind::Point);
  expect_vec(v.lights[2].position, {0, 0, 1});
  // A key is a word's first letter; of V and O the last one given holds.
  EXPECT_EQ(v.lights[3].diffuse, (geometry::Rgb{0.5f, 0.5f, 0.5f}));
  EXPECT_EQ(v.lights[3].kind, geometry::Light::Kind::Point);
  expect_vec(v.lights[3].position, {1, 2, 3});
  EXPECT_TRUE(v.warnings.empty());
}

TEST(CpfgViewFileTest, TheDefaultLightShinesAlongTheLightDirection) {
  std::string dir = test::make_temp_dir("cpfg-view-light-direction");
  // Without light: commands cpfg lights along "light direction:", (1,0,0) by default.
  expect_vec(read_cpfg(dir, "none.v", "\n").lights_or_default()[0].direction, {1, 0, 0});
  io::ViewFile v = read_cpfg(dir, "dir.v", "light direction: 0.0, 3.0, 4.0\n");
  ASSERT_EQ(v.lights_or_default().size(), 1u);
  EXPECT_EQ(v.lights_or_default()[0].kind, geometry::Light::Kind::Directional);
  expect_vec(v.lights_or_default()[0].direction, {0, 0.6f, 0.8f});
}

TEST(CpfgViewFileTest, TropismsAsCpfgReadsThem) {
  std::string dir = test::make_temp_dir("cpfg-view-tropisms");
  io::ViewFile v = read_cpfg(dir, "t.v",
                             "tropism: T: 0,2,0 E: 0.2\n"        // T: made unit length
                             "tropism: T: 0 2 0 I: 0.5 A: 30\n"  // times the intensity
                             "tropism: T: 0 1 0 I: 5\n"          // kept within -1 and 1
                             "tropism: I: 0.5 T: 0 2 0\n"        // before T: an intensity makes 0: not kept
                             "torque: T: 1 0 0 E: 0.3 S: 0.1\n"
                             "tropism: E: 0.3\n");               // no T: no direction
  ASSERT_EQ(v.tropisms.size(), 5u);
  ASSERT_EQ(v.warnings.size(), 1u);
  EXPECT_NE(v.warnings[0].find(":4:13: warning: a tropism of intensity 0"), std::string::npos) << v.warnings[0];
  expect_vec(v.tropisms[0].direction, {0, 1, 0});
  EXPECT_FLOAT_EQ(v.tropisms[0].elasticity, 0.2f);
  expect_vec(v.tropisms[1].direction, {0, 0.5f, 0});
  EXPECT_FLOAT_EQ(v.tropisms[1].angle, 30);
  expect_vec(v.tropisms[2].direction, {0, 1, 0});
  EXPECT_TRUE(v.tropisms[3].torque);
  EXPECT_FLOAT_EQ(v.tropisms[3].step, 0.1f);
  expect_vec(v.tropisms[4].direction, {0, 0, 0});
  // The deprecated tropism (8.1.10).
  io::ViewFile old = read_cpfg(dir, "old.v", "tropism direction: 0,-3,4\ninitial elasticity: 0.4\nelasticity increment: -0.06\n");
  expect_vec(old.old_tropism.direction, {0, -0.6f, 0.8f});
  EXPECT_FLOAT_EQ(old.old_tropism.initial_elasticity, 0.4f);
  EXPECT_FLOAT_EQ(old.old_tropism.elasticity_increment, -0.06f);
}

TEST(CpfgViewFileTest, ContoursFunctionsAndCurvesAreNamedBesideTheViewFile) {
  std::string dir = test::make_temp_dir("cpfg-view-files");
  io::ViewFile v = read_cpfg(dir, "f.v",
                             "contour: 2 leaf.con\n"
                             "function: internode.func 100\n"
                             "function set: functions.fset\n"
                             "function: last.func\n"
                             "curve: profile.con\n");
  ASSERT_EQ(v.contour_files.size(), 1u);
  EXPECT_EQ(v.contour_files[0].id, 2);
  EXPECT_EQ(v.contour_files[0].path, dir + "/leaf.con");
  ASSERT_EQ(v.function_files.size(), 3u);
  EXPECT_EQ(v.function_files[0].path, dir + "/internode.func");
  EXPECT_EQ(v.function_files[0].samples, 100);
  EXPECT_TRUE(v.function_files[1].set);
  EXPECT_EQ(v.function_files[2].samples, 0);
  ASSERT_EQ(v.curve_files.size(), 1u);
  EXPECT_EQ(v.curve_files[0].samples, 100);  // cpfg's default
  EXPECT_TRUE(v.warnings.empty());
}

TEST(CpfgViewFileTest, UnreadableValuesAndOtherCommandsAreWarnings) {
  std::string dir = test::make_temp_dir("cpfg-view-warnings");
  io::ViewFile v = read_cpfg(dir, "w.v",
                             "angle increment: ?\n"
                             "window: Top 0 0 1 1\n"
                             "diffuse reflection: 10\n"
                             "cue range: 0\n"
                             "tsurface: t leaf.ray 1\n");
  EXPECT_FLOAT_EQ(v.angle_increment, 45);  // kept, as cpfg keeps it
  ASSERT_EQ(v.warnings.size(), 4u);
  EXPECT_NE(v.warnings[0].find(":1:18: warning: expected the angle increment, found '?'; 'angle increment:' ignored"),
            std::string::npos)
      << v.warnings[0];
  EXPECT_NE(v.warnings[1].find(":2:1: warning: lpfg command 'window' ignored: cpfg does not read it"), std::string::npos);
  EXPECT_NE(v.warnings[2].find(":3:1: warning: 'diffuse reflection:' ignored"), std::string::npos);
  EXPECT_NE(v.warnings[3].find(":5:1: warning: 'tsurface:' ignored"), std::string::npos);
  EXPECT_TRUE(v.windows.empty());
}

// ---- the files a cpfg view file names ---------------------------------------------------

const char* kContour = "cver 1 3\nname: c\npoints: 4 4\n0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\ntype: cr\nsamples: 10\n";
const char* kFunction = "fver 1 1\nname: NAME\nsamples: 10\nflip: off\npoints: 4\n0 0\n0.3 1\n0.6 1\n1 0\n";

std::string function_named(const std::string& name) {
  std::string f = kFunction;
  return f.replace(f.find("NAME"), 4, name);
}

TEST(CpfgViewFileInputsTest, ContoursGoToTheirIds) {
  std::string dir = test::make_temp_dir("cpfg-inputs-contours");
  write_file(dir, "a.con", kContour);
  std::string view = write_file(dir, "v.v", "contour: 3 a.con\ncontour: 1 gone.con\ncontour: 2 a.con\n");
  io::InputFiles in = io::read_input_files({view}, "", io::ViewDialect::Cpfg);
  // Id 3 in place, ids 1 and 2 circles: cpfg reads no contour after one it
  // cannot read (process_contours stops).
  ASSERT_EQ(in.contours.size(), 3u);
  EXPECT_EQ(in.contours[2].name, "c");
  EXPECT_EQ(in.contours[0].curve, geometry::Contour::Curve::Circle);
  EXPECT_EQ(in.contours[1].curve, geometry::Contour::Curve::Circle);
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_NE(in.warnings[0].find(view + ":2:12: warning: cannot open the contour file"), std::string::npos) << in.warnings[0];
}

TEST(CpfgViewFileInputsTest, FunctionsInOrderASetReplacingThoseBefore) {
  std::string dir = test::make_temp_dir("cpfg-inputs-functions");
  write_file(dir, "first.func", function_named("first"));
  write_file(dir, "second.func", function_named("second"));
  write_file(dir, "set.fset", "funcgalleryver 1 1\nitems: 2\n" + function_named("alpha") + function_named("beta"));
  std::string plain = write_file(dir, "plain.v", "function: first.func 100\nfunction: gone.func\nfunction: second.func\n");
  io::InputFiles a = io::read_input_files({plain}, "", io::ViewDialect::Cpfg);
  // func(1, x), func(2, x), func(3, x); the missing one is 0 everywhere and
  // keeps the ids after it. Files given by function: are not named.
  ASSERT_EQ(a.functions.size(), 3u);
  EXPECT_DOUBLE_EQ(geometry::CpfgFunction(a.functions[1]).value(0.5), 0);
  EXPECT_GT(geometry::CpfgFunction(a.functions[2]).value(0.5), 0.5);
  EXPECT_TRUE(a.functions[0].name.empty());
  EXPECT_EQ(a.functions[0].samples, 10);  // the file's own, not the view file's 100
  std::string set = write_file(dir, "set.v", "function: first.func\nfunction set: set.fset\n");
  io::InputFiles b = io::read_input_files({set}, "", io::ViewDialect::Cpfg);
  ASSERT_EQ(b.functions.size(), 2u);
  EXPECT_EQ(b.functions[0].name, "alpha");  // a set's functions keep their names
  EXPECT_EQ(b.functions[1].name, "beta");
}

// cpfg's curve files (CCurveXYZ::readCurve): keys, then the points, each
// repeated by its multiplicity (the fourth number); a phantom B-spline gets a
// point mirrored beyond each end (createPPoints).
TEST(CpfgViewFileInputsTest, CurvesInCpfgsCurveFormat) {
  std::string dir = test::make_temp_dir("cpfg-inputs-curves");
  write_file(dir, "open.con",
             "version: 1.4\ncontact: 0 0 0\nend: 0 0 0\nheading: 0 1 0\nup: 0 0 -1\nsize: 1\npoints: 4\n"
             "range: 0.0 1.0\ndimension: 4\ntype: bspline\n0 0 0 3\n1 0 0 1\n1 1 0 1\n0 1 0 3\n");
  write_file(dir, "phantom.con", "version: 1.4\npoints: 3\ndimension: 2\ntype: bspline-phantom\n0 0\n1 0\n1 1\n");
  write_file(dir, "bezier.con", "version: 1.4\npoints: 4\ndimension: 2\ntype: bezier\n0 0\n1 0\n1 1\n0 1\n");
  write_file(dir, "cuspy.con", kContour);
  std::string view = write_file(dir, "v.v", "curve: open.con\ncurve: phantom.con\ncurve: bezier.con\ncurve: cuspy.con 50\n");
  io::InputFiles in = io::read_input_files({view}, "", io::ViewDialect::Cpfg);
  ASSERT_EQ(in.curves.size(), 3u);
  EXPECT_TRUE(in.contours.empty());  // curves are not the turtle's contours
  const geometry::Contour& open = in.curves[0];
  EXPECT_FALSE(open.closed);
  ASSERT_EQ(open.points.size(), 8u);
  expect_vec(open.points[2], {0, 0, 0});
  expect_vec(open.points[3], {1, 0, 0});
  expect_vec(open.points[7], {0, 1, 0});
  const geometry::Contour& phantom = in.curves[1];
  ASSERT_EQ(phantom.points.size(), 5u);
  expect_vec(phantom.points[0], {-1, 0, 0});
  expect_vec(phantom.points[4], {1, 2, 0});
  EXPECT_EQ(in.curves[2].name, "c");
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_NE(in.warnings[0].find("bezier.con:4:7: warning: curves of type 'bezier' are not supported; the curve is left out"),
            std::string::npos)
      << in.warnings[0];
}

TEST(CpfgViewFileInputsTest, AnLpfgModelsViewFileNamesNoFunctions) {
  std::string dir = test::make_temp_dir("lpfg-inputs-functions");
  write_file(dir, "first.func", function_named("first"));
  std::string view = write_file(dir, "v.v", "function: first.func\ncontour: 1 a.con\n");
  io::InputFiles in = io::read_input_files({view});
  EXPECT_TRUE(in.functions.empty());
  EXPECT_TRUE(in.contours.empty());
  ASSERT_EQ(in.warnings.size(), 2u);
  EXPECT_NE(in.warnings[0].find("'function:' ignored: lpfg takes functions from the command line"), std::string::npos);
  EXPECT_NE(in.warnings[1].find("cpfg command 'contour' ignored: lpfg does not read it"), std::string::npos);
}

}  // namespace
}  // namespace sylva
