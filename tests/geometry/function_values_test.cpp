// cpfg's and lpfg's evaluation of function files, checked against the
// reference programs' values: cpfg -g -str on a model whose parameters are
// func(id, x) (cpfg prints %g; a second run printed (func - c) * 1e6 for
// more digits), lpfg -b on a model that Printf's func(id, x) with %.9g.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "geometry/function.h"
#include "inputs/function_file.h"
#include "test_support.h"

namespace sylva::geometry {
namespace {

std::string write(const std::string& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir + "/" + name) << text;
  return dir + "/" + name;
}

const char* const kRise =
    "fver 1 1\nname: rise\nsamples: 20\nflip: off\npoints: 4\n"
    "0.000000 0.100000\n0.300000 0.900000\n0.700000 0.200000\n1.000000 1.000000\n";
// A point given twice (multiplicity 2), and 2 samples: cpfg tabulates
// nothing and bisects every value.
const char* const kBump =
    "fver 1 1\nname: bump\nsamples: 2\nflip: off\npoints: 5\n"
    "0.000000 0.000000 1\n0.250000 0.000000 1\n0.500000 1.000000 2\n0.750000 0.000000 1\n1.000000 0.000000 1\n";
// The older format, without samples of its own: cpfg takes the view file's.
const char* const kOld = "range: 0.0 1.0\npoints: 4\n0 1\n0.25 0.8\n0.75 0.2\n1 0\n";

// The view file said: function: rise.func 100 / bump.func / old.func 20 /
// old2.func (the same as old.func).
TEST(CpfgFunctionValues, AsCpfgComputesThem) {
  const std::string dir = test::make_temp_dir("cpfg-function-values");
  const CpfgFunction rise(io::read_cpfg_function_file(write(dir, "rise.func", kRise), 100));
  const CpfgFunction bump(io::read_cpfg_function_file(write(dir, "bump.func", kBump)));
  const CpfgFunction old20(io::read_cpfg_function_file(write(dir, "old.func", kOld), 20));
  const CpfgFunction old(io::read_cpfg_function_file(write(dir, "old2.func", kOld)));
  // B(0.102339,0.525746,0.997661,0.102339,0.997661)C(0.30715,0.567351,0.711855,0.383311,0.383558)
  EXPECT_NEAR(rise.value(0), 0.102339, 5e-7);
  EXPECT_NEAR(rise.value(1), 0.997661, 5e-7);
  EXPECT_NEAR(rise.value(-1), 0.102339, 5e-7);
  EXPECT_NEAR(rise.value(2), 0.997661, 5e-7);
  EXPECT_NEAR(bump.value(0.3), 0.30715, 5e-6);
  EXPECT_NEAR(old20.value(0.3), 0.711855, 5e-7);
  // B(0.34701,0.328209,0.123813,0.562805): (func - c) * 1e6.
  EXPECT_NEAR((rise.value(0.37) - 0.525746) * 1e6, 0.34701, 5e-6);
  EXPECT_NEAR((bump.value(0.61) - 0.567351) * 1e6, 0.328209, 5e-7);
  EXPECT_NEAR((old20.value(0.61) - 0.383311) * 1e6, 0.123813, 5e-7);
  EXPECT_NEAR((old.value(0.61) - 0.383557) * 1e6, 0.562805, 5e-7);
}

// lpfg, on the same curve as rise.func (Printf %.9g): float throughout.
TEST(LpfgFunctionValues, AsLpfgComputesThem) {
  const std::string dir = test::make_temp_dir("lpfg-function-values");
  const LpfgFunction rise(io::read_function_file(write(dir, "rise.func", kRise)));
  EXPECT_EQ(rise.value(0), 0.101170801f);
  EXPECT_EQ(rise.value(0.37f), 0.525475919f);
  EXPECT_EQ(rise.value(1), 0.998829186f);
  const Vec2 t = rise.tangent(0.37f);
  EXPECT_EQ(t.x, 1.04066181f);
  EXPECT_EQ(t.y, 0.29007256f);
}

}  // namespace
}  // namespace sylva::geometry
