// The sylva program as a user meets it: messages for bad input (file, line,
// column, what was expected; no crash; no output file left behind) and the
// behaviour of the command line options, the model cache and the outputs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
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

// A(START), START given with -D.
const char* const kNeedsStart =
    "#ifndef START\n"
    "#error START is not defined\n"
    "#endif\n"
    "module A(float);\n"
    "axiom: A(START);\n"
    "derivation length: 0;\n";

// ---- bad input ------------------------------------------------------------------

// A model that fails: stderr has a line that begins with `prefix` and says
// `what`; the position in the prefix is counted by hand in the text.
struct BadModel {
  std::string name;
  std::string text;
  std::string prefix;
  std::string what;
};

const std::vector<BadModel> kBadModels = {
    {"UndeclaredModuleInPredecessor",
     "module A(float);\n"
     "axiom: A(1);\n"
     "A(x) : { produce A(x); }\n"
     "  B(x) : { produce A(x); }\n",  // B: line 4, column 3
     "model.l:4:3: error: ", "undeclared module 'B'"},
    {"UndeclaredModuleInAxiom",
     "module A(float);\n"
     "\n"
     "axiom: A(1) Q(2);\n",  // Q: line 3, column 13
     "model.l:3:13: error: ", "undeclared module 'Q'"},
    {"UndeclaredModuleInProduce",
     "module A(float);\n"
     "axiom: A(1);\n"
     "A(x) :\n"
     "{\n"
     "  produce A(x) Q(x);\n"  // Q: line 5, column 16
     "}\n",
     "model.l:5:16: error: ", "undeclared module 'Q'"},
    {"WrongParameterCountInAxiom",
     "module A(float);\n"
     "axiom: F(1) A(1, 2);\n",  // A: line 2, column 13
     "model.l:2:13: error: ", "module 'A' has 1 parameter but is given 2"},
    {"WrongParameterCountInProduce",
     "module A(float, float);\n"
     "axiom: A(1, 2);\n"
     "A(x, y) : { produce F(1) A(x); }\n",  // A: line 3, column 26
     "model.l:3:26: error: ", "module 'A' has 2 parameters but is given 1"},
    {"WrongParameterCountInPredecessor",
     "module A(float);\n"
     "axiom: A(1);\n"
     "A(x) : { produce A(x); }\n"
     "    A(x, y) : { produce A(x); }\n",  // A: line 4, column 5
     "model.l:4:5: error: ", "module 'A' has 1 parameter but the predecessor names 2"},
    {"MissingSemicolonAfterModuleDeclaration",
     "module A(float)\n"
     "axiom: A(1);\n",  // reported at 'axiom': line 2, column 1
     "model.l:2:1: error: ", "expected ';' after the declaration of module 'A'"},
    {"UnterminatedParameterList",
     "module A(float);\n"
     "module B(float",  // the file ends after 'float': line 2, column 15
     "model.l:2:15: error: ", "expected ')'"},
    {"UnterminatedBody",
     "module A(float);\n"
     "axiom: A(1);\n"
     "A(x) : {\n"  // the body's '{': line 3, column 8
     "  if (x > 0) {\n"
     "    produce A(x + 1);\n"
     "  }\n",
     "model.l:3:8: error: ", "expected '}'"},
    {"PredefinedModuleRedeclared",
     "module A(float);\n"
     "module F(float);\n"  // F: line 2, column 8
     "axiom: A(1);\n",
     "model.l:2:8: error: ", "'F' is a predefined module"},
    // Without -D START, the model's own #error is reported where it stands.
    {"PreprocessorError", kNeedsStart, "model.l:2:", "START is not defined"},
};

class CliBadModel : public ::testing::TestWithParam<BadModel> {};

TEST_P(CliBadModel, FailsWithItsPositionAndWritesNothing) {
  const std::string dir = make_temp_dir("cli-bad-" + GetParam().name);
  const ProcessResult r = run_bad_model(dir, GetParam().text);
  EXPECT_TRUE(FailsWith(r, GetParam().prefix, GetParam().what));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

INSTANTIATE_TEST_SUITE_P(Table, CliBadModel, ::testing::ValuesIn(kBadModels),
                         [](const ::testing::TestParamInfo<BadModel>& info) { return info.param.name; });

// A command line that fails, run in a folder that holds a model (model.l) and
// a folder named like one (plant.l).
struct BadCommandLine {
  std::string name;
  std::vector<std::string> args;
  std::string prefix;
  std::string what;
};

const std::vector<BadCommandLine> kBadCommandLines = {
    {"MissingModelFile", {"run", "absent.l", "--string", "out.txt"}, "absent.l: error: ", "no such file"},
    {"MissingModelFileTranslated", {"translate", "absent.l"}, "absent.l: error: ", "no such file"},
    {"DirectoryAsModel", {"run", "plant.l", "--string", "out.txt"}, "plant.l: error: ", "is a directory"},
    {"DirectoryAsModelTranslated", {"translate", "plant.l"}, "plant.l: error: ", "is a directory"},
    {"UnknownOption", {"run", "model.l", "--string", "out.txt", "--bogus"}, "sylva: error: ", "--bogus"},
    {"UnknownOptionAlone", {"--bogus"}, "sylva: error: ", "--bogus"},
    // A mistyped command is named, not reported as a missing one.
    {"MistypedCommand", {"runn", "model.l"}, "sylva: error: ", "runn"},
    {"NoCommand", {}, "sylva: error: ", "run, experiment, studio or translate"},
    {"NegativeStepCount", {"run", "model.l", "--string", "out.txt", "--steps", "-3"}, "sylva: error: --steps: ",
     "expected a number of steps (0 or more), not '-3'"},
    {"StepCountNotANumber", {"run", "model.l", "--string", "out.txt", "--steps", "x"}, "sylva: error: --steps: ",
     "expected a number of steps (0 or more), not 'x'"},
    {"StepCountWithTrailingText", {"run", "model.l", "--string", "out.txt", "--steps", "2x"},
     "sylva: error: --steps: ", "expected a number of steps (0 or more), not '2x'"},
};

class CliBadCommandLine : public ::testing::TestWithParam<BadCommandLine> {};

TEST_P(CliBadCommandLine, FailsAndWritesNothing) {
  const std::string dir = make_temp_dir("cli-args-" + GetParam().name);
  write_file(dir + "/model.l", "module A(float);\naxiom: A(1);\n");
  fs::create_directory(dir + "/plant.l");
  EXPECT_TRUE(FailsWith(run_sylva(GetParam().args, dir), GetParam().prefix, GetParam().what));
  EXPECT_TRUE(NothingWritten(dir, "out.txt"));
}

INSTANTIATE_TEST_SUITE_P(Table, CliBadCommandLine, ::testing::ValuesIn(kBadCommandLines),
                         [](const ::testing::TestParamInfo<BadCommandLine>& info) { return info.param.name; });

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

// A model that runs: what it prints on stdout, and on stderr (exactly, or a
// part of it).
struct GoodRun {
  std::string name;
  std::string model;
  std::vector<std::string> args;
  std::string out;
  std::optional<std::string> err = std::nullopt;  // the whole of stderr
  std::string err_part = "";                       // a part of stderr
};

const std::vector<GoodRun> kGoodRuns = {
    // The string goes to standard output by default, or with --string -.
    {"StringToStandardOutputByDefault", kGrowing, {"run", "model.l"}, "A(9)\n", ""},
    {"StringToStandardOutputByDash", kGrowing, {"run", "model.l", "--string", "-"}, "A(9)\n"},
    {"StepsGiven", kGrowing, {"run", "model.l", "--steps", "1"}, "A(7)\n"},
    // -D and --define reach the preprocessor.
    {"ShortDefine", kNeedsStart, {"run", "model.l", "-D", "START=5"}, "A(5)\n"},
    {"LongDefine", kNeedsStart, {"run", "model.l", "--define", "START=7"}, "A(7)\n"},
    // Printf goes to standard error, the string to standard output.
    {"PrintfGoesToStandardError",
     "module A(float);\n"
     "axiom: A(5);\n"
     "derivation length: 2;\n"
     "A(x) : { Printf(\"grow %g\\n\", x); produce A(x + 1); }\n",
     {"run", "model.l"},
     "A(7)\n",
     std::nullopt,
     "grow 5\ngrow 6\n"},
};

class CliRun : public ::testing::TestWithParam<GoodRun> {};

TEST_P(CliRun, PrintsTheString) {
  const GoodRun& run = GetParam();
  const std::string dir = make_temp_dir("cli-run-" + run.name);
  write_file(dir + "/model.l", run.model);
  const ProcessResult r = run_sylva(run.args, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, run.out);
  if (run.err) {
    EXPECT_EQ(r.err, *run.err);
  }
  EXPECT_NE(r.err.find(run.err_part), std::string::npos) << show(r);
}

INSTANTIATE_TEST_SUITE_P(Table, CliRun, ::testing::ValuesIn(kGoodRuns),
                         [](const ::testing::TestParamInfo<GoodRun>& info) { return info.param.name; });

TEST(Cli, StringToFile) {
  std::string dir = test_dir();
  write_file(dir + "/model.l", kGrowing);
  ProcessResult r = run_sylva({"run", "model.l", "--string", "out.txt"}, dir);
  ASSERT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(read_text(dir + "/out.txt"), "A(9)\n");
  // Only the file itself (and its provenance record, docs/provenance.md): no temporary file remains.
  int entries = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 3);  // model.l, out.txt and out.txt.provenance.json
  EXPECT_TRUE(fs::exists(dir + "/out.txt.provenance.json"));

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

}  // namespace
}  // namespace sylva::test
