// Runs in forked processes: results by number whatever order they end in,
// a crash or a hang costing only its own run, and the scheduler feeding
// every kind of worker.
#include <gtest/gtest.h>

#include <csignal>
#include <thread>
#include <unistd.h>

#include "experiment/local_processes.h"
#include "experiment/progress.h"

namespace sylva::experiment {
namespace {

std::vector<RunSpec> numbered(int n) {
  std::vector<RunSpec> runs(n);
  for (int i = 0; i < n; ++i) runs[i].number = i;
  return runs;
}

// A result whose one value is the number squared, computed in the child.
std::string square(const RunSpec& run) {
  RunResult r;
  r.number = run.number;
  r.ok = true;
  r.rows = {{0, 0, {double(run.number * run.number)}, ""}};
  // Later runs end first, so results come back out of order.
  std::this_thread::sleep_for(std::chrono::milliseconds(5 * (6 - run.number % 6)));
  return encode_result(r);
}

TEST(LocalProcesses, ResultsComeBackByRunNumber) {
  LocalProcesses workers(3, square);
  const std::vector<RunResult> results = schedule(numbered(12), {&workers});
  ASSERT_EQ(results.size(), 12u);
  for (int i = 0; i < 12; ++i) {
    EXPECT_TRUE(results[i].ok);
    EXPECT_EQ(results[i].number, i);
    EXPECT_EQ(results[i].rows.at(0).values.at(0), i * i);
  }
}

TEST(LocalProcesses, EachRunHasAFreshProcess) {
  // A global changed by one run is not seen by the next.
  static int counter = 0;
  LocalProcesses workers(1, [](const RunSpec& run) {
    RunResult r;
    r.number = run.number;
    r.ok = true;
    r.rows = {{0, 0, {double(++counter)}, ""}};
    return encode_result(r);
  });
  for (const RunResult& r : schedule(numbered(4), {&workers})) EXPECT_EQ(r.rows.at(0).values.at(0), 1);
}

TEST(LocalProcesses, ACrashOrAHangCostsOnlyItsOwnRun) {
  LocalProcesses workers(2, [](const RunSpec& run) {
    if (run.number == 1) std::raise(SIGSEGV);
    if (run.number == 2) std::this_thread::sleep_for(std::chrono::seconds(30));
    if (run.number == 3) throw std::runtime_error("no such module");
    return square(run);
  }, 0.5);
  const std::vector<RunResult> results = schedule(numbered(5), {&workers});
  EXPECT_TRUE(results[0].ok);
  EXPECT_FALSE(results[1].ok);
  EXPECT_NE(results[1].error.find("signal 11"), std::string::npos) << results[1].error;
  EXPECT_FALSE(results[2].ok);
  EXPECT_NE(results[2].error.find("longer than 0.5 s"), std::string::npos) << results[2].error;
  EXPECT_FALSE(results[3].ok);
  EXPECT_EQ(results[3].error, "no such module");
  EXPECT_TRUE(results[4].ok);
  EXPECT_EQ(results[4].rows.at(0).values.at(0), 16);
}

// A worker of another kind (as MPI ranks are): takes one run at a time and
// finishes it at the next collect.
class FakeWorkers : public Workers {
 public:
  int capacity() const override { return 1; }
  int busy() const override { return pending_ ? 1 : 0; }
  void start(const RunSpec& run) override {
    pending_ = true;
    number_ = run.number;
    ++taken;
  }
  std::vector<RunResult> collect(int) override {
    if (!pending_) return {};
    pending_ = false;
    RunSpec run;
    run.number = number_;
    return {decode_result(square(run))};
  }
  int taken = 0;

 private:
  bool pending_ = false;
  long number_ = 0;
};

TEST(Schedule, EveryKindOfWorkerTakesRunsAndNoRunIsLost) {
  LocalProcesses local(1, square);
  FakeWorkers other;
  const std::vector<RunResult> results = schedule(numbered(20), {&local, &other});
  for (int i = 0; i < 20; ++i) EXPECT_EQ(results[i].rows.at(0).values.at(0), i * i);
  EXPECT_GT(other.taken, 0);
  EXPECT_LT(other.taken, 20);
}

TEST(Progress, TheLineSaysDoneRateAndETA) {
  EXPECT_EQ(Progress::line(40, 100, 0, 10), "[#########---------------] 40/100 runs  4.0 runs/s  ETA 0:15");
  EXPECT_EQ(Progress::line(100, 100, 2, 20), "[########################] 100/100 runs  5.0 runs/s  2 failed");
}

}  // namespace
}  // namespace sylva::experiment
