#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

namespace sylva::test {
namespace {

// The Koch curve of the thesis (section 9.1.1), worked by hand: one step turns
// F(1) into the seven-module generator.
TEST(Smoke, KochOneStep) {
  std::string dir = make_temp_dir("smoke");
  std::string model = dir + "/koch.l";
  {
    std::ofstream out(model);
    out << "#include <lpfgall.h>\nderivation length: 1;\naxiom: F(1);\n"
           "F(v) : { produce F(1) Left(60) F(1) Right(120) F(1) Left(60) F(1); }\n";
  }
  EXPECT_EQ(derive_string(model), "F(1) Left(60) F(1) Right(120) F(1) Left(60) F(1)");
}

}  // namespace
}  // namespace sylva::test
