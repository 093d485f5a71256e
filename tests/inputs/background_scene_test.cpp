// cpfg's background scene files (CPFG manual 8.3; cpfg/background.c): the
// primitives placed by the matrix stack, their materials in the palette's
// background bank.
#include "inputs/background_scene.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "inputs/input_files.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using geometry::Vec3;

void expect_near(Vec3 a, Vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(BackgroundScene, PrimitivesPlacedByTheMatrixStack) {
  const std::string dir = make_temp_dir("background-scene");
  std::ofstream(dir + "/b.dat") << "#define A 0.5\n"
                                   "material\n0.1 0.1 0.1 1\n0.2 0.4 0.6 A\n0 0 0 1\n0 0 0 1\n10\n"
                                   "pushmatrix\n translate 1 2 3\n scale 2 2 2\n rectangle 1 1\n sphere 0.5\npopmatrix\n"
                                   "rotate 90 0 0 1\ncylinder 0.25 2\n"
                                   "multmatrix 1 0 0 0 0 1 0 0 0 0 1 0 5 0 0 1\npolygon 0 0 0 1 0 0 0 1 0\n"
                                   "teapot 3\n";
  const io::BackgroundScene b = io::read_background_scene({dir + "/b.dat"}, "", true);
  ASSERT_EQ(b.materials.size(), 1u);
  EXPECT_EQ(b.materials[0].diffuse, (geometry::Rgb{0.2f, 0.4f, 0.6f}));
  EXPECT_FLOAT_EQ(b.materials[0].transparency, 0.5f);  // the diffuse alpha
  EXPECT_FLOAT_EQ(b.materials[0].shininess, 10);
  // The rectangle (0,0)-(1,1) scaled by 2 then moved by (1,2,3).
  ASSERT_EQ(b.scene.groups.size(), 2u);
  expect_near(b.scene.positions[0], {1, 2, 3});
  expect_near(b.scene.positions[2], {3, 4, 3});
  EXPECT_EQ(b.scene.groups[0].color, io::background_color(0));
  EXPECT_EQ(geometry::Palette::bank_of(io::background_color(0)), io::kBackgroundBank);
  // The sphere at the moved origin, its radius not scaled (as cpfg draws it).
  ASSERT_EQ(b.scene.spheres.size(), 1u);
  expect_near(b.scene.spheres[0].center, {1, 2, 3});
  EXPECT_FLOAT_EQ(b.scene.spheres[0].radius, 0.5f);
  // After popmatrix, rotated 90 degrees about z: the cylinder's axis (local
  // y) points along -x; two discs close it.
  ASSERT_EQ(b.scene.segments.size(), 1u);
  expect_near(b.scene.segments[0].start, {0, 0, 0});
  expect_near(b.scene.segments[0].end, {-2, 0, 0});
  EXPECT_FLOAT_EQ(b.scene.segments[0].start_width, 0.5f);
  EXPECT_EQ(b.scene.circles.size(), 2u);
  // multmatrix takes columns: a translation by 5 along x, then the rotation.
  expect_near(b.scene.positions[4], {0, 5, 0});
  expect_near(b.scene.positions[5], {0, 6, 0});
  ASSERT_EQ(b.warnings.size(), 1u);
  EXPECT_NE(b.warnings[0].find("unknown keyword 'teapot'"), std::string::npos) << b.warnings[0];
}

// The view file names it; drawn only with a colormap or material file, as
// cpfg draws it; its materials go in the palette's background bank.
TEST(BackgroundScene, ReadWithTheInputFiles) {
  const std::string dir = make_temp_dir("background-inputs");
  std::ofstream(dir + "/b.dat") << "material 0 0 0 1 0.5 0.25 1 1\nbox 1 1 1\n";
  std::ofstream(dir + "/v.v") << "background scene: b.dat\n";
  std::ofstream(dir + "/c.map", std::ios::binary) << std::string(768, '\x10');
  const io::InputFiles plain = io::read_input_files({dir + "/v.v"}, "", io::ViewDialect::Cpfg);
  EXPECT_FALSE(plain.background);
  ASSERT_FALSE(plain.warnings.empty());
  EXPECT_NE(plain.warnings.back().find("background scene not drawn"), std::string::npos);
  const io::InputFiles in = io::read_input_files({dir + "/c.map", dir + "/v.v"}, "", io::ViewDialect::Cpfg);
  ASSERT_TRUE(in.background);
  EXPECT_EQ(in.background->groups.size(), 6u);  // the box's faces
  EXPECT_EQ(in.palette.color(io::background_color(0)), (geometry::Rgb{0.5f, 0.25f, 1}));
}

}  // namespace
}  // namespace sylva::test
