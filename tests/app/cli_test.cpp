// The sylva program as a user meets it: messages for bad input (file, line,
// column, what was expected; no crash; no output file left behind) and the
// behaviour of the command line options, the model cache and the outputs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

std::string current_test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

// A fresh directory of the test's own.
std::string test_dir() { return make_temp_dir("cli-" + current_test_name()); }

std::string show(const ProcessResult& r) {
  return "exit status " + std::to_string(r.exit_code) + "\n--- stdout ---\n" + r.out + "\n--- stderr ---\n" + r.err;
}

// A failure that was reported, not a crash: a plain non-zero exit status (a
// signal reads as -1), a line of stderr that begins with `prefix` and says
// `what`, nothing on stdout, and no trace of an abort.
::testing::AssertionResult FailsWith(const ProcessResult& r, const std::string& prefix, const std::string& what) {
  if (r.exit_code == 0) return ::testing::AssertionFailure() << "expected a failure, got " << show(r);
  if (r.exit_code < 0 || r.exit_code >= 128)
    return ::testing::AssertionFailure() << "killed or crashed: " << show(r);
  for (const char* crash : {"terminate called", "Aborted", "Segmentation fault", "core dumped"})
    if (r.err.find(crash) != std::string::npos)
      return ::testing::AssertionFailure() << "crashed (" << crash << "): " << show(r);
  if (!r.out.empty()) return ::testing::AssertionFailure() << "printed on stdout: " << show(r);
  std::istringstream lines(r.err);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(prefix, 0) == 0 && line.find(what) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no line of stderr begins with \"" << prefix << "\" and contains \"" << what
                                       << "\": " << show(r);
}

// Neither `name` nor a temporary file of it (name.tmp*) is in `dir`.
::testing::AssertionResult NothingWritten(const std::string& dir, const std::string& name) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    std::string file = entry.path().filename().string();
    if (file.rfind(name, 0) == 0) return ::testing::AssertionFailure() << entry.path() << " was left behind";
  }
  return ::testing::AssertionSuccess();
}

// Writes `text` to DIR/model.l and runs `sylva run model.l --string out.txt` in DIR.
ProcessResult run_bad_model(const std::string& dir, const std::string& text) {
  write_file(dir + "/model.l", text);
  return run_sylva({"run", "model.l", "--string", "out.txt"}, dir);
}

// ---- bad input ------------------------------------------------------------------

TEST(CliErrors, UndeclaredModuleInPredecessor) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "axiom: A(1);\n"
                                  "A(x) : { produce A(x); }\n"
                                  "  B(x) : { produce A(x); }\n");  // B: line 4, column 3
  EXPECT_TRUE(FailsWith(r, "model.l:4:3: error: ", "undeclared module 'B'"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, UndeclaredModuleInAxiom) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "\n"
                                  "axiom: A(1) Q(2);\n");  // Q: line 3, column 13
  EXPECT_TRUE(FailsWith(r, "model.l:3:13: error: ", "undeclared module 'Q'"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, UndeclaredModuleInProduce) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "axiom: A(1);\n"
                                  "A(x) :\n"
                                  "{\n"
                                  "  produce A(x) Q(x);\n"  // Q: line 5, column 16
                                  "}\n");
  EXPECT_TRUE(FailsWith(r, "model.l:5:16: error: ", "undeclared module 'Q'"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, WrongParameterCountInAxiom) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "axiom: F(1) A(1, 2);\n");  // A: line 2, column 13
  EXPECT_TRUE(FailsWith(r, "model.l:2:13: error: ", "module 'A' has 1 parameter but is given 2"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, WrongParameterCountInProduce) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float, float);\n"
                                  "axiom: A(1, 2);\n"
                                  "A(x, y) : { produce F(1) A(x); }\n");  // A: line 3, column 26
  EXPECT_TRUE(FailsWith(r, "model.l:3:26: error: ", "module 'A' has 2 parameters but is given 1"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, WrongParameterCountInPredecessor) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "axiom: A(1);\n"
                                  "A(x) : { produce A(x); }\n"
                                  "    A(x, y) : { produce A(x); }\n");  // A: line 4, column 5
  EXPECT_TRUE(FailsWith(r, "model.l:4:5: error: ", "module 'A' has 1 parameter but the predecessor names 2"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, MissingSemicolonAfterModuleDeclaration) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float)\n"
                                  "axiom: A(1);\n");  // reported at 'axiom': line 2, column 1
  EXPECT_TRUE(FailsWith(r, "model.l:2:1: error: ", "expected ';' after the declaration of module 'A'"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, UnterminatedParameterList) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "module B(float");  // the file ends after 'float': line 2, column 15
  EXPECT_TRUE(FailsWith(r, "model.l:2:15: error: ", "expected ')'"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, UnterminatedBody) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "axiom: A(1);\n"
                                  "A(x) : {\n"  // the body's '{': line 3, column 8
                                  "  if (x > 0) {\n"
                                  "    produce A(x + 1);\n"
                                  "  }\n");
  EXPECT_TRUE(FailsWith(r, "model.l:3:8: error: ", "expected '}'"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, PredefinedModuleRedeclared) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "module F(float);\n"  // F: line 2, column 8
                                  "axiom: A(1);\n");
  EXPECT_TRUE(FailsWith(r, "model.l:2:8: error: ", "'F' is a predefined module"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, MissingModelFile) {
  std::string dir = test_dir();
  ProcessResult r = run_sylva({"run", "absent.l", "--string", "out.txt"}, dir);
  EXPECT_TRUE(FailsWith(r, "absent.l: error: ", "no such file"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
  EXPECT_TRUE(FailsWith(run_sylva({"translate", "absent.l"}, dir), "absent.l: error: ", "no such file"));
}

TEST(CliErrors, DirectoryAsModel) {
  std::string dir = test_dir();
  fs::create_directory(dir + "/plant.l");
  ProcessResult r = run_sylva({"run", "plant.l", "--string", "out.txt"}, dir);
  EXPECT_TRUE(FailsWith(r, "plant.l: error: ", "is a directory"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
  EXPECT_TRUE(FailsWith(run_sylva({"translate", "plant.l"}, dir), "plant.l: error: ", "is a directory"));
}

TEST(CliErrors, UnknownOption) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", "module A(float);\naxiom: A(1);\n");
  ProcessResult r = run_sylva({"run", "model.l", "--string", "out.txt", "--bogus"}, dir);
  EXPECT_TRUE(FailsWith(r, "sylva: error: ", "--bogus"));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
  EXPECT_TRUE(FailsWith(run_sylva({"--bogus"}, dir), "sylva: error: ", "--bogus"));
  // A mistyped command is named, not reported as a missing one.
  EXPECT_TRUE(FailsWith(run_sylva({"runn", "model.l"}, dir), "sylva: error: ", "runn"));
  EXPECT_TRUE(FailsWith(run_sylva({}, dir), "sylva: error: ", "run or translate"));
}

TEST(CliErrors, BadStepCount) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", "module A(float);\naxiom: A(1);\n");
  for (const char* steps : {"-3", "x", "2x"}) {
    ProcessResult r = run_sylva({"run", "model.l", "--string", "out.txt", "--steps", steps}, dir);
    EXPECT_TRUE(FailsWith(r, "sylva: error: --steps: ", std::string("expected a number of steps (0 or more), not '") +
                                                           steps + "'"));
    EXPECT_TRUE(NothingWritten(dir, "out.txt"));
  }
}

TEST(CliErrors, CppErrorInProductionBody) {
  std::string dir = test_dir();
  ProcessResult r = run_bad_model(dir,
                                  "module A(float);\n"
                                  "axiom: A(1);\n"
                                  "A(x) : {\n"
                                  "  float y = x + undeclared_thing;\n"  // line 4, column 17
                                  "  produce A(y);\n"
                                  "}\n");
  EXPECT_TRUE(FailsWith(r, "model.l:4:17: error: ", "undeclared_thing"));
  // The message is about the model, not about the generated C++.
  EXPECT_EQ(r.err.find(".ii"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("model-cache"), std::string::npos) << r.err;
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

TEST(CliErrors, UnwritableStringPath) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", "module A(float);\naxiom: A(1);\nderivation length: 1;\n");
  ProcessResult r = run_sylva({"run", "model.l", "--string", "missing/out.txt"}, dir);
  EXPECT_TRUE(FailsWith(r, "missing/out.txt: error: ", "cannot write"));
  EXPECT_FALSE(fs::exists(dir + "/missing"));
  EXPECT_TRUE(NothingWritten(dir, "missing"));

  // A directory where the file should be.
  fs::create_directory(dir + "/taken");
  r = run_sylva({"run", "model.l", "--string", "taken"}, dir);
  EXPECT_TRUE(FailsWith(r, "taken: error: ", "cannot write"));
  EXPECT_TRUE(fs::is_directory(dir + "/taken"));
  EXPECT_TRUE(fs::is_empty(dir + "/taken"));
  EXPECT_TRUE(NothingWritten(dir, "taken.tmp"));
}

// ---- good behaviour -------------------------------------------------------------

// Two steps of A(x) -> A(x + 2) from A(5).
const char* const kGrowing =
    "module A(float);\n"
    "axiom: A(5);\n"
    "derivation length: 2;\n"
    "A(x) : { produce A(x + 2); }\n";

TEST(Cli, RunHelpMentionsEveryOption) {
  ProcessResult r = run_sylva({"run", "--help"});
  ASSERT_EQ(r.exit_code, 0) << show(r);
  for (const char* option : {"--steps", "--string", "--interpreted", "--cache-dir", "--compiler", "--define"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option << " missing from:\n" << r.out;
}

TEST(Cli, StringGoesToStandardOutput) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", kGrowing);
  ProcessResult by_default = run_sylva({"run", "model.l"}, dir);
  ASSERT_EQ(by_default.exit_code, 0) << show(by_default);
  EXPECT_EQ(by_default.out, "A(9)\n");
  EXPECT_EQ(by_default.err, "");

  ProcessResult dash = run_sylva({"run", "model.l", "--string", "-"}, dir);
  ASSERT_EQ(dash.exit_code, 0) << show(dash);
  EXPECT_EQ(dash.out, "A(9)\n");

  ProcessResult steps = run_sylva({"run", "model.l", "--steps", "1"}, dir);
  ASSERT_EQ(steps.exit_code, 0) << show(steps);
  EXPECT_EQ(steps.out, "A(7)\n");
}

TEST(Cli, StringToFile) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", kGrowing);
  ProcessResult r = run_sylva({"run", "model.l", "--string", "out.txt"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(read_text(dir + "/out.txt"), "A(9)\n");
  // Only the file itself: no temporary file remains.
  int entries = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 2);  // model.l and out.txt

  // Overwritten by the next run.
  r = run_sylva({"run", "model.l", "--steps", "0", "--string", "out.txt"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(read_text(dir + "/out.txt"), "A(5)\n");
}

TEST(Cli, CompilesOnlyWhatChanged) {
  std::string dir = test_dir();
  std::string cache = dir + "/cache";  // a cache of this test's own: the first run must compile
  auto run = [&] { return run_sylva({"run", "model.l", "--verbose", "--cache-dir", cache}, dir); };
  auto compiled = [](const ProcessResult& r) { return r.err.find("sylva: compiling") != std::string::npos; };

  write_file(dir + "/step.h", "#define STEP 2\n");
  write_file(dir + "/model.l",
             "#include \"step.h\"\n"
             "module A(float);\n"
             "axiom: A(5);\n"
             "derivation length: 2;\n"
             "A(x) : { produce A(x + STEP); }\n");
  ProcessResult first = run();
  ASSERT_EQ(first.exit_code, 0) << show(first);
  EXPECT_TRUE(compiled(first)) << show(first);
  EXPECT_EQ(first.out, "A(9)\n");

  ProcessResult again = run();
  ASSERT_EQ(again.exit_code, 0) << show(again);
  EXPECT_FALSE(compiled(again)) << show(again);
  EXPECT_EQ(again.out, "A(9)\n");

  // The model changes.
  write_file(dir + "/model.l",
             "#include \"step.h\"\n"
             "module A(float);\n"
             "axiom: A(50);\n"
             "derivation length: 2;\n"
             "A(x) : { produce A(x + STEP); }\n");
  ProcessResult changed = run();
  ASSERT_EQ(changed.exit_code, 0) << show(changed);
  EXPECT_TRUE(compiled(changed)) << show(changed);
  EXPECT_EQ(changed.out, "A(54)\n");
  EXPECT_FALSE(compiled(run()));

  // A file it includes changes.
  write_file(dir + "/step.h", "#define STEP 10\n");
  ProcessResult header_changed = run();
  ASSERT_EQ(header_changed.exit_code, 0) << show(header_changed);
  EXPECT_TRUE(compiled(header_changed)) << show(header_changed);
  EXPECT_EQ(header_changed.out, "A(70)\n");

  ProcessResult settled = run();
  ASSERT_EQ(settled.exit_code, 0) << show(settled);
  EXPECT_FALSE(compiled(settled)) << show(settled);
  EXPECT_EQ(settled.out, "A(70)\n");
}

TEST(Cli, TranslatePrintsCpp) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", kGrowing);
  ProcessResult r = run_sylva({"translate", "model.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_NE(r.out.find("sylva_model_v1"), std::string::npos);

  r = run_sylva({"translate", "model.l", "-o", "model.cpp"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(read_text(dir + "/model.cpp").find("sylva_model_v1"), std::string::npos);
}

TEST(Cli, DefineReachesThePreprocessor) {
  std::string dir = test_dir();
  write_file(dir + "/model.l",
             "#ifndef START\n"
             "#error START is not defined\n"
             "#endif\n"
             "module A(float);\n"
             "axiom: A(START);\n"
             "derivation length: 0;\n");
  ProcessResult r = run_sylva({"run", "model.l", "-D", "START=5"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "A(5)\n");

  r = run_sylva({"run", "model.l", "--define", "START=7"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "A(7)\n");

  // Without it, the model's own #error is reported where it stands.
  r = run_sylva({"run", "model.l"}, dir);
  EXPECT_TRUE(FailsWith(r, "model.l:2:", "START is not defined"));
}

TEST(Cli, IncludeFromTheModelsDirectory) {
  std::string dir = test_dir();
  fs::create_directory(dir + "/model");
  write_file(dir + "/model/other.h", "#define STEP 3\n");
  write_file(dir + "/model/plant.l",
             "#include \"other.h\"\n"
             "module A(float);\n"
             "axiom: A(1);\n"
             "derivation length: 2;\n"
             "A(x) : { produce A(x + STEP); }\n");
  // Run from elsewhere: the include is found next to the model, not in the working directory.
  ProcessResult r = run_sylva({"run", "model/plant.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "A(7)\n");
  r = run_sylva({"run", dir + "/model/plant.l"}, "/");
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "A(7)\n");
}

TEST(Cli, PrintfGoesToStandardError) {
  std::string dir = test_dir();
  write_file(dir + "/model.l",
             "module A(float);\n"
             "axiom: A(5);\n"
             "derivation length: 2;\n"
             "A(x) : { Printf(\"grow %g\\n\", x); produce A(x + 1); }\n");
  ProcessResult r = run_sylva({"run", "model.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "A(7)\n");
  EXPECT_NE(r.err.find("grow 5\ngrow 6\n"), std::string::npos) << show(r);
}

}  // namespace
}  // namespace sylva::test
