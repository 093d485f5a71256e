// A run bounded in modules, string memory and time: a runaway derivation
// stops at the step that crosses a limit, with a message naming the step and
// the limit, before the allocation that would cross it; through the command
// line the run fails and writes nothing.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "api/simulation.h"
#include "lstring/module_string.h"
#include "lstring/module_types.h"
#include "lstring/run_limits.h"
#include "test_support.h"

namespace sylva::test {
namespace {

constexpr const char* kRunaway =
    "#include <lpfgall.h>\nmodule A();\nderivation length: 60;\naxiom: A;\nA() : { produce A A; }\n";

std::unique_ptr<Simulation> open(const std::string& path, const RunLimits& limits) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.limits = limits;
  return std::make_unique<Simulation>(path, options, [](const std::string&) {});
}

std::string limit_message(Simulation& s) {
  try {
    s.run();
  } catch (const LimitExceeded& e) {
    return e.what();
  }
  return "no limit reached";
}

TEST(RunLimits, ByteSizes) {
  EXPECT_EQ(parse_byte_size("1000"), 1000u);
  EXPECT_EQ(parse_byte_size("512M"), std::size_t{512} << 20);
  EXPECT_EQ(parse_byte_size("8G"), std::size_t{8} << 30);
  EXPECT_EQ(parse_byte_size("8GiB"), std::size_t{8} << 30);
  EXPECT_EQ(parse_byte_size("2kb"), 2048u);
  EXPECT_EQ(parse_byte_size("0"), 0u);
  EXPECT_EQ(parse_byte_size("lots"), std::nullopt);
  EXPECT_EQ(parse_byte_size("5X"), std::nullopt);
  EXPECT_EQ(parse_byte_size("99999999999999T"), std::nullopt);
}

TEST(RunLimits, DefaultsProtectTheMachine) {
  const RunLimits limits = default_run_limits();
  EXPECT_GT(limits.max_memory, 0u);
  EXPECT_EQ(limits.max_modules, 0u);  // a string only derived is bounded by its memory
  EXPECT_EQ(limits.max_drawn_modules, limits.max_memory / 64);
  EXPECT_EQ(max_modules_for_memory(std::size_t{1} << 30), std::size_t{1} << 24);
  EXPECT_EQ(max_modules_for_memory(0), 0u);
  EXPECT_EQ(limits.timeout_seconds, 0);
}

// Strings of six-byte P(float) and one-byte Q modules against a limit of 10:
// the count stops early only where the bytes left cannot cross it.
TEST(RunLimits, ModulesAreCountedWhateverTheirSizesAndOrder) {
  const ModuleTypes types({{"P", sizeof(float)}, {"Q", 0}});
  auto string_of = [&](const std::string& pattern) {
    ModuleString s;
    const float x = 1;
    for (char c : pattern) c == 'P' ? s.append_module(0, &x, sizeof x) : s.append_module(1, nullptr, 0);
    return s;
  };
  RunBudget budget;
  budget.set_limits(RunLimits{10, 0, 0});
  budget.set_module_sizes(types.encoded_sizes());
  auto crosses = [&](const std::string& pattern) {
    const ModuleString s = string_of(pattern);
    try {
      budget.check_modules(s.data(), s.size_bytes());
    } catch (const LimitExceeded&) {
      return true;
    }
    return false;
  };
  EXPECT_FALSE(crosses("PPPQQQQQQQ"));    // 25 bytes, 10 modules
  EXPECT_TRUE(crosses("PPPQQQQQQQQ"));    // 26 bytes, 11
  EXPECT_TRUE(crosses("QQQQQQQQPPP"));    // 26 bytes, 11, the small ones first
  EXPECT_FALSE(crosses("PPPPPPPPPP"));    // 60 bytes, 10
  EXPECT_TRUE(crosses("PPPPPPPPPPP"));    // 66 bytes, 11
  EXPECT_FALSE(crosses("QQQQQQQQQQ"));    // 10 bytes, 10: not counted
  EXPECT_TRUE(crosses("QPQPQPQPQPQ"));    // 11 modules
}

TEST(RunLimits, ModulesStopTheStepThatCrossesThem) {
  const std::string path = write_temp_file("limits-modules", "runaway.l", kRunaway);
  auto s = open(path, RunLimits{1000, 0, 0});
  // 2^10 = 1024 modules after step 10.
  EXPECT_EQ(limit_message(*s),
            "sylva: error: step 10: the string has more than 1000 modules, the limit (--max-modules N raises it)");
  EXPECT_EQ(s->step_number(), 10);  // the step that crossed it, not one more
}

TEST(RunLimits, MemoryStopsTheStepBeforeItAllocatesPastTheLimit) {
  const std::string path = write_temp_file("limits-memory", "runaway.l", kRunaway);
  const std::size_t limit = std::size_t{64} << 20;
  auto s = open(path, RunLimits{0, limit, 0});
  const std::string message = limit_message(*s);
  // A module A takes 1 byte: 2^26 of them fill 64 MiB, with the step's old
  // string beside the new one a step or two sooner.
  EXPECT_NE(message.find("sylva: error: step 2"), std::string::npos) << message;
  EXPECT_NE(message.find("more than the limit of 64.0 MiB (--max-memory SIZE raises it)"), std::string::npos)
      << message;
  EXPECT_LE(string_bytes_in_use(), limit);
}

// 2^11 = 2048 modules derive past a drawing limit of 1000, and stop when
// drawn; 2^9 = 512 draw.
TEST(RunLimits, ADrawingHoldsNoMoreModulesThanItsLimit) {
  const std::string path = write_temp_file("limits-drawn", "runaway.l", kRunaway);
  RunLimits limits;
  limits.max_drawn_modules = 1000;
  auto s = open(path, limits);
  s->run(11);
  EXPECT_EQ(s->string().count_modules(s->types()), 2048u);
  std::string message = "no limit reached";
  try {
    s->scene(0);
  } catch (const LimitExceeded& e) {
    message = e.what();
  }
  EXPECT_EQ(message,
            "sylva: error: drawing after step 11: the string has more than 1000 modules, the most a drawing may have "
            "within the memory limit (--max-memory SIZE raises it)");
  s->run(9);
  EXPECT_NO_THROW(s->scene(0));
}

TEST(RunLimits, TimeStopsTheRunBetweenSteps) {
  const std::string path = write_temp_file(
      "limits-time", "slow.l",
      "#include <lpfgall.h>\nmodule A();\nderivation length: 2000000000;\naxiom: A;\nA() : { produce A; }\n");
  auto s = open(path, RunLimits{0, 0, 0.2});
  const auto started = std::chrono::steady_clock::now();
  const std::string message = limit_message(*s);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
  EXPECT_NE(message.find("the run went past its time limit of 0.2 s (--timeout SECONDS sets another)"),
            std::string::npos)
      << message;
}

TEST(RunLimits, TheCommandLineFailsAndWritesNothing) {
  const std::string dir = make_temp_dir("limits-cli");
  const std::string model = write_temp_file("limits-cli-model", "runaway.l", kRunaway);
  const ProcessResult r = run_sylva({"run", model, "--max-modules", "5000", "-s", dir + "/out.str"}, dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("step 13: the string has more than 5000 modules"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.str"));
  const ProcessResult memory = run_sylva({"run", model, "--max-memory", "1M", "--max-modules", "0", "-s", dir + "/out.str"}, dir);
  EXPECT_EQ(memory.exit_code, 1) << memory.err;
  EXPECT_NE(memory.err.find("--max-memory SIZE raises it"), std::string::npos) << memory.err;
  const ProcessResult bad = run_sylva({"run", model, "--max-memory", "lots"}, dir);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("expected a size such as 4G or 512M, not 'lots'"), std::string::npos) << bad.err;
}

TEST(RunLimits, AModelThatNeverComesBackIsStoppedAfterItsTime) {
  const std::string dir = make_temp_dir("limits-watchdog");
  const std::string model = write_temp_file(
      "limits-watchdog-model", "loop.l",
      "#include <lpfgall.h>\nmodule A();\nderivation length: 1;\naxiom: A;\n"
      "A() : { volatile int forever = 1; while (forever) {} produce A; }\n");
  const auto started = std::chrono::steady_clock::now();
  const ProcessResult r = run_sylva({"run", model, "--timeout", "0.5", "-s", dir + "/out.str"}, dir);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(60));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("sylva: error: step 1: the run went past its time limit of 0.5 s and did not come back"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.str"));
}

}  // namespace
}  // namespace sylva::test
