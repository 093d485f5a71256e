// clover as the Virtual Laboratory's program computes it (ENVIRO/clover):
// the unit tests' values are worked by hand from its rules (cell = floor of
// the scaled position; a leaf covers the cells of an ellipse of half-width
// (int)(r / cell + 1) around its cell, -n <= i < n; light = light / 255 *
// t^leaves). The model at the end was run with the reference cpfg and the
// reference clover, built from the Virtual Laboratory's sources.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>

#include "env/light/light_test_support.h"
#include "env/programs/programs.h"
#include "render/png_renderer.h"

namespace sylva::test::light {
namespace {

using env::make_clover;

constexpr float kPi = std::numbers::pi_v<float>;

// A 10 x 10 grid of unit cells from (0, 0): the cell of (u, v) is (floor u, floor v).
std::string unit_grid(const std::string& extra = "") {
  return "grid range: 10 10\ngrid position: 0 0\ngrid size: 10 10\ntransmittance: 0.5\n" + extra;
}

std::unique_ptr<env::Field> clover(const std::string& test, const std::string& spec) {
  return make_clover(invocation_with_file(test, "clover", "clover.spec", spec));
}

TEST(CloverTest, ALeafCoversTheCellsOfItsEllipse) {
  auto field = clover("clover-leaves", unit_grid());
  // Area pi: radius 1, half-width (int)(1 / 1 + 1) = 2 cells around (5, 5):
  // offsets -2..1 with i^2/4 + j^2/4 <= 1, so (3, 5) and (5, 3) are covered
  // but not (7, 5), (5, 7) or (3, 4).
  std::vector<env::Query> q{query_at(5.5f, 5.5f, 0, {1, kPi}), query_at(5.5f, 5.5f, 0, {1, kPi}),
                            query_at(5.5f, 5.5f, 0, {1, kPi}),
                            query_at(5.2f, 5.7f, 0, {0, 0}),   // (5, 5): 3 leaves
                            query_at(3.1f, 5.9f, 0, {0, 0}),   // (3, 5): 3 leaves
                            query_at(7.5f, 5.5f, 0, {0, 0}),   // (7, 5): open
                            query_at(5.5f, 7.5f, 0, {0, 0}),   // (5, 7): open
                            query_at(3.5f, 4.5f, 0, {0, 0}),   // (3, 4): open
                            query_at(5.5f, 3.5f, 0, {7})};     // one parameter: a query, (5, 3)
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[3].value[0], 0.125f);  // 0.5^3
  EXPECT_FLOAT_EQ(a[4].value[0], 0.125f);
  EXPECT_FLOAT_EQ(a[5].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[6].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[7].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[8].value[0], 0.125f);
  // A query with two parameters is answered two values (the second is the
  // image's, 0 without one); with one parameter, one. Leaves get nothing.
  for (int i : {3, 4, 5, 6, 7}) {
    EXPECT_EQ(a[i].set.count(), 2u) << i;
    EXPECT_EQ(a[i].value[1], 0.0f) << i;
  }
  EXPECT_EQ(a[8].set.count(), 1u);
  for (int i : {0, 1, 2}) EXPECT_TRUE(a[i].set.none()) << i;
}

TEST(CloverTest, ASmallLeafCoversThreeCells) {
  auto field = clover("clover-small", unit_grid());
  // Area 0.5: radius 0.40, half-width 1: offsets (-1, 0), (0, -1) and (0, 0).
  std::vector<env::Query> q{query_at(2.5f, 2.5f, 0, {1, 0.5f}), query_at(1.5f, 2.5f, 0, {0}),
                            query_at(2.5f, 1.5f, 0, {0}),        query_at(2.9f, 2.1f, 0, {0}),
                            query_at(1.5f, 1.5f, 0, {0}),        query_at(3.5f, 2.5f, 0, {0}),
                            query_at(7.5f, 7.5f, 0, {1, 1e-8f}), query_at(7.5f, 7.5f, 0, {0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[1].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[2].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[3].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[4].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[5].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[7].value[0], 1.0f);  // an area below 1e-7 is no leaf
}

TEST(CloverTest, LeavesAreEnteredBeforeQueriesOfTheSamePass) {
  auto field = clover("clover-order", unit_grid());
  // The query comes first in the string but the leaf after it still shades it.
  std::vector<env::Query> q{query_at(2.5f, 2.5f, 0, {0, 0}), query_at(2.5f, 2.5f, 0, {1, 0.5f})};
  EXPECT_FLOAT_EQ(answer_all(*field, q)[0].value[0], 0.5f);
}

TEST(CloverTest, LeavesStayUntilRemovedAndAnyOtherActionRemoves) {
  auto field = clover("clover-keep", unit_grid());
  std::vector<env::Query> add{query_at(5.5f, 5.5f, 0, {1, 2}), query_at(5.5f, 5.5f, 0, {1, 2})};
  answer_all(*field, add, 0);
  std::vector<env::Query> look{query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, look, 1)[0].value[0], 0.25f);
  // 2 removes a leaf, and so does 3 (anything but 0 and 1).
  std::vector<env::Query> remove{query_at(5.5f, 5.5f, 0, {2, 2}), query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, remove, 2)[1].value[0], 0.5f);
  std::vector<env::Query> three{query_at(5.5f, 5.5f, 0, {3, 2}), query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, three, 3)[1].value[0], 1.0f);
  // Removing more leaves than there are leaves the cell open, not brighter.
  std::vector<env::Query> extra{query_at(5.5f, 5.5f, 0, {2, 2}), query_at(5.5f, 5.5f, 0, {1, 2}),
                                query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, extra, 4)[2].value[0], 0.5f);
}

TEST(CloverTest, RemoveOldLeavesStartsEachPassFromAnEmptyGrid) {
  auto field = clover("clover-remove", unit_grid("remove old leaves: on\n"));
  std::vector<env::Query> first{query_at(5.5f, 5.5f, 0, {1, 2}), query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, first, 0)[1].value[0], 0.5f);
  std::vector<env::Query> second{query_at(5.5f, 5.5f, 0, {0, 0})};
  EXPECT_FLOAT_EQ(answer_all(*field, second, 1)[0].value[0], 1.0f);
}

TEST(CloverTest, OutsideTheGridThereIsNoLight) {
  // A transmittance of 0 is read as 0.0001.
  testing::internal::CaptureStderr();
  auto field = clover("clover-outside", "grid range: 4 2\ngrid position: -2 -1\ngrid size: 8 4\ntransmittance: 0\n");
  EXPECT_NE(testing::internal::GetCapturedStderr().find("a transmittance of 0 is read as 0.0001"), std::string::npos);
  std::vector<env::Query> q{query_at(-1.99f, -0.99f, 0, {0}), query_at(1.99f, 0.99f, 0, {0}),
                            query_at(2.01f, 0, 0, {0}),       query_at(0, -1.01f, 0, {0}),
                            query_at(0.1f, 0.1f, 0, {1, 0.1f}), query_at(0.1f, 0.1f, 0, {0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[1].value[0], 1.0f);
  EXPECT_FLOAT_EQ(a[2].value[0], 0.0f);
  EXPECT_FLOAT_EQ(a[3].value[0], 0.0f);
  EXPECT_FLOAT_EQ(a[5].value[0], 0.0001f);
}

TEST(CloverTest, WithZNotUpTheGroundIsXZ) {
  auto field = clover("clover-yup", unit_grid("z is up: off\n"));
  // The leaf at x = 5.5, z = 5.5 (y = 9, ignored) shades (5.5, 0, 5.5) but not
  // (5.5, 5.5, 0.5).
  std::vector<env::Query> q{query_at(5.5f, 9, 5.5f, {1, 1}), query_at(5.5f, 0, 5.5f, {0, 0}),
                            query_at(5.5f, 5.5f, 0.5f, {0, 0}), query_at(5.5f, 0, 5.5f, {0})};
  q[3].turtle.position_count = 2;  // x z needs three values: no answer
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[1].value[0], 0.5f);
  EXPECT_FLOAT_EQ(a[2].value[0], 1.0f);
  EXPECT_TRUE(a[3].set.none());
}

// A 2 x 2 picture over a 4 x 4 grid: cell c samples pixel (int)(c * 1/3),
// so cells 0..2 take the first pixel and cell 3 the second. PNG: the bottom
// row of the picture is row 0, and the last row and column are never copied
// (0). Light is green / 255, the second answer red / 128.
TEST(CloverTest, APngImageGivesLightAndASecondValue) {
  std::string dir = make_temp_dir("clover-png");
  io::Image image;
  image.width = 2;
  image.height = 2;
  image.rgb = {9, 255, 9, 0, 51, 200, /* bottom */ 64, 102, 0, 255, 10, 255};
  io::write_png(dir + "/light.png", image);
  std::ofstream(dir + "/clover.spec") << "grid range: 4 4\ngrid position: 0 0\ngrid size: 4 4\n"
                                         "transmittance: 0.5\ninput image: light.png\n";
  auto field = make_clover(env::ProgramInvocation{"clover", {"clover.spec"}, dir, dir + "/field.e", 1});
  std::vector<env::Query> q{query_at(0.5f, 0.5f, 0, {0, 0}), query_at(2.5f, 2.5f, 0, {0, 0}),
                            query_at(3.5f, 0.5f, 0, {0, 0}), query_at(0.5f, 3.5f, 0, {0, 0}),
                            query_at(1.5f, 1.5f, 0, {1, 1}), query_at(1.5f, 1.5f, 0, {0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[0].value[0], 102 / 255.0f);
  EXPECT_FLOAT_EQ(a[0].value[1], 64 / 128.0f);
  EXPECT_FLOAT_EQ(a[1].value[0], 102 / 255.0f);
  EXPECT_FLOAT_EQ(a[2].value[0], 0.0f);  // the last column
  EXPECT_FLOAT_EQ(a[3].value[0], 0.0f);  // the top row
  EXPECT_FLOAT_EQ(a[5].value[0], 0.5f * 102 / 255.0f);  // under one leaf
}

// A 3 x 3 SGI image, run-length encoded, channel c of row y (0 = bottom)
// and column x holding the value `value(c, y, x)`.
std::vector<std::uint8_t> sgi_image(int (*value)(int, int, int)) {
  const int size = 3, channels = 3, rows = size * channels;
  std::vector<std::uint8_t> bytes(512, 0);
  auto put16 = [&](std::size_t at, int v) {
    bytes[at] = static_cast<std::uint8_t>(v >> 8);
    bytes[at + 1] = static_cast<std::uint8_t>(v);
  };
  put16(0, 474);
  bytes[2] = 1;  // run-length encoded
  bytes[3] = 1;  // one byte per value
  put16(4, 3);
  put16(6, size);
  put16(8, size);
  put16(10, channels);
  std::vector<std::uint8_t> data;
  std::vector<std::uint32_t> starts, lengths;
  const std::uint32_t first = 512 + 8 * rows;
  for (int c = 0; c < channels; ++c)
    for (int y = 0; y < size; ++y) {
      starts.push_back(first + static_cast<std::uint32_t>(data.size()));
      data.push_back(0x80 | size);  // a literal run of three values, then the end
      for (int x = 0; x < size; ++x) data.push_back(static_cast<std::uint8_t>(value(c, y, x)));
      data.push_back(0);
      lengths.push_back(size + 2);
    }
  for (std::uint32_t v : starts) bytes.insert(bytes.end(), {std::uint8_t(v >> 24), std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)});
  for (std::uint32_t v : lengths) bytes.insert(bytes.end(), {std::uint8_t(v >> 24), std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v)});
  bytes.insert(bytes.end(), data.begin(), data.end());
  return bytes;
}

// A cpfg model with two leaves, a small removal and queries around them on
// an 8 x 8 grid, run with the image `image` (written as `name`). The
// expected strings below are what the reference cpfg printed with the
// reference clover (cpfg -g -M plant.mat -str out.str -e light.e light.l
// light.v): answers travel as "%g".
std::string run_light_model(const std::string& test, const std::string& name, const std::vector<std::uint8_t>& image) {
  const std::string dir = make_temp_dir(test);
  std::ofstream(dir + "/" + name, std::ios::binary)
      .write(reinterpret_cast<const char*>(image.data()), static_cast<std::streamsize>(image.size()));
  std::ofstream(dir + "/light.l")
      << "Lsystem: 1\nderivation length: 1\nAxiom: @M(0,0,0)?E(1,0.19635)@M(0.3,0,0)?E(1,0.19635)@M(0.3,0,0)"
         "?E(2,0.01)@M(0.1,0.1,0)?E(0,0)@M(-0.2,0.05,0)?E(0,0)@M(0.55,0.05,0)?E(0,0)@M(0.8,0.05,0)?E(0,0)"
         "@M(-0.55,0.05,0)?E(0,0)@M(-0.45,0.05,0)?E(0,0)@M(1,0,0)?E(0,0)@M(-1,-1,0)?E(0,0)@M(0.05,0.55,0)?E(0,0)"
         "@M(0.05,-0.45,0)?E(0,0)@M(0.9,0.9,0)?E(0,0)@M(0.9,-0.9,0)?E(0,0)@M(-0.9,0.9,0)?E(0)\nF --> F\n"
         "endlsystem\n";
  std::ofstream(dir + "/light.e") << "executable: clover -e light.e light.spec\ncommunication type: pipes\n"
                                     "turtle position: %g %g %g\n";
  // "2,2" and "8 x 8": the separators clover's reader accepts.
  std::ofstream(dir + "/light.spec") << "grid size: 8 x 8\ngrid range: 2,2\ngrid position: -1 -1\n"
                                        "transmittance: 0.5\ninput image: " << name << "\n";
  ProcessResult run = run_sylva({"run", "-e", "light.e", "light.l"}, dir);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return run.out;
}

constexpr const char* kLightModelStart =
    "@M(0,0,0)?E(1,0.19635)@M(0.3,0,0)?E(1,0.19635)@M(0.3,0,0)?E(2,0.01)@M(0.1,0.1,0)";

TEST(CloverTest, ACpfgModelGetsTheReferenceAnswersWithAnSgiImage) {
  const std::vector<std::uint8_t> image =
      sgi_image([](int c, int y, int x) { return c == 0 ? 60 * x + 20 * y : c == 1 ? 40 + 70 * y + 20 * x : 7; });
  EXPECT_EQ(run_light_model("clover-cpfg-sgi", "light.rgb", image),
            std::string(kLightModelStart) +
                "?E(0.254902,0.625)"
                "@M(-0.2,0.05,0)?E(0.107843,0.15625)@M(0.55,0.05,0)?E(0.254902,0.625)@M(0.8,0.05,0)?E(0.588235,1.09375)"
                "@M(-0.55,0.05,0)?E(0.431373,0.15625)@M(-0.45,0.05,0)?E(0.215686,0.15625)@M(1,0,0)?E(0,0)"
                "@M(-1,-1,0)?E(0.156863,0)@M(0.05,0.55,0)?E(0.509804,0.625)@M(0.05,-0.45,0)?E(0.117647,0.46875)"
                "@M(0.9,0.9,0)?E(0.862745,1.25)@M(0.9,-0.9,0)?E(0.313726,0.9375)@M(-0.9,0.9,0)?E(0.705882)\n");
}

// A 3 x 3 Targa image, 24 bits, origin at the top left; file row k, column x
// holds blue 5 + k, green 30 + 60x + 10k, red 100 + 40k + 20x. `runs`
// encodes it in packets: row 0 one raw packet, row 1 a run of two and a raw
// one, row 2 a run of three repeating its first pixel.
std::vector<std::uint8_t> targa_image(bool runs) {
  auto pixel = [](int k, int x) {
    return std::vector<std::uint8_t>{std::uint8_t(5 + k), std::uint8_t(30 + 60 * x + 10 * k),
                                     std::uint8_t(100 + 40 * k + 20 * x)};
  };
  std::vector<std::uint8_t> bytes = {0, 0, std::uint8_t(runs ? 10 : 2), 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 3, 0, 24, 0x20};
  auto add = [&](const std::vector<std::uint8_t>& b) { bytes.insert(bytes.end(), b.begin(), b.end()); };
  if (!runs) {
    for (int k = 0; k < 3; ++k)
      for (int x = 0; x < 3; ++x) add(pixel(k, x));
    return bytes;
  }
  add({0x02});
  for (int x = 0; x < 3; ++x) add(pixel(0, x));
  add({0x81});
  add(pixel(1, 0));
  add({0x00});
  add(pixel(1, 2));
  add({0x82});
  add(pixel(2, 0));
  return bytes;
}

TEST(CloverTest, ACpfgModelGetsTheReferenceAnswersWithTargaImages) {
  EXPECT_EQ(run_light_model("clover-cpfg-tga", "light.tga", targa_image(false)),
            std::string(kLightModelStart) +
                "?E(0.313726,0.78125)@M(-0.2,0.05,0)?E(0.137255,0.3125)@M(0.55,0.05,0)?E(0.313726,0.78125)"
                "@M(0.8,0.05,0)?E(0.705882,1.25)@M(-0.55,0.05,0)?E(0.54902,0.3125)@M(-0.45,0.05,0)?E(0.27451,0.3125)"
                "@M(1,0,0)?E(0,0)@M(-1,-1,0)?E(0.705882,0.390625)@M(0.05,0.55,0)?E(0.627451,0.78125)"
                "@M(0.05,-0.45,0)?E(0.392157,0.859375)@M(0.9,0.9,0)?E(0.54902,1.17188)@M(0.9,-0.9,0)"
                "?E(0.862745,1.32812)@M(-0.9,0.9,0)?E(0.392157)\n");
  // In run-length packets the light comes from the pixels' blue.
  EXPECT_EQ(run_light_model("clover-cpfg-tga-rle", "light_rle.tga", targa_image(true)),
            std::string(kLightModelStart) +
                "?E(0.0117647,0.3125)@M(-0.2,0.05,0)?E(0.00588235,0.3125)@M(0.55,0.05,0)?E(0.0117647,0.3125)"
                "@M(0.8,0.05,0)?E(0.705882,1.25)@M(-0.55,0.05,0)?E(0.0235294,0.3125)@M(-0.45,0.05,0)"
                "?E(0.0117647,0.3125)@M(1,0,0)?E(0,0)@M(-1,-1,0)?E(0.027451,0.390625)@M(0.05,0.55,0)"
                "?E(0.0235294,0.3125)@M(0.05,-0.45,0)?E(0.0137255,0.390625)@M(0.9,0.9,0)?E(0.54902,1.17188)"
                "@M(0.9,-0.9,0)?E(0.027451,0.390625)@M(-0.9,0.9,0)?E(0.392157)\n");
}

// The specification file as clover reads it: "100x100view.pnl" is two
// numbers, 100 and 100 (atof), an unknown line is passed over, a missing
// file leaves the defaults (a 2 x 2 grid of 512 x 512 cells from (-1, -1),
// transmittance 0.6).
TEST(CloverTest, ReadsItsFileAsTheRealProgramDoes) {
  testing::internal::CaptureStderr();
  auto field = clover("clover-syntax", "grid position: -50 -50\ngrid range: 100x100view.pnl\ngrid size: 10x10\n"
                                       "colour: green\ntransmittance: 0.25\n");
  const std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_NE(warnings.find("clover.spec:2: warning: '100view.pnl' is not a number"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("clover.spec:4: warning: clover does not know 'colour'"), std::string::npos) << warnings;
  // Cells of 10 x 10 from (-50, -50): a leaf of area 1 at (5, 5) covers cell (5, 5).
  std::vector<env::Query> q{query_at(5, 5, 0, {1, 1}), query_at(9, 9, 0, {0}), query_at(-45, -45, 0, {0})};
  auto a = answer_all(*field, q);
  EXPECT_FLOAT_EQ(a[1].value[0], 0.25f);
  EXPECT_FLOAT_EQ(a[2].value[0], 1.0f);

  env::ProgramInvocation missing{"clover", {"-e", "field.e", "/nonexistent/clover.spec"}, ".", "field.e", 3};
  testing::internal::CaptureStderr();
  auto defaults = make_clover(missing);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("cannot open its specification file"), std::string::npos);
  // Cells of 2/512 from -1; a leaf of area 1e-4 (radius 0.0056, half-width 2).
  std::vector<env::Query> d{query_at(0.001f, 0.001f, 0, {1, 1e-4f}), query_at(0.001f, 0.001f, 0, {0}),
                            query_at(0.99f, 0.99f, 0, {0}), query_at(1.01f, 0, 0, {0})};
  auto b = answer_all(*defaults, d);
  EXPECT_FLOAT_EQ(b[1].value[0], 0.6f);
  EXPECT_FLOAT_EQ(b[2].value[0], 1.0f);
  EXPECT_FLOAT_EQ(b[3].value[0], 0.0f);
}

TEST(CloverTest, ASpecificationFileMustBeNamed) {
  env::ProgramInvocation invocation{"clover", {"-e", "field.e"}, ".", "field.e", 3};
  EXPECT_EQ(error_of([&] { make_clover(invocation); }),
            "field.e:3: error: clover needs its specification file: 'executable: clover [-e commfile.e] specfile'");
}

}  // namespace
}  // namespace sylva::test::light
