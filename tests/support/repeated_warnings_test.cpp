// Repeated warnings are told once and counted at the end; other messages
// (a model's Printf output) pass through every time.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "support/repeated_warnings.h"
#include "test_support.h"

namespace sylva {
namespace {

TEST(RepeatedWarnings, EachWarningOnceThenItsCount) {
  std::vector<std::string> out;
  RepeatedWarnings warnings([&](const std::string& text) { out.push_back(text); });
  for (int i = 0; i < 3; ++i) {
    warnings("warning: maximum decomposition depth (1) reached for module A\n");
    warnings("step " + std::to_string(i) + "\n");  // Printf output: every time
  }
  warnings("plant.v:3: warning: unknown command 'x:' ignored\n");
  warnings.finish();
  EXPECT_EQ(out, (std::vector<std::string>{
                     "warning: maximum decomposition depth (1) reached for module A\n", "step 0\n", "step 1\n",
                     "step 2\n", "plant.v:3: warning: unknown command 'x:' ignored\n",
                     "warning: maximum decomposition depth (1) reached for module A (3 times in all)\n"}));
}

TEST(RepeatedWarnings, PrintfTextThatMentionsWarningsIsNotAWarning) {
  EXPECT_TRUE(RepeatedWarnings::is_warning("warning: x\n"));
  EXPECT_TRUE(RepeatedWarnings::is_warning("a.l:3:4: warning: x\n"));
  EXPECT_FALSE(RepeatedWarnings::is_warning("no warning: here\n"));
  EXPECT_FALSE(RepeatedWarnings::is_warning("warnings: 3\n"));
}

TEST(RepeatedWarnings, FinishStartsTheCountingAfresh) {
  std::vector<std::string> out;
  RepeatedWarnings warnings([&](const std::string& text) { out.push_back(text); });
  warnings("warning: w\n");
  warnings.finish();  // once only: no count line
  warnings("warning: w\n");  // told again after finish
  warnings("warning: w\n");
  warnings.finish();
  EXPECT_EQ(out, (std::vector<std::string>{"warning: w\n", "warning: w\n", "warning: w (2 times in all)\n"}));
}

// A model whose decomposition reaches the depth limit in every one of its 5
// steps for every A: one warning, then its count.
TEST(RepeatedWarnings, ADepthWarningOfEveryStepIsToldOnce) {
  const std::string dir = test::make_temp_dir("repeated-warnings");
  std::ofstream(dir + "/model.l") << (
                        "module A; module B;\n"
                        "axiom: A A;\n"
                        "derivation length: 5;\n"
                        "decomposition:\n"
                        "maximum depth: 2;\n"
                        "A : { produce A B; }\n");

  const ProcessResult r = test::run_sylva({"run", "model.l", "--string", "out.txt"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string warning = "warning: maximum decomposition depth (2) reached for module A";
  std::size_t first = r.err.find(warning);
  ASSERT_NE(first, std::string::npos) << r.err;
  // Each step's decomposition reaches it once per pass: 5 steps and the axiom's.
  const std::size_t count_line = r.err.find(warning + " (6 times in all)");
  EXPECT_NE(count_line, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(warning, first + 1), count_line) << r.err;
}

}  // namespace
}  // namespace sylva
