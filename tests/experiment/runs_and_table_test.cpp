// The run list of a plan and the table written from results.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "experiment/runs.h"
#include "experiment/sample_stream.h"
#include "experiment/table.h"

namespace sylva::experiment {
namespace {

Plan two_by_three(int replicates) {
  Plan plan;
  plan.parameters = {{"A", {"1", "2"}, {}}, {"B", {"x", "y", "z"}, {}}};
  plan.replicates = replicates;
  plan.seed = 10;
  plan.measures = {{"n", "count(A)", {}}, {"h", "height", {}}};
  return plan;
}

TEST(PlanRuns, TheGridVariesTheFirstParameterSlowestAndRepeatsSeedsAcrossPoints) {
  const std::vector<RunSpec> runs = plan_runs(two_by_three(2));
  ASSERT_EQ(runs.size(), 12u);
  EXPECT_EQ(runs[0].defines(), (std::vector<std::string>{"A=1", "B=x"}));
  EXPECT_EQ(runs[2].defines(), (std::vector<std::string>{"A=1", "B=y"}));
  EXPECT_EQ(runs[6].defines(), (std::vector<std::string>{"A=2", "B=x"}));
  EXPECT_EQ(runs[11].defines(), (std::vector<std::string>{"A=2", "B=z"}));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i].number, static_cast<long>(i));
    EXPECT_EQ(runs[i].point, static_cast<long>(i / 2));
    EXPECT_EQ(runs[i].replicate, static_cast<int>(i % 2));
    EXPECT_EQ(runs[i].seed, replicate_seed(10, static_cast<int>(i % 2)));
  }
  EXPECT_EQ(one_run_per_define_set(runs).size(), 6u);
  EXPECT_NE(replicate_seed(10, 0), replicate_seed(10, 1));
  EXPECT_NE(replicate_seed(10, 0), replicate_seed(11, 0));
}

// Replicate seeds are spread over 1 .. 2^31 - 1, so lpfg's generator starts
// from unrelated states: the first draws of 1000 replicates have the mean and
// spread of uniform numbers (consecutive seeds 1 .. 1000 would all draw < 0.1).
TEST(PlanRuns, ReplicateSeedsGiveIndependentFirstDraws) {
  double sum = 0;
  for (int r = 0; r < 1000; ++r) {
    const long seed = replicate_seed(1, r);
    ASSERT_GE(seed, 1);
    ASSERT_LE(seed, 2147483647L);
    // erand48's first number from lpfg's state {seed, seed >> 16, 0}.
    const std::uint64_t x = (0x5DEECE66DULL * (static_cast<std::uint64_t>(seed) & 0xFFFFFFFFULL) + 0xB) & 0xFFFFFFFFFFFFULL;
    sum += static_cast<double>(x) / 281474976710656.0;
  }
  EXPECT_NEAR(sum / 1000, 0.5, 0.05);  // sd of the mean: 0.009
}

TEST(PlanRuns, ZipTakesTheIthValuesTogetherAndNoReplicatesMeansNoSeed) {
  Plan plan = two_by_three(0);
  plan.parameters[1].values.pop_back();
  plan.zip = true;
  const std::vector<RunSpec> runs = plan_runs(plan);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].defines(), (std::vector<std::string>{"A=2", "B=y"}));
  EXPECT_FALSE(runs[0].seed.has_value());
}

TEST(ResultTable, NumbersReadBackExactlyAndMissingValuesAreNA) {
  EXPECT_EQ(number_cell(0.1), "0.1");
  EXPECT_EQ(number_cell(3), "3");
  EXPECT_EQ(number_cell(1.0 / 3), "0.3333333333333333");
  EXPECT_EQ(std::stod(number_cell(1.0 / 3)), 1.0 / 3);
  EXPECT_EQ(number_cell(std::nan("")), "NA");
  EXPECT_EQ(number_cell(-HUGE_VAL), "-Inf");
}

TEST(ResultTable, OneRowPerRunAndStepWithTheFailuresSaid) {
  Plan plan;
  plan.parameters = {{"A", {"1"}, {}}};
  plan.replicates = 2;
  plan.steps = {2, 4};
  plan.measures = {{"n", "count(A)", {}}};
  const std::vector<RunSpec> runs = plan_runs(plan);
  std::vector<RunResult> results(2);
  results[0].number = 0;
  results[0].ok = true;
  results[0].rows = {{2, 0, {5}, ""}, {4, 0, {std::nan("")}, "the run ended at step 3"}};
  results[1].number = 1;
  results[1].error = "model.l:3:1: error: bad, \"very\"";
  const std::string s0 = std::to_string(replicate_seed(1, 0)), s1 = std::to_string(replicate_seed(1, 1));
  const std::string expected =
      "run,point,replicate,seed,A,step,n,status,error\n"
      "0,0,0," + s0 + ",1,2,5,ok,\n"
      "0,0,0," + s0 + ",1,4,NA,ended,the run ended at step 3\n"
      "1,0,1," + s1 + ",1,2,NA,error,\"model.l:3:1: error: bad, \"\"very\"\"\"\n"
      "1,0,1," + s1 + ",1,4,NA,error,\"model.l:3:1: error: bad, \"\"very\"\"\"\n";
  EXPECT_EQ(table_text(plan, runs, results), expected);
}

TEST(ResultTable, ResultsTravelAsTextUnchanged) {
  RunResult r;
  r.number = 7;
  r.ok = true;
  r.rows = {{3, 1.5, {0.1, 1.0 / 3, std::nan(""), HUGE_VAL, -HUGE_VAL}, ""}};
  const RunResult back = decode_result(encode_result(r));
  EXPECT_EQ(back.number, 7);
  ASSERT_EQ(back.rows.size(), 1u);
  EXPECT_EQ(back.rows[0].values[0], 0.1);
  EXPECT_EQ(back.rows[0].values[1], 1.0 / 3);
  EXPECT_TRUE(std::isnan(back.rows[0].values[2]));
  EXPECT_EQ(back.rows[0].values[3], HUGE_VAL);
  EXPECT_EQ(back.rows[0].values[4], -HUGE_VAL);
  EXPECT_EQ(back.rows[0].time, 1.5);
}

}  // namespace
}  // namespace sylva::experiment
