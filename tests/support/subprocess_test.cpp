// Running a program: its exit status, its stdout and stderr kept apart and
// whole, stdin empty, and failures to start or a death by signal reported.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "support/subprocess.h"

namespace sylva {
namespace {

TEST(RunProcess, ExitStatusAndBothStreams) {
  const ProcessResult r = run_process({"sh", "-c", "printf out; printf err >&2; exit 3"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.out, "out");
  EXPECT_EQ(r.err, "err");
}

TEST(RunProcess, ArgumentsArePassedAsTheyAre) {
  const ProcessResult r = run_process({"printf", "%s|%s", "a b", "$HOME"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "a b|$HOME");  // no shell in between
}

TEST(RunProcess, LargeOutputOnBothStreamsIsReadWhole) {
  // More than a pipe holds on each stream, written interleaved: reading one
  // stream to its end first would deadlock.
  const ProcessResult r =
      run_process({"sh", "-c", "i=0; while [ $i -lt 2000 ]; do echo 0123456789012345678901234567890123456789; "
                               "echo abcdefghijabcdefghijabcdefghijabcdefghij >&2; i=$((i+1)); done"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.size(), 2000u * 41);
  EXPECT_EQ(r.err.size(), 2000u * 41);
}

TEST(RunProcess, StandardInputIsEmpty) {
  const ProcessResult r = run_process({"cat"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "");
}

TEST(RunProcess, AProgramThatCannotStart) {
  const ProcessResult r = run_process({"/nonexistent/sylva-no-such-program"});
  EXPECT_EQ(r.exit_code, -1);
  EXPECT_NE(r.err.find("cannot run /nonexistent/sylva-no-such-program"), std::string::npos) << r.err;
}

TEST(RunProcess, KilledBySignal) {
  const ProcessResult r = run_process({"sh", "-c", "kill -TERM $$"});
  EXPECT_EQ(r.exit_code, -1);
}

TEST(RunProcess, ATimeoutKillsTheWholeProcessGroup) {
  // The shell's background child writes a file once a second; after the
  // timeout nothing of the group may be left to write it.
  const std::string marker = testing::TempDir() + "/still_running_" + std::to_string(getpid());
  std::remove(marker.c_str());
  const auto start = std::chrono::steady_clock::now();
  ProcessResult r = run_process({"sh", "-c", "(sleep 1; touch " + marker + ") & sleep 30"}, 0.3);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(r.timed_out);
  EXPECT_EQ(r.exit_code, -1);
  EXPECT_LT(seconds, 5.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  EXPECT_FALSE(std::filesystem::exists(marker));
}

TEST(RunProcess, AProgramWithinItsTimeIsNotStopped) {
  ProcessResult r = run_process({"sh", "-c", "echo done"}, 10);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "done\n");
}

TEST(RunProcess, TheChildRunsInAGroupOfItsOwn) {
  ProcessResult r = run_process({"sh", "-c", "set -- $(cat /proc/$$/stat); echo $5"});
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(std::stoi(r.out), static_cast<int>(getpgrp()));
}

}  // namespace
}  // namespace sylva
