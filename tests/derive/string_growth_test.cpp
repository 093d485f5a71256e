// A step that turns a tiny string into a huge one (a model that lays out a
// whole field from its axiom) must not make the next step reserve memory in
// proportion: the growth ratio of that step (here ~10^5) is no forecast.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "api/simulation.h"
#include "test_support.h"

namespace sylva::test {
namespace {

TEST(StringGrowth, ABurstOfGrowthDoesNotInflateTheNextStep) {
  const std::string path = make_temp_dir("string-growth") + "/model.l";
  std::ofstream(path) << "#include <lpfgall.h>\n"
                         "module A(int); module B(float);\n"
                         "derivation length: 3;\n"
                         "axiom: A(0);\n"
                         "A(i): { for (int k = 0; k < 200000; ++k) nproduce B(k); produce; }\n"
                         "B(x): { produce B(x + 1); }\n";
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(path, options);
  simulation.run();
  // Step 1 lays out B(0) .. B(199999); steps 2 and 3 add 2 to each.
  const std::string text = derive_string(path);
  EXPECT_EQ(std::count(text.begin(), text.end(), 'B'), 200000);
  EXPECT_EQ(text.substr(0, 12), "B(2) B(3) B(");
  EXPECT_EQ(text.substr(text.size() - 9), "B(200001)");
}

}  // namespace
}  // namespace sylva::test
