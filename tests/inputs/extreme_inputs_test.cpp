// Input files that once stopped a reader or what uses its result (found by
// the fuzz targets in fuzz/): each now reads, or fails at its line, without
// undefined behaviour (the ASan+UBSan build checks that part).
#include <gtest/gtest.h>

#include <string>

#include "geometry/contour.h"
#include "inputs/contour_file.h"

namespace sylva::test {
namespace {

TEST(ExtremeInputs, AContourWithPointsTooFarApartToMeasureIsStillSampled) {
  // Its arc length is infinite, so every sample's place along it is NaN.
  const geometry::Contour c =
      io::parse_contour("3 2 open\n0.5 -1\n1 066666666666666666666666666666666\n0.5 1\n", "far.con");
  EXPECT_EQ(c.resample(8).size(), 8u);
  c.at_parameter(0.5);
}

}  // namespace
}  // namespace sylva::test
