// Compiles shared by concurrent runs, stopped past their time limit or by an
// interruption without leaving anything behind; `sylva cache`.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "build/cache_test_support.h"
#include "support/diagnostic.h"
#include "support/subprocess.h"

extern char** environ;

namespace sylva::test {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Writes its partial output, then hangs with a child of its own (as g++ has
// cc1plus), saying the pids of both beside itself.
const std::string kHungCompiler = stand_in_script(
    ": > \"$out\"\n"
    "sleep 60 &\n"
    "echo $! > \"$(dirname \"$0\")/child\"\n"
    "echo $$ > \"$(dirname \"$0\")/started\"\n"
    "wait");

// Waits up to `seconds` for `path` to hold a pid.
pid_t pid_in(const std::string& path, int seconds = 60) {
  const Clock::time_point end = Clock::now() + std::chrono::seconds(seconds);
  do {
    std::ifstream in(path);
    pid_t pid = 0;
    if (in >> pid && pid > 0) return pid;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  } while (Clock::now() < end);
  return 0;
}

// Not running (gone, or a zombie no one has reaped yet), within a few seconds.
bool stopped(pid_t pid) {
  for (const Clock::time_point end = Clock::now() + std::chrono::seconds(5); Clock::now() < end;) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    if (!std::getline(stat, text)) return true;
    const std::size_t state = text.rfind(')') + 2;
    if (state < text.size() && (text[state] == 'Z' || text[state] == 'X')) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

class CompileRuns : public CacheTest {};

TEST_F(CompileRuns, ConcurrentRunsOfOneModelShareOneCompile) {
  options_.compiler = stand_in("slow", stand_in_script("sleep 1; : > \"$out\""));
  build::BuiltModel first, second;
  std::thread other([&] { first = build(); });
  second = build();
  other.join();
  EXPECT_EQ(compiles(options_.compiler).size(), 1u);
  EXPECT_EQ(first.library_path, second.library_path);
  EXPECT_NE(first.compiled_now, second.compiled_now);
  EXPECT_EQ(files_containing(".tmp"), 0);

  // Two sylva processes compiling another model (lpfg's -c: compile only).
  edit("model.l", "module A(float);\naxiom: A(3);\n");
  std::vector<ProcessResult> results(2);
  std::vector<std::thread> runs;
  for (ProcessResult& result : results)
    runs.emplace_back([&] {
      result = run_sylva({"run", "-c", dir_ + "/model.l", "--compiler", options_.compiler, "--cache-dir",
                          options_.cache_dir});
    });
  for (std::thread& run : runs) run.join();
  for (const ProcessResult& result : results) EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(compiles(options_.compiler).size(), 2u);
}

TEST_F(CompileRuns, ACompilePastItsTimeLimitIsStoppedWhole) {
  options_.compiler = stand_in("hung", kHungCompiler);
  options_.compile_timeout_seconds = 1;
  const Clock::time_point start = Clock::now();
  try {
    build();
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()).find(dir_ + "/model.l: error: compiling the model took longer than the limit "
                                                "of 1 seconds"),
              0u)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("--compile-timeout"), std::string::npos) << e.what();
  }
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(30));
  EXPECT_TRUE(stopped(pid_in(dir_ + "/hung/started", 0)));
  EXPECT_TRUE(stopped(pid_in(dir_ + "/hung/child", 0)));
  EXPECT_EQ(files_containing(".tmp"), 0);
  EXPECT_EQ(files_ending(".so"), 0);
}

TEST_F(CompileRuns, AnInterruptedRunEndsByTheSignalAndLeavesNothingRunningOrBehind) {
  const std::string compiler = stand_in("hung", kHungCompiler);
  const std::vector<std::string> argv = {"/usr/bin/env", "-C",          dir_,        SYLVA_BINARY,     "run",
                                         "model.l",      "--compiler",  compiler,    "--cache-dir",    options_.cache_dir,
                                         "-s",           "out.str"};
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // Ctrl-C reaches Sylva only: the compiler runs in a process group of its own.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  posix_spawnattr_setsigdefault(&attributes, &interrupt);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t sylva = 0;
  ASSERT_EQ(posix_spawn(&sylva, args[0], nullptr, &attributes, args.data(), environ), 0);
  posix_spawnattr_destroy(&attributes);

  const pid_t compiler_pid = pid_in(dir_ + "/hung/started");
  ASSERT_GT(compiler_pid, 0);
  const pid_t child = pid_in(dir_ + "/hung/child");
  EXPECT_EQ(files_containing(".tmp"), 2);  // the C++ and the partial library
  kill(sylva, SIGINT);
  int status = 0;
  ASSERT_EQ(waitpid(sylva, &status, 0), sylva);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  EXPECT_TRUE(stopped(compiler_pid));
  EXPECT_TRUE(stopped(child));
  EXPECT_EQ(files_containing(".tmp"), 0);
  EXPECT_EQ(files_containing(".tmp", dir_), 0);
  EXPECT_FALSE(fs::exists(dir_ + "/out.str"));
}

TEST_F(CompileRuns, TheCacheCommandShowsPrunesAndClears) {
  write("other.l", "module B(float);\naxiom: B(7);\n");
  build();
  build("other.l");
  const std::vector<std::string> cache_dir = {"--cache-dir", options_.cache_dir};
  auto sylva_cache = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "cache");
    args.insert(args.end(), cache_dir.begin(), cache_dir.end());
    return run_sylva(args);
  };
  ProcessResult shown = sylva_cache({});
  EXPECT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_NE(shown.out.find("folder: " + options_.cache_dir + "\n"), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("models: 2\n"), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("size:   "), std::string::npos) << shown.out;

  const ProcessResult pruned = sylva_cache({"prune", "--max-size", "1"});
  EXPECT_EQ(pruned.exit_code, 0) << pruned.err;
  EXPECT_EQ(pruned.out.find("removed 2 compiled models"), 0u) << pruned.out;
  build();
  const ProcessResult cleared = sylva_cache({"clear"});
  EXPECT_EQ(cleared.exit_code, 0) << cleared.err;
  EXPECT_EQ(cleared.out.find("removed 1 compiled model "), 0u) << cleared.out;
  shown = sylva_cache({});
  EXPECT_NE(shown.out.find("models: 0\n"), std::string::npos) << shown.out;

  const ProcessResult bad = sylva_cache({"prune", "--max-size", "lots"});
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("expected a size such as 500M or 2G"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace sylva::test
