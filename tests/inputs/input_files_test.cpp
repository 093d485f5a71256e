// The readers of lpfg's other input files (animation, colormap, material,
// surface, contour, function) and the dispatch on extensions: values read
// from hand-written files and checked by hand, the defaults, and errors that
// name file, line and column.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "inputs/animation_file.h"
#include "inputs/contour_file.h"
#include "inputs/function_file.h"
#include "inputs/input_files.h"
#include "inputs/input_test_helpers.h"
#include "inputs/palette_files.h"
#include "inputs/surface_file.h"

namespace sylva {
namespace {

using geometry::Vec3;
using test::error_of;
using test::expect_vec;
using test::input;
using test::write_file;

// --- Animation file -----------------------------------------------------------

TEST(AnimationFileTest, ReadsEveryCommand) {
  io::AnimationFile a = io::read_animation_file(input("plant.a"));
  EXPECT_EQ(a.first_frame, 2);
  EXPECT_EQ(a.last_frame, 9);
  EXPECT_EQ(a.step, 3);
  EXPECT_FLOAT_EQ(a.swap_interval, 5);
  EXPECT_FALSE(a.double_buffer);
  EXPECT_FALSE(a.clear_between_frames);
  EXPECT_TRUE(a.new_view_between_frames);
  EXPECT_TRUE(a.display_on_request);
  EXPECT_FALSE(a.hcenter_between_frames);
  EXPECT_FALSE(a.scale_between_frames);
  EXPECT_TRUE(a.stepno_frame_numbers);
  EXPECT_EQ(a.frames(20), (std::vector<int>{2, 5, 8}));
  EXPECT_EQ(a.frames(6), (std::vector<int>{2, 5}));
  EXPECT_TRUE(a.warnings.empty());
}

// The editors write "last frame: -1" for "up to the derivation length";
// lpfg and cpfg read numbers with %d, so "130 " and huge values are read too.
TEST(AnimationFileTest, ReadsTheEditorsDialect) {
  std::string dir = test::make_temp_dir("animation-dialect");
  io::AnimationFile minus_one = io::read_animation_file(write_file(dir, "a.a", "first frame: 1\nlast frame: -1\n"));
  EXPECT_FALSE(minus_one.last_frame);
  EXPECT_EQ(minus_one.frames(3), (std::vector<int>{1, 2, 3}));
  io::AnimationFile huge = io::read_animation_file(write_file(dir, "b.a", "last frame: 2147483647\nstep: 2 \n"));
  EXPECT_EQ(huge.last_frame, 2147483647);
  EXPECT_EQ(huge.frames(5), (std::vector<int>{0, 2, 4}));
  io::AnimationFile trailing = io::read_animation_file(write_file(dir, "c.a", "last frame: 130 \nframe numbers: consecutive\n"));
  EXPECT_EQ(trailing.last_frame, 130);
  EXPECT_FALSE(trailing.stepno_frame_numbers);
  EXPECT_TRUE(trailing.warnings.empty());
}

// Continuous time (docs/continuous-time.md): the run's end and the time between frames.
TEST(AnimationFileTest, ReadsTheTimesOfAContinuousRun) {
  std::string dir = test::make_temp_dir("animation-times");
  io::AnimationFile a = io::read_animation_file(write_file(dir, "t.a", "end time: 575\ntime step: 0.1\n"));
  EXPECT_EQ(a.end_time, 575.0);
  EXPECT_EQ(a.time_step, 0.1);  // as a double, not rounded to a float
  EXPECT_TRUE(a.warnings.empty());
  io::AnimationFile bad = io::read_animation_file(write_file(dir, "u.a", "end time: -1\ntime step: soon\n"));
  EXPECT_FALSE(bad.end_time);
  EXPECT_FALSE(bad.time_step);
  ASSERT_EQ(bad.warnings.size(), 2u);
  EXPECT_NE(bad.warnings[0].find("u.a:1:11: warning: expected a positive time after 'end time:'"), std::string::npos)
      << bad.warnings[0];
}

// cpfg's frame intervals choose the frames on their own: 1, then 3 to 9 every
// 3 steps (3, 6, 9), then 12 and 13 with the file's step of 1.
TEST(AnimationFileTest, ReadsCpfgFrameIntervals) {
  std::string dir = test::make_temp_dir("animation-intervals");
  io::AnimationFile a =
      io::read_animation_file(write_file(dir, "i.a", "step: 1\nframe intervals: 1, 3-9 step 3, 12-13 rotate 0 1 0\n"));
  ASSERT_EQ(a.intervals.size(), 3u);
  EXPECT_EQ(a.first_frame, 1);
  EXPECT_EQ(a.last_frame, 13);
  EXPECT_EQ(a.frames(20), (std::vector<int>{1, 3, 6, 9, 12, 13}));
  EXPECT_EQ(a.frames(7), (std::vector<int>{1, 3, 6}));
}

TEST(AnimationFileTest, DefaultsWhenCommandsAreAbsent) {
  std::string dir = test::make_temp_dir("animation-defaults");
  io::AnimationFile a = io::read_animation_file(write_file(dir, "empty.a", "\n"));
  EXPECT_EQ(a.first_frame, 0);
  EXPECT_FALSE(a.last_frame);
  EXPECT_EQ(a.step, 1);
  EXPECT_TRUE(a.double_buffer);
  EXPECT_TRUE(a.clear_between_frames);
  EXPECT_FALSE(a.new_view_between_frames);
  EXPECT_FALSE(a.display_on_request);
  EXPECT_EQ(a.frames(3), (std::vector<int>{0, 1, 2, 3}));
}

// lpfg and cpfg never stop on an animation file: a value they cannot read is
// a warning at its line and column, and the setting keeps its default.
TEST(AnimationFileTest, BadValuesAreWarningsAtFileLineAndColumn) {
  std::string dir = test::make_temp_dir("animation-bad");
  std::string step = write_file(dir, "step.a", "first frame: 1\n  step: 0\n");
  io::AnimationFile a = io::read_animation_file(step);
  EXPECT_EQ(a.step, 1);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_EQ(a.warnings[0], step + ":2:9: warning: expected a positive number of steps between frames after 'step:', found '0'; ignored");
  std::string flag = write_file(dir, "flag.a", "double buffer: maybe\nfirst frame: x\n");
  io::AnimationFile b = io::read_animation_file(flag);
  EXPECT_TRUE(b.double_buffer);
  EXPECT_EQ(b.first_frame, 0);
  ASSERT_EQ(b.warnings.size(), 2u);
  EXPECT_EQ(b.warnings[0], flag + ":1:16: warning: expected on or off after 'double buffer:', found 'maybe'; ignored");
  EXPECT_EQ(b.warnings[1], flag + ":2:14: warning: expected the first frame after 'first frame:', found 'x'; ignored");
  std::string missing = dir + "/none.a";
  EXPECT_EQ(error_of([&] { io::read_animation_file(missing); }), missing + ": error: cannot open the animation file");
}

// --- Colormaps and materials --------------------------------------------------

TEST(PaletteTest, DefaultPaletteHasBlackBackgroundWhiteFirstColourAndDistinctOthers) {
  geometry::Palette p = geometry::Palette::default_palette();
  EXPECT_FALSE(p.from_materials);
  EXPECT_EQ(p.background(), (geometry::Rgb{0, 0, 0}));
  EXPECT_EQ(p.color(1), (geometry::Rgb{1, 1, 1}));
  std::set<std::tuple<float, float, float>> seen;
  for (int i = 0; i < 256; ++i) seen.insert({p.color(i).r, p.color(i).g, p.color(i).b});
  EXPECT_EQ(seen.size(), 256u);
}

TEST(PaletteTest, ReadsABinaryColormap) {
  std::string bytes;
  for (int i = 0; i < 256; ++i) bytes += {static_cast<char>(i), static_cast<char>(255 - i), static_cast<char>(i / 2)};
  std::string path = write_file(test::make_temp_dir("colormap"), "c.map", bytes);
  geometry::Palette p = io::read_colormap_file(path);
  EXPECT_FALSE(p.from_materials);
  EXPECT_EQ(p.color(0), (geometry::Rgb{0, 1, 0}));
  EXPECT_EQ(p.color(255), (geometry::Rgb{1, 0, 127 / 255.0f}));
  EXPECT_EQ(p.color(51), (geometry::Rgb{0.2f, 204 / 255.0f, 25 / 255.0f}));
  EXPECT_EQ(p.at(51).ambient, p.color(51));
}

TEST(PaletteTest, ColormapOfTheWrongSizeIsAnError) {
  std::string dir = test::make_temp_dir("colormap-bad");
  std::string path = write_file(dir, "short.map", std::string(767, '\0'));
  EXPECT_EQ(error_of([&] { io::read_colormap_file(path); }),
            path + ": error: expected a colormap of 768 bytes (256 RGB triplets), found 767 bytes");
  EXPECT_EQ(error_of([&] { io::read_colormap_file(dir + "/none.map"); }), dir + "/none.map: error: cannot open the colormap file");
}

// cpfg's -m1 a.map -m2 b.map (cpfg/irisGL.c my_getcolormapitem): colour 44
// is entry 44 of colormap 1; 344 (cpfg's 600) entry 88 of colormap 2; a
// colormap no file gave is cpfg's grey (200, 200, 200).
TEST(PaletteTest, SeveralColormapsAsCpfgNumbersThem) {
  const std::string dir = test::make_temp_dir("colormap-banks");
  std::string a, b;
  for (int i = 0; i < 256; ++i) {
    a += {static_cast<char>(i), 10, 20};
    b += {static_cast<char>(i), static_cast<char>(200), 30};
  }
  const std::string map1 = write_file(dir, "a.map", a), map2 = write_file(dir, "b.map2", b);
  io::InputFiles in = io::read_input_files(
      {io::InputFile(map1, io::InputKind::Colormap, 1), io::InputFile(map2, io::InputKind::Colormap, 2)});
  EXPECT_TRUE(in.warnings.empty());
  EXPECT_EQ(in.palette.color(44), (geometry::Rgb{44 / 255.0f, 10 / 255.0f, 20 / 255.0f}));
  EXPECT_EQ(in.palette.color(344), (geometry::Rgb{88 / 255.0f, 200 / 255.0f, 30 / 255.0f}));
  const float grey = 200 / 255.0f;
  EXPECT_EQ(in.palette.color(600), (geometry::Rgb{grey, grey, grey}));  // colormap 3: none
  // Only -m2: the first colormap's colours are grey too.
  io::InputFiles second = io::read_input_files({io::InputFile(map2, io::InputKind::Colormap, 2)});
  EXPECT_EQ(second.palette.color(5), (geometry::Rgb{grey, grey, grey}));
  EXPECT_EQ(second.palette.color(261), (geometry::Rgb{5 / 255.0f, 200 / 255.0f, 30 / 255.0f}));
  // A material set given after the colormaps wins: the colormaps are read past.
  std::string record = {3, 0, 10, 20, 30, 40, 50, 60, 0, 0, 0, 0, 0, 0, 0};
  const std::string mat = write_file(dir, "m.mat", record);
  io::InputFiles later = io::read_input_files(
      {io::InputFile(map1, io::InputKind::Colormap, 1), io::InputFile(mat, io::InputKind::Materials, 2)});
  EXPECT_TRUE(later.palette.from_materials);
  EXPECT_EQ(later.palette.color(259), (geometry::Rgb{40 / 255.0f, 50 / 255.0f, 60 / 255.0f}));
  EXPECT_EQ(later.palette.color(3), (geometry::Rgb{1, 1, 1}));  // cpfg's default material
  ASSERT_EQ(later.warnings.size(), 1u);
  EXPECT_NE(later.warnings[0].find(map1 + ": warning: not used"), std::string::npos) << later.warnings[0];
}

TEST(PaletteTest, ReadsMaterialRecords) {
  // id, transparency, ambient, diffuse, emission, specular, shininess
  std::string bytes = {7, 51, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 64,
                       static_cast<char>(255), 0, 0, 0, 0, static_cast<char>(255), 0, 0, 0, 0, 0, 0, 0, 0, static_cast<char>(200)};
  std::string path = write_file(test::make_temp_dir("material"), "m.mat", bytes);
  geometry::Palette p = io::read_material_file(path);
  EXPECT_TRUE(p.from_materials);
  const geometry::Material& m = p.at(7);
  EXPECT_FLOAT_EQ(m.transparency, 0.2f);
  EXPECT_EQ(m.ambient, (geometry::Rgb{10 / 255.0f, 20 / 255.0f, 30 / 255.0f}));
  EXPECT_EQ(m.diffuse, (geometry::Rgb{40 / 255.0f, 50 / 255.0f, 60 / 255.0f}));
  EXPECT_EQ(m.emission, (geometry::Rgb{70 / 255.0f, 80 / 255.0f, 90 / 255.0f}));
  EXPECT_EQ(m.specular, (geometry::Rgb{100 / 255.0f, 110 / 255.0f, 120 / 255.0f}));
  EXPECT_FLOAT_EQ(m.shininess, 64);
  EXPECT_EQ(p.at(255).diffuse, (geometry::Rgb{1, 0, 0}));
  EXPECT_FLOAT_EQ(p.at(255).shininess, 128);  // clamped to OpenGL's limit
  // An index the file does not name keeps the default material.
  EXPECT_EQ(p.at(1).diffuse, geometry::Material{}.diffuse);
}

TEST(PaletteTest, MaterialFileOfPartialRecordsIsAnError) {
  std::string path = write_file(test::make_temp_dir("material-bad"), "m.mat", std::string(20, '\1'));
  EXPECT_EQ(error_of([&] { io::read_material_file(path); }),
            path + ": error: expected 15-byte material records, found 20 bytes (5 left over)");
}

// --- Surfaces -----------------------------------------------------------------

TEST(SurfaceFileTest, ReadsTheHeaderAndEveryPatch) {
  geometry::BezierSurface s = io::read_surface_file(input("leaf.s"));
  EXPECT_EQ(s.name, "leaf");
  expect_vec(s.contact, {0, 0, 0});
  expect_vec(s.heading, {0, 1, 0});
  expect_vec(s.up, {0, 0, 1});
  EXPECT_FLOAT_EQ(s.size, 2);
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[0].name, "left");
  EXPECT_EQ(s.patches[1].name, "right");
  expect_vec(s.patches[0].points[0], {-1, 0, 0});
  expect_vec(s.patches[0].points[4 * 1 + 2], {-0.3f, 0.7f, 0.1f});  // row 2, column 3
  expect_vec(s.patches[1].points[15], {1, 2, 0.5f});
}

TEST(SurfaceFileTest, ReadsLabelsWrittenWithoutSpaces) {
  geometry::BezierSurface s = io::read_surface_file(input("surfaces/petal.s"));
  expect_vec(s.contact, {0.5f, 0, 0});
  ASSERT_EQ(s.patches.size(), 1u);
  expect_vec(s.patches[0].points[5], {0.33f, 0.33f, 0});
}

TEST(SurfaceFileTest, BadInputsNameFileLineAndColumn) {
  std::string dir = test::make_temp_dir("surface-bad");
  std::string text = test::read_text(input("leaf.s"));
  std::string truncated = write_file(dir, "short.s", text.substr(0, text.rfind("1.0 2.0 0.5")));
  EXPECT_EQ(error_of([&] { io::read_surface_file(truncated); }),
            truncated + ":24:37: error: expected control point 16 of 16 of patch 'right' (x), found the end of the file");
  std::string bad_size = write_file(dir, "size.s", "0 1 0 1 0 1\nCONTACT POINT X: 0 Y: 0 Z: 0\nEND POINT X: 0 Y: 0 Z: 0\n"
                                                   "HEADING X: 0 Y: 1 Z: 0\nUP X: 0 Y: 0 Z: 1\nSIZE: big\n");
  EXPECT_EQ(error_of([&] { io::read_surface_file(bad_size); }), bad_size + ":6:7: error: expected the size, found 'big'");
  std::string no_patch = write_file(dir, "none.s", "0 1 0 1 0 1\nCONTACT POINT X: 0 Y: 0 Z: 0\nEND POINT X: 0 Y: 0 Z: 0\n"
                                                   "HEADING X: 0 Y: 1 Z: 0\nUP X: 0 Y: 0 Z: 1\nSIZE: 1\n");
  EXPECT_EQ(error_of([&] { io::read_surface_file(no_patch); }), no_patch + ":6:8: error: expected a patch, found the end of the file");
  EXPECT_EQ(error_of([&] { io::read_surface_file(dir + "/gone.s"); }), dir + "/gone.s: error: cannot open the surface file");
}

// Surfaces of the older editors carry "PRECISION S: s T: t" after the
// bounding box; lpfg's reader skips that line (lpfg/surface.cpp).
TEST(SurfaceFileTest, ReadsPastThePrecisionLine) {
  std::string dir = test::make_temp_dir("surface-precision");
  std::string patch = "p1\nTOP COLOR: 1 DIFFUSE: 1.0 BOTTOM COLOR: 1 DIFFUSE: 1.0\nAL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n";
  for (int i = 0; i < 16; ++i) patch += std::to_string(i % 4) + " " + std::to_string(i / 4) + " 0\n";
  std::string path = write_file(dir, "bud.s",
                                "0 3 0 3 0 0\nPRECISION S: 5 T: 5\nCONTACT POINT  X: 1.5 Y: 0.00 Z: 0.00\n"
                                "END POINT  X: 1.5 Y: 3.00 Z: 0.00\nHEADING  X: 0.00 Y: 1.00 Z: 0.00\n"
                                "UP  X: 0.00 Y: 0.00 Z: 1.00\nSIZE: 3.0\n" + patch);
  geometry::BezierSurface s = io::read_surface_file(path);
  expect_vec(s.contact, {1.5f, 0, 0});
  EXPECT_FLOAT_EQ(s.size, 3);
  ASSERT_EQ(s.patches.size(), 1u);
  expect_vec(s.patches[0].points[15], {3, 3, 0});
}

// --- Contours -----------------------------------------------------------------

TEST(ContourFileTest, ReadsTheLatestFormatWithMultiplicities) {
  geometry::Contour c = io::read_contour_file(input("cross.con"));
  EXPECT_EQ(c.name, "cross section");
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.curve, geometry::Contour::Curve::BSpline);
  EXPECT_EQ(c.samples, 10);
  // Multiplicities 1, 2, 1, 2: six B-spline control points.
  ASSERT_EQ(c.points.size(), 6u);
  expect_vec(c.points[1], {1, 0, 0});
  expect_vec(c.points[2], {1, 0, 0});
  expect_vec(c.points[3], {1, 1, 0});
  expect_vec(c.points[5], {0, 1, 0.5f});
}

// The contour editor writes "type:" and "samples:" between "points:" and the
// point list (lpfg's reader takes the lines in that order: name, points, type,
// samples, then one line per point).
TEST(ContourFileTest, ReadsTypeAndSamplesBeforeThePoints) {
  std::string dir = test::make_temp_dir("contour-editor-order");
  std::string set = write_file(dir, "c.cset",
                               "contourgalleryver 1 1\nitems: 1\ncver 1 3\nname: calyx\npoints: 3 5\ntype: or\n"
                               "samples: 8\n-2 3 0 3\n0 5 0 1\n2 3 0 1\n");
  std::vector<geometry::Contour> contours = io::read_contour_set_file(set);
  ASSERT_EQ(contours.size(), 1u);
  EXPECT_EQ(contours[0].name, "calyx");
  EXPECT_FALSE(contours[0].closed);
  EXPECT_EQ(contours[0].samples, 8);
  ASSERT_EQ(contours[0].points.size(), 5u);  // multiplicities 3 + 1 + 1
  expect_vec(contours[0].points[2], {-2, 3, 0});
  expect_vec(contours[0].points[4], {2, 3, 0});
}

TEST(ContourFileTest, ReadsTheFirstFormat) {
  geometry::Contour c = io::read_contour_file(input("old.con"));
  EXPECT_EQ(c.name, "old");
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.samples, 0);
  ASSERT_EQ(c.points.size(), 3u);
  expect_vec(c.points[0], {0.5f, -1, 0});
  expect_vec(c.points[2], {0.5f, 1, 0});
}

TEST(ContourFileTest, ReadsAContourSetInOrder) {
  std::vector<geometry::Contour> set = io::read_contour_set_file(input("profiles.cset"));
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set[0].name, "wide");
  EXPECT_FALSE(set[0].closed);
  EXPECT_EQ(set[1].name, "narrow");
  EXPECT_TRUE(set[1].closed);  // ce: closed, end points interpolated
  expect_vec(set[1].points[1], {0, 0.5f, 0});
}

TEST(ContourFileTest, BadInputsNameFileLineAndColumn) {
  std::string dir = test::make_temp_dir("contour-bad");
  std::string type = write_file(dir, "t.con", "cver 1 3\nname: x\npoints: 2 2\n0 0 0 1\n1 0 0 1\ntype: round\n");
  EXPECT_EQ(error_of([&] { io::read_contour_file(type); }),
            type + ":6:7: error: expected a contour type (or, cr, oe, ce, open or closed), found 'round'");
  std::string point = write_file(dir, "p.con", "cver 1 3\nname: x\npoints: 2 2\n0 0 0 1\n1 zero 0 1\ntype: cr\n");
  EXPECT_EQ(error_of([&] { io::read_contour_file(point); }),
            point + ":5:3: error: expected control point 2 of 2 (y), found 'zero'");
  std::string count = write_file(dir, "c.cset", "contourgalleryver 1 1\nitems: 2\ncver 1 3\nname: x\npoints: 2 2\n0 0 0 1\n1 0 0 1\ntype: cr\n");
  EXPECT_EQ(error_of([&] { io::read_contour_set_file(count); }), count + ":8:9: error: expected 'cver', found the end of the file");
  EXPECT_EQ(error_of([&] { io::read_contour_file(dir + "/none.con"); }), dir + "/none.con: error: cannot open the contour file");
}

// --- Functions ----------------------------------------------------------------

TEST(FunctionFileTest, ReadsAFunction) {
  geometry::Function f = io::read_function_file(input("width.func"));
  EXPECT_EQ(f.name, "width");
  EXPECT_EQ(f.samples, 40);
  ASSERT_EQ(f.points.size(), 4u);
  EXPECT_EQ(f.points[0], (geometry::Vec2{0, 1}));
  EXPECT_EQ(f.points[1], (geometry::Vec2{0.25f, 0.8f}));
  EXPECT_EQ(f.points[3], (geometry::Vec2{1, 0}));
}

TEST(FunctionFileTest, ReadsAFunctionSetOfBothFormats) {
  std::vector<geometry::Function> set = io::read_function_set_file(input("curves.fset"));
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set[0].name, "rise");
  EXPECT_EQ(set[0].samples, 10);
  EXPECT_EQ(set[0].points[2], (geometry::Vec2{0.6f, 0.6f}));
  EXPECT_EQ(set[1].name, "curves_2");  // the old format has no name
  ASSERT_EQ(set[1].points.size(), 5u);
  EXPECT_EQ(set[1].points[2], (geometry::Vec2{0.5f, 0.5f}));
}

TEST(FunctionFileTest, BadInputsNameFileLineAndColumn) {
  std::string dir = test::make_temp_dir("function-bad");
  std::string order = write_file(dir, "o.func", "fver 1 1\nname: f\nsamples: 5\nflip: off\npoints: 4\n0 0\n0.5 1\n0.4 1\n1 0\n");
  EXPECT_EQ(error_of([&] { io::read_function_file(order); }),
            order + ":8:1: error: expected x of control point 3 of 4 to be at least the previous point's x (0.500000), found '0.4'");
  std::string few = write_file(dir, "few.func", "fver 1 1\nname: f\npoints: 2\n0 0\n1 1\n");
  EXPECT_EQ(error_of([&] { io::read_function_file(few); }), few + ":3:9: error: expected at least 4 control points, found 2");
  std::string key = write_file(dir, "key.func", "fver 1 1\nnom: f\n");
  EXPECT_EQ(error_of([&] { io::read_function_file(key); }),
            key + ":2:1: error: expected a function key (name:, samples:, flip:, points:), found 'nom:'");
}

// --- All input files ----------------------------------------------------------

TEST(InputFilesTest, ReadsEveryKindInAnyOrder) {
  std::string dir = test::make_temp_dir("inputs-all");
  std::string map = write_file(dir, "c.map", std::string(768, '\x80'));
  io::InputFiles in = io::read_input_files({input("width.func"), input("profiles.cset"), input("plant.v"), map,
                                            input("cross.con"), input("plant.a"), input("curves.fset")});
  ASSERT_TRUE(in.view && in.animation);
  EXPECT_EQ(in.animation->step, 3);
  EXPECT_EQ(in.palette.color(9), (geometry::Rgb{128 / 255.0f, 128 / 255.0f, 128 / 255.0f}));
  // Contours in command-line order; functions in lpfg's: the .fset's, then
  // the .func files'.
  ASSERT_EQ(in.contours.size(), 3u);
  EXPECT_EQ(in.contours[0].name, "wide");
  EXPECT_EQ(in.contours[1].name, "narrow");
  EXPECT_EQ(in.contours[2].name, "cross section");
  ASSERT_EQ(in.functions.size(), 3u);
  EXPECT_EQ(in.functions[0].name, "rise");
  EXPECT_EQ(in.functions[1].name, "curves_2");
  EXPECT_EQ(in.functions[2].name, "width");
  // The view file's surfaces, beside it, with its scale and subdivisions.
  ASSERT_EQ(in.surfaces.size(), 2u);
  EXPECT_EQ(in.surfaces[0].name, "leaf");
  EXPECT_FLOAT_EQ(in.surfaces[0].size, 2 / 1.5f);
  EXPECT_EQ(in.surfaces[0].u_divisions, 6);
  EXPECT_EQ(in.surfaces[0].v_divisions, 4);
  EXPECT_EQ(in.surfaces[1].name, "petal");
  EXPECT_FLOAT_EQ(in.surfaces[1].size, 1);
  // The view file's warnings (its cpfg "angle increment:" and an unknown command).
  EXPECT_EQ(in.warnings.size(), 2u);
  turtle::TurtleSettings t = in.turtle_settings();
  EXPECT_EQ(t.surfaces, &in.surfaces);
  EXPECT_EQ(t.contours, &in.contours);
  EXPECT_EQ(t.contour_sides, 12);
}

TEST(InputFilesTest, NoFilesGiveTheDefaults) {
  io::InputFiles in = io::read_input_files({});
  EXPECT_FALSE(in.view || in.animation);
  EXPECT_EQ(in.palette.color(1), (geometry::Rgb{1, 1, 1}));
  EXPECT_EQ(in.turtle_settings().contour_sides, 16);  // the manual's default
}

// lpfg reads past a file it does not know and keeps the last file of each
// kind; both are warnings here.
TEST(InputFilesTest, UnknownExtensionsAreIgnoredAndALaterViewFileWins) {
  std::string dir = test::make_temp_dir("inputs-bad");
  std::string txt = write_file(dir, "notes.txt", "hello\n");
  io::InputFiles unknown = io::read_input_files({txt});
  ASSERT_EQ(unknown.warnings.size(), 1u);
  EXPECT_EQ(unknown.warnings[0], txt + ": warning: not a kind of input file lpfg or cpfg reads (.txt); ignored");
  std::string a = write_file(dir, "a.v", "contour sides: 5\n"), b = write_file(dir, "b.v", "contour sides: 7\n");
  io::InputFiles two = io::read_input_files({a, b});
  EXPECT_EQ(two.turtle_settings().contour_sides, 7);
  ASSERT_EQ(two.warnings.size(), 1u);
  EXPECT_EQ(two.warnings[0], b + ": warning: a second view file; it replaces " + a + ", as in lpfg and cpfg");
  // A colormap given as cpfg's -m2 is read by its flag whatever its name.
  std::string map2 = write_file(dir, "plant.map2", std::string(768, '\x40'));
  io::InputFiles cpfg = io::read_input_files({io::InputFile(map2, io::InputKind::Colormap, 1)});
  EXPECT_EQ(cpfg.palette.color(3), (geometry::Rgb{64 / 255.0f, 64 / 255.0f, 64 / 255.0f}));
  EXPECT_EQ(error_of([&] { io::read_input_files({dir + "/gone.con"}); }), dir + "/gone.con: error: cannot open the contour file");
}

}  // namespace
}  // namespace sylva
