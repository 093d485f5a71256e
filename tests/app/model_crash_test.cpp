// A model whose code crashes, run by the sylva program: the run ends with a
// message naming the rule and the step, a non-zero status, and no output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "test_support.h"

namespace sylva::test {
namespace {

namespace fs = std::filesystem;

// Runs `command` with sh in `dir`, "$SYLVA" naming the program; stderr ends
// with "status N", the command's exit status as the shell gives it (128 + the
// signal's number for a process killed by a signal).
ProcessResult run_shell(const std::string& dir, const std::string& command) {
  return run_process({"/usr/bin/env", "-C", dir, std::string("SYLVA_CACHE_DIR=") + SYLVA_TEST_CACHE_DIR,
                      std::string("SYLVA=") + SYLVA_BINARY, "/bin/sh", "-c",
                      command + "; echo \"status $?\" >&2"});
}

std::string model_dir(const std::string& text) {
  const std::string dir =
      make_temp_dir(std::string("crash-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::ofstream(dir + "/model.l") << text;
  return dir;
}

bool nothing_but_the_model(const std::string& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.path().filename() != "model.l") return false;
  return true;
}

TEST(ModelCrash, IntegerDivisionByZeroNamesTheProductionAndTheStep) {
  const std::string dir = model_dir(
      "module A(int);\n"
      "volatile int zero = 0;\n"
      "derivation length: 3;\n"
      "axiom: A(1);\n"
      "A(n) : {\n"
      "  if (n >= 2) produce A(n / zero);\n"
      "  produce A(n + 1);\n"
      "}\n");
  const ProcessResult r = run_shell(dir, "\"$SYLVA\" run model.l --string out.txt");
  EXPECT_NE(r.err.find("model.l:5: error: model crashed in production (SIGFPE, integer division by zero) (step 2)\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("status 136"), std::string::npos) << r.err;  // SIGFPE
  EXPECT_TRUE(nothing_but_the_model(dir));
}

TEST(ModelCrash, AThrownIntIsAnErrorAtTheProduction) {
  const std::string dir = model_dir(
      "module A(float);\n"
      "derivation length: 1;\n"
      "axiom: A(1);\n"
      "A(x) : { throw 42; }\n");
  const ProcessResult r = run_shell(dir, "\"$SYLVA\" run model.l --string out.txt");
  EXPECT_EQ(r.err, "model.l:4: error: model threw an exception in production (int) (step 1)\nstatus 1\n");
  EXPECT_TRUE(nothing_but_the_model(dir));
}

// ---- standard output

const char* const kModel =
    "module A(float);\n"
    "axiom: A(1);\n";

TEST(StandardOutput, AFullDiskIsAnError) {
  const std::string dir = model_dir(kModel);
  const ProcessResult r = run_shell(dir, "\"$SYLVA\" run model.l > /dev/full");
  EXPECT_EQ(r.err, "sylva: error: cannot write to standard output: No space left on device\nstatus 1\n");
  const ProcessResult translated = run_shell(dir, "\"$SYLVA\" translate model.l > /dev/full");
  EXPECT_EQ(translated.err, "sylva: error: cannot write to standard output: No space left on device\nstatus 1\n");
  const ProcessResult help = run_shell(dir, "\"$SYLVA\" --help > /dev/full");
  EXPECT_EQ(help.err, "sylva: error: cannot write to standard output: No space left on device\nstatus 1\n");
}

TEST(StandardOutput, AClosedStandardOutputIsAnError) {
  // A model of its own, so it is compiled in this run: the compiler's pipes
  // must not take the closed descriptor's place.
  const std::string dir = model_dir(std::string(kModel) + "// compiled with standard output closed\n");
  const ProcessResult r = run_shell(dir, "\"$SYLVA\" run model.l >&-");
  EXPECT_EQ(r.err, "sylva: error: cannot write to standard output: Bad file descriptor\nstatus 1\n");
}

TEST(StandardOutput, AWriteThatWorksStillSucceeds) {
  const std::string dir = model_dir(kModel);
  const ProcessResult r = run_shell(dir, "\"$SYLVA\" run model.l");
  EXPECT_EQ(r.out, "A(1)\n");
  EXPECT_EQ(r.err, "status 0\n");
}

}  // namespace
}  // namespace sylva::test
