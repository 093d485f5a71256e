// clover (EnviroManual 3.2.1): light from above through leaves stored in a 2D
// grid. Expected values are worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "env/programs/programs.h"
#include "env/light/light_test_support.h"
#include "io/png_renderer.h"

namespace sylva::test::light {
namespace {

using env::make_clover;

constexpr float kPi = std::numbers::pi_v<float>;

// A 10 x 10 grid of unit voxels from (0, 0): voxel (i, j) has its centre at
// (i + 0.5, j + 0.5).
std::string unit_grid(const std::string& extra = "") {
  return "grid range: 10 10\ngrid position: 0 0\ngrid size: 10 10\ntransmittance: 0.5\n" + extra;
}

TEST(CloverTest, LightPassingLeavesIsTransmittancePowerLeafCount) {
  auto field = make_clover(invocation_with_file("clover-leaves", "clover", "clover.par", unit_grid()));
  // Three leaves of area pi (radius 1) at (5, 5) cover the four voxels whose
  // centres (4.5|5.5, 4.5|5.5) lie 0.71 from it; (6.5, 5.5) is 1.58 away.
  std::vector<env::Query> q{query_at(5, 5, 0, {1, kPi}), query_at(5, 5, 0, {1, kPi}), query_at(5, 5, 0, {1, kPi}),
                            query_at(5.2f, 5.7f, 0, {0, 0}),  // voxel (5, 5): under 3 leaves
                            query_at(4.1f, 4.9f, 0, {0, 0}),  // voxel (4, 4): under 3 leaves
                            query_at(6.5f, 5.5f, 0, {0, 0}),  // voxel (6, 5): open sky
                            query_at(5.5f, 3.5f, 0, {7})};    // one parameter: a query, voxel (5, 3)
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[3].value[0], 0.125f);  // 0.5^3
  EXPECT_FLOAT_EQ(a[4].value[0], 0.125f);
  EXPECT_FLOAT_EQ(a[5].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[6].value[0], 1.0f);
  // Only p1 of light queries is answered; leaf modules are left alone.
  for (int i : {3, 4, 5, 6}) EXPECT_EQ(a[i].set.count(), 1u) << i;
  for (int i : {0, 1, 2}) EXPECT_TRUE(a[i].set.none()) << i;
}

TEST(CloverTest, LeavesAreEnteredBeforeQueriesOfTheSamePass) {
  auto field = make_clover(invocation_with_file("clover-order", "clover", "clover.par", unit_grid()));
  // The query comes first in the string but the leaf after it still shades it.
  std::vector<env::Query> q{query_at(2.5f, 2.5f, 0, {0, 0}), query_at(2.5f, 2.5f, 0, {1, 0.5f})};
  EXPECT_FLOAT_EQ(answer_all(*field, q)[0].value[0], 0.5f);
}

TEST(CloverTest, SmallLeafCoversOnlyVoxelsWhoseCentresItContains) {
  auto field = make_clover(invocation_with_file("clover-small", "clover", "clover.par", unit_grid()));
  // Radius sqrt(0.5 / pi) = 0.40: around (2.5, 2.5) it covers voxel (2, 2)
  // only; around (3.0, 3.0) it covers no centre (the nearest are 0.71 away).
  std::vector<env::Query> q{query_at(2.5f, 2.5f, 0, {1, 0.5f}), query_at(3.0f, 3.0f, 0, {1, 0.5f}),
                            query_at(2.9f, 2.1f, 0, {0, 0}), query_at(3.1f, 3.1f, 0, {0, 0}),
                            query_at(1.9f, 2.5f, 0, {0, 0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[2].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[3].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[4].value[0], 1.0f);
}

TEST(CloverTest, LeavesStayUntilRemoved) {
  auto field = make_clover(invocation_with_file("clover-keep", "clover", "clover.par", unit_grid()));
  std::vector<env::Query> add{query_at(5.5f, 5.5f, 0, {1, 2}), query_at(5.5f, 5.5f, 0, {1, 2})};
  answer_all(*field, add, 0);
  std::vector<env::Query> look{query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, look, 1)[0].value[0], 0.25f);
  std::vector<env::Query> remove{query_at(5.5f, 5.5f, 0, {2, 2}), query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, remove, 2)[1].value[0], 0.5f);
  // Removing more leaves than there are leaves the voxel open, not brighter.
  std::vector<env::Query> extra{query_at(5.5f, 5.5f, 0, {2, 2}), query_at(5.5f, 5.5f, 0, {2, 2}),
                                query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, extra, 3)[2].value[0], 1.0f);
}

TEST(CloverTest, RemoveOldLeavesClearsTheGridAfterEachPass) {
  auto field = make_clover(
      invocation_with_file("clover-remove", "clover", "clover.par", unit_grid("remove old leaves: yes\n")));
  std::vector<env::Query> first{query_at(5.5f, 5.5f, 0, {1, 2}), query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, first, 0)[1].value[0], 0.5f);
  std::vector<env::Query> second{query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, second, 1)[0].value[0], 1.0f);
}

TEST(CloverTest, OutsideTheGridThereIsNoLight) {
  auto field = make_clover(invocation_with_file("clover-outside", "clover", "clover.par",
                                                "grid range: 4 2\ngrid position: -2 -1\ngrid size: 8 4\n"
                                                "transmittance: 0\n"));
  std::vector<env::Query> q{query_at(-1.99f, -0.99f, 0, {0}), query_at(1.99f, 0.99f, 0, {0}),
                            query_at(2.01f, 0, 0, {0}), query_at(0, -1.01f, 0, {0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[1].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[2].value[0], 0.0f);
  EXPECT_FLOAT_EQ(a[3].value[0], 0.0f);
}

TEST(CloverTest, WithYUpTheGroundIsXZ) {
  auto field =
      make_clover(invocation_with_file("clover-yup", "clover", "clover.par", unit_grid("z is up: no\n")));
  // The leaf at x = 5.5, z = 5.5 (y = 9, ignored) shades (5.5, 0, 5.5) but not
  // (5.5, 5.5, 0.5).
  std::vector<env::Query> q{query_at(5.5f, 9, 5.5f, {1, 1}), query_at(5.5f, 0, 5.5f, {0, 0}),
                            query_at(5.5f, 5.5f, 0.5f, {0, 0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[1].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[2].value[0], 1.0f);
}

TEST(CloverTest, InputImageGreenChannelGivesInitialIntensity) {
  std::string dir = make_temp_dir("clover-image");
  // 2 x 2 pixels; green 255 and 51 on the top row, 102 and 0 on the bottom.
  io::Image image;
  image.width = 2;
  image.height = 2;
  image.rgb = {9, 255, 9, 0, 51, 200, /* bottom */ 0, 102, 0, 255, 0, 255};
  io::write_png(dir + "/light.png", image);
  std::ofstream(dir + "/clover.par") << "grid range: 4 4\ngrid position: 0 0\ngrid size: 4 4\n"
                                        "transmittance: 0.5\ninput image: light.png\n";
  env::ProgramInvocation invocation{"clover", {"clover.par"}, dir, dir + "/field.e", 1};
  auto field = make_clover(invocation);
  // The image covers the grid with its top row at the high-y edge: each
  // quarter of the 4 x 4 grid takes one pixel.
  std::vector<env::Query> q{query_at(0.5f, 3.5f, 0, {0, 0}), query_at(3.5f, 3.5f, 0, {0, 0}),
                            query_at(1.5f, 0.5f, 0, {0, 0}), query_at(2.5f, 1.5f, 0, {0, 0}),
                            query_at(0.5f, 0.5f, 0, {1, 1}), query_at(0.5f, 0.5f, 0, {0, 0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[1].value[0], 51 / 255.0f);
  EXPECT_FLOAT_EQ(a[2].value[0], 102 / 255.0f);
  EXPECT_FLOAT_EQ(a[3].value[0], 0.0f);
  EXPECT_FLOAT_EQ(a[5].value[0], 0.5f * 102 / 255.0f);  // under one leaf
}

TEST(CloverTest, UnknownActionIsAnError) {
  auto field = make_clover(invocation_with_file("clover-action", "clover", "clover.par", unit_grid()));
  std::vector<env::Query> q{query_at(1, 1, 0, {3, 0})};
  std::string message = error_of([&] { answer_all(*field, q); });
  EXPECT_NE(message.find("clover"), std::string::npos) << message;
  EXPECT_NE(message.find("expected 0 (light query), 1 (add a leaf) or 2 (remove a leaf)"), std::string::npos)
      << message;
}

TEST(CloverTest, MissingTurtlePositionIsAnError) {
  auto field = make_clover(invocation_with_file("clover-position", "clover", "clover.par", unit_grid()));
  std::vector<env::Query> q{query_at(1, 1, 0, {0, 0})};
  q[0].turtle.position_count = 0;
  EXPECT_NE(error_of([&] { answer_all(*field, q); }).find("turtle position: %g %g %g"), std::string::npos);
}

// Parameter file errors name the file, line and column, and what was expected.
std::string clover_error(const std::string& text) {
  auto invocation = invocation_with_file("clover-errors", "clover", "clover.par", text);
  std::string message = error_of([&] { make_clover(invocation); });
  std::string prefix = (invocation.directory / "clover.par").string();
  EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
  return message.substr(std::min(message.size(), prefix.size()));
}

TEST(CloverTest, ParameterFileErrors) {
  EXPECT_EQ(clover_error("grid range 10 10\n"),
            ":1:1: error: clover: expected a command 'keyword: values' (e.g. 'transmittance: 0.5'), found 'grid range "
            "10 10'");
  EXPECT_EQ(clover_error("grid range: 10 10\n  grid sise: 10 10\n"),
            ":2:3: error: clover: unknown command 'grid sise:'; expected one of 'grid range:', 'grid position:', "
            "'grid size:', 'transmittance:', 'input image:', 'remove old leaves:', 'z is up:', 'verbose:'");
  EXPECT_EQ(clover_error("grid range: 10 ten\n"),
            ":1:16: error: clover: expected a number (the grid's width and depth in world units), found 'ten'");
  EXPECT_EQ(clover_error("grid range: 10\n"),
            ":1:15: error: clover: expected 2 numbers after 'grid range:' (the grid's width and depth in world "
            "units), found 1");
  EXPECT_EQ(clover_error("grid size: 10 2.5\n"),
            ":1:15: error: clover: expected a positive whole number (voxels along the two ground axes), found 2.5");
  EXPECT_EQ(clover_error(unit_grid("transmittance: 1.5\n")),
            ":5:16: error: clover: expected the transmittance of leaves between 0 and 1, found 1.5");
  EXPECT_EQ(clover_error(unit_grid("z is up: maybe\n")),
            ":5:10: error: clover: expected yes or no (also on/off) after 'z is up:'");
  EXPECT_EQ(clover_error("grid range: 10 10\ntransmittance: 0.5\n"),
            ": error: clover: the parameter file has no 'grid size: x y' line");
  std::string image = clover_error(unit_grid("input image: missing.png\n"));
  EXPECT_EQ(image.rfind(":5:14: error: clover: input image ", 0), 0u) << image;
  EXPECT_NE(image.find("missing.png: cannot read the file"), std::string::npos) << image;
}

TEST(CloverTest, ParameterFileAcceptsCommentsCaseAndSeparators) {
  auto field = make_clover(invocation_with_file("clover-syntax", "clover", "clover.par",
                                                "# a field\n\nGrid Range: 10, 10\ngrid  size: 10x10\n"
                                                "grid position: 0 0\ntransmittance: 0.25\nverbose: off\n"));
  std::vector<env::Query> q{query_at(1.5f, 1.5f, 0, {1, 1}), query_at(1.5f, 1.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, q)[1].value[0], 0.25f);
}

TEST(CloverTest, MissingParameterFileArgumentIsAnError) {
  env::ProgramInvocation invocation{"clover", {"-e", "field.e"}, ".", "field.e", 3};
  EXPECT_EQ(error_of([&] { make_clover(invocation); }),
            "field.e:3: error: clover: expected a parameter file after the program name, e.g. 'executable: clover -e "
            "field.e clover.par'");
}

}  // namespace
}  // namespace sylva::test::light
