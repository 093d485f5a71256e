// Input files that once stopped a reader or what uses its result (found by
// the fuzz targets in fuzz/): each now reads, or fails at its line, without
// undefined behaviour (the ASan+UBSan build checks that part).
#include <gtest/gtest.h>

#include <climits>
#include <string>
#include <vector>

#include "geometry/contour.h"
#include "inputs/animation_file.h"
#include "inputs/contour_file.h"
#include "inputs/input_test_helpers.h"

namespace sylva::test {
namespace {

TEST(ExtremeInputs, AContourWithPointsTooFarApartToMeasureIsStillSampled) {
  // Its arc length is infinite, so every sample's place along it is NaN.
  const geometry::Contour c =
      io::parse_contour("3 2 open\n0.5 -1\n1 066666666666666666666666666666666\n0.5 1\n", "far.con");
  EXPECT_EQ(c.resample(8).size(), 8u);
  c.at_parameter(0.5);
}

TEST(ExtremeInputs, AFrameStepPastTheLastFrameEndsTheFrames) {
  const std::string dir = make_temp_dir("extreme-animation");
  const io::AnimationFile intervals =
      io::read_animation_file(write_file(dir, "i.a", "frame intervals: 1, 3-9 step 4444444444444\n"));
  EXPECT_EQ(intervals.frames(100), (std::vector<int>{1, 3}));
  const io::AnimationFile steps = io::read_animation_file(write_file(dir, "s.a", "first frame: 2\nstep: 9999999999\n"));
  EXPECT_EQ(steps.frames(INT_MAX), (std::vector<int>{2}));
}

}  // namespace
}  // namespace sylva::test
