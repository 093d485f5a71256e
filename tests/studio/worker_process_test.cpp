// The worker process's limits and failures, with stand-in workers (small
// shell programs) whose behaviour is known exactly, and the real one.
#include "studio/worker_process.h"

#include <gtest/gtest.h>

#include <chrono>

#include "test_support.h"

namespace sylva::studio {
namespace {

using nlohmann::json;

std::vector<std::string> shell(const std::string& script) { return {"/bin/sh", "-c", script}; }

TEST(WorkerProcess, AnswersComeBackWithTheirPayload) {
  // A worker that answers one fixed message with a 3-byte payload.
  WorkerProcess worker(shell(R"(read line <&3; printf '{"ok":true,"payload":3}\nabc' >&4; sleep 5)"), "", {});
  const WorkerMessage answer = worker.request({{"op", "status"}}, 5);
  EXPECT_TRUE(answer.json.value("ok", false));
  EXPECT_EQ(answer.payload, "abc");
  EXPECT_FALSE(answer.json.contains("payload"));
}

TEST(WorkerProcess, ACrashIsReportedWithItsSignal) {
  WorkerProcess worker(shell("read line <&3; kill -SEGV $$"), "", {});
  try {
    worker.request({{"op", "step"}}, 5);
    FAIL() << "expected a failure";
  } catch (const WorkerFailure& e) {
    EXPECT_EQ(e.kind(), "crash");
    EXPECT_NE(std::string(e.what()).find("signal 11"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(worker.running());
}

TEST(WorkerProcess, AWorkerTooSlowIsStoppedWithWhatItStarted) {
  // The worker starts a child of its own, which must go too.
  const std::string marker = test::make_temp_dir("worker-timeout") + "/alive";
  WorkerProcess worker(shell("(sleep 3; touch " + marker + ") & read line <&3; sleep 30"), "", {});
  const auto start = std::chrono::steady_clock::now();
  try {
    worker.request({{"op", "step"}}, 0.5);
    FAIL() << "expected a timeout";
  } catch (const WorkerFailure& e) {
    EXPECT_EQ(e.kind(), "timeout");
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(3));
  std::this_thread::sleep_for(std::chrono::milliseconds(3500));
  EXPECT_FALSE(std::filesystem::exists(marker)) << "the worker's child outlived it";
}

TEST(WorkerProcess, PrintedOutputIsKeptApartFromAnswers) {
  WorkerProcess worker(shell(R"(read line <&3; echo printed; echo also >&2; printf '{"ok":true}\n' >&4; sleep 5)"),
                       "", {});
  EXPECT_TRUE(worker.request({{"op", "step"}}, 5).json.value("ok", false));
  std::string console;
  for (int i = 0; i < 50 && console.find("also") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    console += worker.take_console();
  }
  EXPECT_EQ(console, "printed\nalso\n");
}

TEST(WorkerProcess, TheNextRequestStartsAFreshWorker) {
  // Each worker answers once and exits: the second request needs a new one.
  WorkerProcess worker(shell(R"(read line <&3; printf '{"ok":true,"pid":%d}\n' $$ >&4)"), "", {});
  const int first = worker.request({{"op", "a"}}, 5).json["pid"];
  EXPECT_THROW(worker.request({{"op", "b"}}, 5), WorkerFailure);  // it exited after answering
  const int second = worker.request({{"op", "c"}}, 5).json["pid"];
  EXPECT_NE(first, second);
}

TEST(WorkerProcess, MemoryIsLimited) {
  // 200 MiB of address space cannot hold a 256 MiB string.
  const std::string dir = test::make_temp_dir("worker-memory");
  WorkerLimits limits;
  limits.memory_bytes = std::size_t{200} << 20;
  WorkerProcess worker(shell("read line <&3; perl -e '$x = q(a) x 268435456; print 1' >/dev/null 2>&1 && "
                             "printf '{\"ok\":true,\"fit\":true}\\n' >&4 || printf '{\"ok\":true,\"fit\":false}\\n' >&4"),
                       dir, limits);
  EXPECT_FALSE(worker.request({{"op", "x"}}, 20).json.value("fit", true));
}

}  // namespace
}  // namespace sylva::studio
