// L+C as lpfg's translator reads it beyond the manual's examples.
#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

namespace sylva::test {
namespace {

// lpfg's translator makes a produce statement a block of its own, so one can
// be a production's whole body, without braces. Worked by hand: A(1) and
// B(2) age by 1 a step; after two steps A(3) B(4).
TEST(LcDialect, AProduceStatementCanBeTheWholeBody) {
  std::string dir = make_temp_dir("lc-braceless");
  std::string model = dir + "/age.l";
  std::ofstream(model) << "#include <lpfgall.h>\nmodule A(float); module B(float);\n"
                          "derivation length: 2;\naxiom: A(1) B(2);\nproduction:\n"
                          "A(t) : produce A(t+1);\nB(t) :\n\tproduce B(t + 1);\n";
  EXPECT_EQ(derive_string(model), "A(3) B(4)");
}

}  // namespace
}  // namespace sylva::test
