// Sizes an input file gives that no real model comes near (a hundred million
// samples, a surface of 10^5 by 10^5 subdivisions) are refused at their line
// and column before anything is allocated for them.
#include <gtest/gtest.h>

#include <string>

#include "inputs/contour_file.h"
#include "inputs/curve_file.h"
#include "inputs/function_file.h"
#include "inputs/label_font.h"
#include "inputs/view_file.h"
#include "input_test_helpers.h"

namespace sylva::test {
namespace {

TEST(AbsurdSizes, ContourSamplesAndPoints) {
  const std::string dir = make_temp_dir("absurd-contours");
  const std::string samples =
      write_file(dir, "s.con", "cver 1 3\nname: c\npoints: 4 4\n0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\ntype: cr\nsamples: 100000000\n");
  EXPECT_EQ(error_of([&] { io::read_contour_file(samples); }),
            samples + ":9:10: error: the number of samples 100000000 is past the limit of 100000, far above any real "
                      "model's (is the file damaged?)");
  const std::string points = write_file(dir, "p.con", "cver 1 3\nname: c\npoints: 2000000000 4\n");
  EXPECT_EQ(error_of([&] { io::read_contour_file(points); }),
            points + ":3:9: error: the number of control points 2000000000 is past the limit of 1000000, far above "
                     "any real model's (is the file damaged?)");
}

TEST(AbsurdSizes, FunctionSamples) {
  const std::string dir = make_temp_dir("absurd-functions");
  const std::string path =
      write_file(dir, "f.func", "fver 1 1\nname: f\nsamples: 999999999\nflip: off\npoints: 4\n0 0\n0.3 1\n0.6 1\n1 0\n");
  EXPECT_EQ(error_of([&] { io::read_function_file(path); }),
            path + ":3:10: error: the number of samples 999999999 is past the limit of 100000, far above any real "
                   "model's (is the file damaged?)");
}

TEST(AbsurdSizes, CurveMultiplicity) {
  const std::string dir = make_temp_dir("absurd-curves");
  const std::string path = write_file(dir, "c.crv",
                                      "version: 1.4\npoints: 4\nrange: 0.0 1.0\ndimension: 4\ntype: bspline\n0 0 0 1\n"
                                      "1 0 0 1e9\n1 1 0 1\n0 1 0 1\n");
  EXPECT_EQ(error_of([&] { io::read_curve_file(path); }),
            path + ":7:7: error: the multiplicity of point 2 of 4 is past the limit of 1000, far above any real "
                   "curve's (is the file damaged?)");
}

TEST(AbsurdSizes, ViewFileSurfaceSubdivisionsAndIds) {
  const std::string dir = make_temp_dir("absurd-view");
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {"surface: a.s 1 100000 100000",
       ":1:16: warning: the subdivisions along s 100000 is past the limit of 1000, far above any real model's (is the "
       "file damaged?); 'surface:' ignored"},
      {"contour: 100000000 c.con",
       ":1:10: warning: the contour id 100000000 is past the limit of 10000, far above any real model's (is the file "
       "damaged?); 'contour:' ignored"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = write_file(dir, "v" + std::to_string(i) + ".v", cases[i].text + "\n");
    const io::ViewDialect dialect = i == 0 ? io::ViewDialect::Lpfg : io::ViewDialect::Cpfg;  // contour: is cpfg's
    io::ViewFile view;
    EXPECT_EQ(error_of([&] { view = io::read_view_file(path, "", dialect); }), "") << cases[i].text;
    ASSERT_EQ(view.warnings.size(), 1u) << cases[i].text;
    EXPECT_EQ(view.warnings[0], path + cases[i].expected) << cases[i].text;
  }
}

TEST(AbsurdSizes, AFontSizePastAnIntIsNoSize) {
  EXPECT_EQ(io::parse_x_font("-*-courier-bold-r-*-*-99999999999-*-*-*-*-*-*-*").points,
            io::parse_x_font("-*-courier-bold-r-*-*-*-*-*-*-*-*-*-*").points);
}

}  // namespace
}  // namespace sylva::test
