// The plan reader from strings: values as -D gets them, errors at the plan's
// line and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "experiment/plan.h"
#include "experiment/sample_stream.h"
#include "test_support.h"

namespace sylva::experiment {
namespace {

// A plan beside a model file, so `model = "m.l"` resolves.
std::string plan_dir() {
  static const std::string dir = [] {
    const std::string d = test::make_temp_dir("plan-reader");
    std::ofstream(d + "/m.l") << "#define ANGLE 30\n";
    return d;
  }();
  return dir;
}

Plan parse(const std::string& body) {
  return parse_plan("model = \"m.l\"\n" + body, plan_dir() + "/plan.toml");
}

std::string error_of(const std::string& body) {
  try {
    parse(body);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kMeasure = "[measures]\nn = \"count(A)\"\n";

TEST(PlanReader, ListsAndRangesGiveTheValuesDefinesGet) {
  const Plan plan = parse("[parameters]\nA = [10, 2.5, \"x\"]\nB = { from = 0.1, to = 0.5, step = 0.1 }\n"
                          "C = { from = 0, to = 1, count = 3 }\nD = 7\n" + kMeasure);
  ASSERT_EQ(plan.parameters.size(), 4u);
  EXPECT_EQ(plan.parameters[0].name, "A");
  EXPECT_EQ(plan.parameters[0].values, (std::vector<std::string>{"10", "2.5", "x"}));
  // 0.1 + k * 0.1 written as a person would: 0.3, not 0.30000000000000004.
  EXPECT_EQ(plan.parameters[1].values, (std::vector<std::string>{"0.1", "0.2", "0.3", "0.4", "0.5"}));
  EXPECT_EQ(plan.parameters[2].values, (std::vector<std::string>{"0", "0.5", "1"}));
  EXPECT_EQ(plan.parameters[3].values, (std::vector<std::string>{"7"}));
  EXPECT_EQ(plan.model, std::filesystem::weakly_canonical(plan_dir() + "/m.l").string());
  EXPECT_EQ(plan.output, std::filesystem::weakly_canonical(plan_dir() + "/plan.csv").string());
}

TEST(PlanReader, MeasuresKeepTheOrderTheyAreWrittenIn) {
  const Plan plan = parse("[measures]\nzeta = \"count(A)\"\nalpha = \"height\"\nmid = \"zeta + 1\"\n");
  ASSERT_EQ(plan.measures.size(), 3u);
  EXPECT_EQ(plan.measures[0].name, "zeta");
  EXPECT_EQ(plan.measures[1].name, "alpha");
  EXPECT_EQ(plan.measures[2].name, "mid");
  // The column of the expression's first character, past the quote.
  EXPECT_EQ(plan.measures[1].at.line, 4);
  EXPECT_EQ(plan.measures[1].at.column, 10);
}

TEST(PlanReader, UniformSamplesDependOnTheSeedAndTheNameOnly) {
  const Plan a = parse("seed = 7\n[parameters]\nP = { uniform = [2, 3], samples = 50 }\n" + kMeasure);
  const Plan b = parse("seed = 7\n[parameters]\nQ = [1]\nP = { uniform = [2, 3], samples = 50 }\n" + kMeasure);
  const Plan c = parse("seed = 8\n[parameters]\nP = { uniform = [2, 3], samples = 50 }\n" + kMeasure);
  ASSERT_EQ(a.parameters[0].values.size(), 50u);
  EXPECT_EQ(a.parameters[0].values, b.parameters[1].values);
  EXPECT_NE(a.parameters[0].values, c.parameters[0].values);
  double sum = 0;
  for (const std::string& v : a.parameters[0].values) {
    const double x = std::stod(v);
    EXPECT_GE(x, 2);
    EXPECT_LT(x, 3);
    sum += x;
  }
  EXPECT_NEAR(sum / 50, 2.5, 0.15);  // the mean of 50 uniform draws: sd 0.041
  // The stream itself, a second way: SplitMix64 of the seed mixed with the name.
  SampleStream stream(7, "P");
  EXPECT_EQ(a.parameters[0].values[0], [&] {
    char t[32];
    std::snprintf(t, sizeof t, "%.12g", 2 + stream.next());
    return std::string(t);
  }());
}

TEST(PlanReader, StepsAndTimesAreSortedAndUnique) {
  const Plan plan = parse("steps = [8, 2, 4, 2]\n" + kMeasure);
  EXPECT_EQ(plan.steps, (std::vector<int>{2, 4, 8}));
  EXPECT_NE(error_of("steps = [1]\ntimes = [1.0]\n" + kMeasure).find("plan.toml:3:"), std::string::npos);
}

TEST(PlanReader, ErrorsPointAtThePlansLineAndColumn) {
  // A range with no values.
  EXPECT_NE(error_of("[parameters]\nA = { from = 5, to = 1, step = 1 }\n" + kMeasure).find("plan.toml:3:5: error: the range of 'A' has no values"),
            std::string::npos)
      << error_of("[parameters]\nA = { from = 5, to = 1, step = 1 }\n" + kMeasure);
  EXPECT_NE(error_of("[parameters]\nA = []\n" + kMeasure).find("plan.toml:3:5: error: 'A' has no values"), std::string::npos);
  // An unknown key, at the key.
  EXPECT_NE(error_of("replicate = 3\n" + kMeasure).find("plan.toml:2:1: error: unknown key 'replicate'"), std::string::npos);
  // TOML syntax.
  EXPECT_NE(error_of("steps = [1,\n").find("plan.toml:"), std::string::npos);
  // Zip needs equal lengths.
  EXPECT_NE(error_of("design = \"zip\"\n[parameters]\nA = [1, 2]\nB = [1]\n" + kMeasure).find("plan.toml:5:5: error: with design"),
            std::string::npos);
  // A measure named like a column.
  EXPECT_NE(error_of("[measures]\nstep = \"count(A)\"\n").find("plan.toml:3:8: error: the measure 'step'"), std::string::npos);
  // No model file.
  EXPECT_NE([&] {
    try {
      parse_plan("model = \"missing.l\"\n" + kMeasure, plan_dir() + "/plan.toml");
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  }().find("plan.toml:1:9: error: no model file"), std::string::npos);
  // Too many values or runs: a clear error rather than memory exhausted.
  EXPECT_NE(error_of("[parameters]\nA = { from = 0, to = 1, count = 2000000 }\n" + kMeasure).find("plan.toml:3:33: error: at most 10^6 values"),
            std::string::npos);
  EXPECT_NE(error_of("replicates = 100000\n[parameters]\nA = { from = 1, to = 1000, step = 1 }\n" + kMeasure)
                .find("plan.toml:4:5: error: the plan makes 100000000 runs (at most 10^7)"),
            std::string::npos);
  // Nothing measured.
  EXPECT_NE(error_of("").find("measures nothing"), std::string::npos);
  // A plot of a parameter the plan lacks.
  EXPECT_NE(error_of(kMeasure + "[plot]\nx = \"B\"\ny = \"n\"\nfile = \"p.png\"\n").find("plan.toml:5:5: error: [plot] x 'B'"),
            std::string::npos);
}

}  // namespace
}  // namespace sylva::experiment
