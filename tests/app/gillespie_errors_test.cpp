// Gillespie groups written wrongly: the sylva program says where (file, line,
// column for what the translator sees) and what is wrong, and exits with a
// non-zero status without crashing. A propensity that turns out negative
// while the model runs is a warning naming the production, as in lpfg.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "test_support.h"

namespace sylva::test {
namespace {

std::string test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

// Writes `text` to DIR/model.l and runs `sylva run model.l` in a fresh DIR.
ProcessResult run_model(const std::string& text) {
  const std::string dir = make_temp_dir("gillespie-" + test_name());
  std::ofstream(dir + "/model.l") << text;
  return run_sylva({"run", "model.l"}, dir);
}

// A reported failure: a plain non-zero exit status and a line of stderr that
// begins with `prefix` and contains `what`.
::testing::AssertionResult FailsWith(const ProcessResult& r, const std::string& prefix, const std::string& what) {
  const std::string shown = "exit status " + std::to_string(r.exit_code) + "\nstderr:\n" + r.err;
  if (r.exit_code <= 0 || r.exit_code >= 128) return ::testing::AssertionFailure() << "expected a failure: " << shown;
  if (r.err.find("terminate called") != std::string::npos) return ::testing::AssertionFailure() << shown;
  std::istringstream lines(r.err);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(prefix, 0) == 0 && line.find(what) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no line begins with \"" << prefix << "\" and says \"" << what << "\"\n"
                                       << shown;
}

const std::string kHead = "#include <lpfgall.h>\nmodule A(int);\naxiom: A(0);\n";  // lines 1-3

TEST(GillespieErrors, PropensityOutsideAGillespieGroup) {
  ProcessResult r = run_model(kHead + "A(n) : {\n  propensity 1 produce A(n + 1);\n}\n");
  EXPECT_TRUE(FailsWith(r, "model.l:5:3: error: ", "'propensity' is only allowed in the productions of a Gillespie group"));
}

TEST(GillespieErrors, PropensityInAControlStatement) {
  ProcessResult r = run_model(kHead + "Start: { propensity 1 produce A(1); }\n");
  EXPECT_TRUE(FailsWith(r, "model.l:4:10: error: ", "'propensity' is only allowed"));
}

TEST(GillespieErrors, ProduceWithoutPropensityInAGillespieGroup) {
  ProcessResult r = run_model(kHead + "ggroup 1:\nA(n) : { produce A(n + 1); }\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:5:10: error: ", "write 'propensity <expression> produce ...;'"));
}

TEST(GillespieErrors, PropensityWithoutProduce) {
  ProcessResult r = run_model(kHead + "ggroup 1:\nA(n) : { propensity n + 1; }\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:5:26: error: ", "expected 'produce' after the propensity, found ';'"));
}

TEST(GillespieErrors, PropensityWithoutExpression) {
  ProcessResult r = run_model(kHead + "ggroup 1:\nA(n) : { propensity produce A(n); }\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:5:21: error: ", "expected an expression after 'propensity'"));
}

TEST(GillespieErrors, GroupAndGillespieGroupShareANumber) {
  ProcessResult r = run_model(kHead + "group 2:\nA(n) : { produce A(n); }\nendgroup\nggroup 2:\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:7:8: error: ", "group 2 is already a regular group"));
  r = run_model(kHead + "ggroup 2:\nendgroup\ngroup 2:\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:6:7: error: ", "group 2 is already a Gillespie group"));
}

TEST(GillespieErrors, GroupZeroCannotBeAGillespieGroup) {
  ProcessResult r = run_model(kHead + "ggroup 0:\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:4:8: error: ", "group 0 is the main group"));
}

TEST(GillespieErrors, GillespieGroupWithoutANumber) {
  ProcessResult r = run_model(kHead + "ggroup REACTIONS:\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:4:8: error: ", "expected a group number after 'ggroup', found 'REACTIONS'"));
}

TEST(GillespieErrors, NewContextInAGillespieGroup) {
  ProcessResult r = run_model(kHead + "ggroup 1:\nA(m) << A(n) : { propensity 1 produce A(n); }\nendgroup\n");
  EXPECT_TRUE(FailsWith(r, "model.l:5:6: error: ", "new context '<<' cannot be used in a Gillespie group"));
}

// lpfg takes a negative propensity as 0, with a message; so does Sylva,
// with a warning naming the production, once.
TEST(GillespieErrors, NegativePropensityIsTakenAsZero) {
  // The propensity is 1 - n: fine for A(0), negative once A(2) is there.
  ProcessResult r = run_model(kHead +
                              "derivation length: 5;\n"
                              "Start: { UseGroup(1); }\n"
                              "ggroup 1:\n"
                              "A(n) : {\n"  // line 7
                              "  propensity 1 produce A(n + 2);\n"
                              "  propensity 1 - n produce A(n);\n"
                              "}\n"
                              "endgroup\n");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string warning = "model.l:7: warning: a propensity must be a finite number, 0 or more";
  const std::size_t at = r.err.find(warning);
  ASSERT_NE(at, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(warning, at + 1), std::string::npos) << "told once: " << r.err;
  EXPECT_NE(r.err.find("taken as 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("Gillespie group 1"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sylva::test
