// Models with more module types than one-byte ids hold: the predefined
// modules and the 200 declared first fill the ids up to 254, so W and Q get
// wide, three-byte ids. Context, new context, branches and parameters work
// across them as with one-byte ids. The expected strings were worked by hand; lpfg derives
// the same module names.
#include <gtest/gtest.h>

#include <string>

#include "api/simulation.h"
#include "test_support.h"

namespace sylva::test {
namespace {

std::string model_with_wide_ids(const std::string& rules) {
  std::string text = "#include <lpfgall.h>\n";
  for (int k = 0; k < 200; ++k) text += "module F" + std::to_string(k) + "();\n";
  return text + "module W(int);\nmodule Q();\nderivation length: 2;\n" + rules;
}

std::string derived(const std::string& name, const std::string& rules) {
  return derive_string(write_temp_file("wide-ids", name, model_with_wide_ids(rules)));
}

TEST(WideModuleIds, TheLastDeclaredModulesHaveThem) {
  const std::string path = write_temp_file("wide-ids", "ids.l", model_with_wide_ids("axiom: W(1) Q;\n"));
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(path, options);
  EXPECT_GE(*simulation.types().find("W"), 255);
  EXPECT_GE(*simulation.types().find("Q"), 255);
  EXPECT_LT(*simulation.types().find("F0"), 255);
}

// Step 1: W(1) sees Q on its right; W(2) sees Q on its left.
//   W(11) [ W(1) ] F199 Q F0 W(4) Q
// Step 2: W(11)'s right context is F199 (the branch skipped), W(1)'s the
// branch's end; W(4) sees Q on its right, and the first rule wins.
//   W(11) [ W(1) ] F199 Q F0 W(14) [ W(4) ] F199 Q
TEST(WideModuleIds, ContextAndBranchesWalkOverThem) {
  EXPECT_EQ(derived("context.l", "axiom: W(1) Q W(2);\n"
                                 "W(x) > Q : { produce W(x + 10) SB() W(x) EB() F199; }\n"
                                 "Q < W(x) : { produce F0 W(x * 2) Q; }\n"),
            "W(11) SB W(1) EB F199 Q F0 W(14) SB W(4) EB F199 Q");
}

// Backward steps read the successors already built on the right:
//   Q W(1) W(2) Q -> Q W(3) W(2) Q -> Q W(5) W(2) Q
TEST(WideModuleIds, NewContextReadsThemBackward) {
  EXPECT_EQ(derived("backward.l", "Start: { Backward(); }\n"
                                  "axiom: Q W(1) W(2) Q;\n"
                                  "W(x) >> W(y) : { produce W(x + y); }\n"),
            "Q W(5) W(2) Q");
}

}  // namespace
}  // namespace sylva::test
