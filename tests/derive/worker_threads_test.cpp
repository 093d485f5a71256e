// run_tasks: every task once, its result in its own slot, on threads kept
// from pass to pass; the first failure in task order; the run's limits on
// every thread; and passes that cannot have the kept threads (another pass
// holding them, a task starting a pass, a forked process) run on threads
// of their own.
#include "derive/worker_threads.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "lstring/run_limits.h"

namespace sylva::derive {
namespace {

// Squares of 0..count-1 computed on `threads` threads, and the number of
// times any task ran.
std::vector<std::size_t> squares(int threads, std::size_t count, std::atomic<int>* runs = nullptr) {
  std::vector<std::size_t> slots(count, 0);
  run_tasks(threads, count, [&](std::size_t k) {
    slots[k] = k * k;
    if (runs) runs->fetch_add(1);
  });
  return slots;
}

bool all_squares(const std::vector<std::size_t>& slots) {
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k] != k * k) return false;
  return true;
}

TEST(RunTasks, RunsEveryTaskOnceInPassAfterPass) {
  // Thread counts up and down: the kept threads grow and are left idle.
  for (int pass = 0; pass < 300; ++pass) {
    const int threads = 1 + pass % 7;
    const std::size_t count = static_cast<std::size_t>(pass % 23);
    std::atomic<int> runs{0};
    const std::vector<std::size_t> slots = squares(threads, count, &runs);
    ASSERT_TRUE(all_squares(slots)) << "pass " << pass;
    ASSERT_EQ(runs.load(), static_cast<int>(count)) << "pass " << pass;
  }
}

// Four tasks that each wait until all four have started: they can only
// finish when four threads run them at once.
int four_at_once() {
  std::atomic<int> started{0};
  run_tasks(4, 4, [&](std::size_t) {
    started.fetch_add(1);
    while (started.load() < 4) std::this_thread::yield();
  });
  return started.load();
}

TEST(RunTasks, UsesTheThreadsItIsGiven) { EXPECT_EQ(four_at_once(), 4); }

TEST(RunTasks, RethrowsTheFailureOfTheFirstTaskInOrder) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    try {
      run_tasks(4, 40, [](std::size_t k) {
        if (k == 7 || k == 31) throw std::runtime_error("task " + std::to_string(k));
      });
      FAIL() << "no failure";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "task 7");
    }
  }
  EXPECT_TRUE(all_squares(squares(4, 50)));  // the threads are still there
}

TEST(RunTasks, EveryThreadChecksTheCallersLimits) {
  RunBudget budget;
  RunBudget::Scope scope(budget);
  std::vector<RunBudget*> seen(64, nullptr);
  run_tasks(4, seen.size(), [&](std::size_t k) {
    seen[k] = RunBudget::active();
    std::this_thread::yield();
  });
  for (RunBudget* active : seen) EXPECT_EQ(active, &budget);
}

TEST(RunTasks, PassesOnSeveralThreadsAtOnceAndWithinATask) {
  // Two callers at once, and a task that starts a pass of its own: one
  // pass has the kept threads, the others start threads of their own.
  std::vector<std::vector<std::size_t>> results(3);
  std::thread other([&] { results[0] = squares(3, 500); });
  run_tasks(3, 6, [&](std::size_t k) {
    if (k == 2) results[1] = squares(3, 200);
  });
  results[2] = squares(3, 300);
  other.join();
  for (const auto& slots : results) EXPECT_TRUE(all_squares(slots));
  EXPECT_EQ(results[1].size(), 200u);
}

TEST(RunTasks, RunsInAForkedProcess) {
  ASSERT_EQ(four_at_once(), 4);  // the kept threads exist here, not in a child
  const pid_t child = fork();
  ASSERT_NE(child, -1);
  if (child == 0) {
    alarm(20);  // tasks waiting for threads that did not survive the fork
    _exit(all_squares(squares(4, 100)) && four_at_once() == 4 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child was stopped by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace sylva::derive
