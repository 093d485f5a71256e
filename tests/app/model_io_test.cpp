// What a model does with files through its predefined functions, and the
// command-line options around them: saved strings read back (OutputString,
// LoadString, --axiom-from), images it asks for (OutputFrame), several views
// (UseView, vgroup, window:), and VerifyString:. Expected values are worked
// out by hand in the comments or computed here the way the model does.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace sylva::test {
namespace {
namespace fs = std::filesystem;

std::string test_dir() {
  return make_temp_dir(std::string("model-io-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string show(const ProcessResult& r) {
  return "exit status " + std::to_string(r.exit_code) + "\n--- stdout ---\n" + r.out + "\n--- stderr ---\n" + r.err;
}

// Runs sylva in `dir` and expects success; returns its standard output.
std::string run_ok(const std::vector<std::string>& args, const std::string& dir) {
  ProcessResult r = run_sylva(args, dir);
  EXPECT_EQ(r.exit_code, 0) << show(r);
  return r.out;
}

// A reported failure: non-zero exit, no crash, nothing on stdout, and a
// stderr line starting with `prefix` and containing `what`.
::testing::AssertionResult FailsWith(const ProcessResult& r, const std::string& prefix, const std::string& what) {
  if (r.exit_code <= 0 || r.exit_code >= 128) return ::testing::AssertionFailure() << "expected a reported failure: " << show(r);
  if (!r.out.empty()) return ::testing::AssertionFailure() << "printed on stdout: " << show(r);
  std::istringstream lines(r.err);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(prefix, 0) == 0 && line.find(what) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no stderr line \"" << prefix << "..." << what << "\": " << show(r);
}

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Image read_png(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  if (!data) return image;
  image.rgb.assign(data, data + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  stbi_image_free(data);
  return image;
}

// Pixels that are not the background (the first pixel's colour).
int drawn_pixels(const Image& image) {
  int n = 0;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3)
    if (image.rgb[i] != image.rgb[0] || image.rgb[i + 1] != image.rgb[1] || image.rgb[i + 2] != image.rgb[2]) ++n;
  return n;
}

std::string count_lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) n += line.rfind(prefix, 0) == 0;
  return std::to_string(n);
}

// ---- saved strings --------------------------------------------------------------

const std::string kStringIo = example_path("string-io/string-io.l");

TEST(SavedStrings, OutputStringThenLoadStringOrAxiomFromContinueTheDerivationExactly) {
  const std::string dir = test_dir();
  const std::string uninterrupted = run_ok({"run", kStringIo}, dir);  // 8 steps
  run_ok({"run", kStringIo, "-D", "SAVE_AT=3", "--string", "final.txt"}, dir);
  ASSERT_TRUE(fs::exists(dir + "/saved.str"));

  // After 3 steps: three cells C(...) and the apex, whose radius the model
  // grows as r -> r*1.3f + 0.01f from 0.1f; printed with the fewest digits
  // that read back to the same float.
  const std::string saved = read_text(dir + "/saved.str");
  float r = 0.1f;
  for (int k = 0; k < 3; ++k) r = r * 1.3f + 0.01f;
  char number[32] = "";
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(number, sizeof number, "%.*g", digits, r);
    if (std::strtof(number, nullptr) == r) break;
  }
  EXPECT_EQ(saved.substr(saved.rfind(' ') + 1), "Apex(" + std::string(number) + ",3)\n");
  EXPECT_EQ(saved.rfind("C({id=0,", 0), 0u) << saved;

  // Five more steps from the saved string: the uninterrupted run's string,
  // struct, enum, vector, bool and double parameters to the last bit.
  EXPECT_EQ(run_ok({"run", kStringIo, "--axiom-from", "saved.str", "--steps", "5"}, dir), uninterrupted);
  EXPECT_EQ(run_ok({"run", kStringIo, "-D", "LOAD", "--steps", "5"}, dir), uninterrupted);
}

TEST(SavedStrings, ASavedStringReadsBackAsItWasWritten) {
  // --string output read with --axiom-from and 0 steps writes the same text.
  const std::string dir = test_dir();
  run_ok({"run", kStringIo, "--steps", "4", "--string", "four.str"}, dir);
  EXPECT_EQ(run_ok({"run", kStringIo, "--axiom-from", "four.str", "--steps", "0"}, dir), read_text(dir + "/four.str"));
}

TEST(SavedStrings, MalformedSavedStringsAreErrorsAtTheirLineAndColumn) {
  const std::string dir = test_dir();
  struct Case {
    std::string text, where, what;
  };
  const std::vector<Case> cases = {
      {"Apex(1,0)\n  Leaf Apex(1,0)\n", "bad.str:2:3: error: ", "unknown module 'Leaf'"},
      {"Apex(1,0) Apex(1)\n", "bad.str:1:11: error: ", "module 'Apex' has 2 parameters but the saved string gives 1"},
      {"Apex\n", "bad.str:1:1: error: ", "module 'Apex' has 2 parameters but the saved string gives none"},
      {"Apex(1,0,2)\n", "bad.str:1:1: error: ", "gives 3"},
      {"Apex(1,x)\n", "bad.str:1:8: error: ", "expected an integer in the parameters of 'Apex'"},
      {"C({id=0,mass=1,age=0,divided=2},0,(0,0,0))\n", "bad.str:1:30: error: ", "expected 0 or 1"},
      {"C({id=0,weight=1},0,(0,0,0))\n", "bad.str:1:9: error: ", "expected a field of Cell"},
      {"C({id=0,mass=1,age=0,divided=0},0,(0,0))\n", "bad.str:1:39: error: ", "expected ','"},
      // Cell has the fields id, mass, age, divided: each must be given once.
      {"C({id=0},0,(0,0,0))\n", "bad.str:1:8: error: ", "expected field 'mass'"},
      {"C({},0,(0,0,0))\n", "bad.str:1:4: error: ", "expected field 'id'"},
      {"C({mass=1,age=0,divided=0,id=1,age=2},0,(0,0,0))\n", "bad.str:1:32: error: ", "expected field 'age' only once"},
      {"Apex(1,0\n", "bad.str:1:5: error: ", "expected ')'"},
  };
  for (const Case& c : cases) {
    write_file(dir + "/bad.str", c.text);
    ProcessResult r = run_sylva({"run", kStringIo, "--axiom-from", "bad.str", "--string", "out.txt"}, dir);
    EXPECT_TRUE(FailsWith(r, c.where, c.what)) << c.text;
    EXPECT_FALSE(fs::exists(dir + "/out.txt")) << c.text;
  }
  ProcessResult missing = run_sylva({"run", kStringIo, "--axiom-from", "none.str"}, dir);
  EXPECT_TRUE(FailsWith(missing, "none.str: error: ", "cannot read the saved string"));
}

TEST(SavedStrings, ADirectoryOrAnEmptyFileIsNoSavedString) {
  const std::string dir = test_dir();
  fs::create_directories(dir + "/folder.str");
  EXPECT_TRUE(FailsWith(run_sylva({"run", kStringIo, "--axiom-from", "folder.str"}, dir), "folder.str: error: ",
                        "cannot read the saved string: it is a directory"));
  write_file(dir + "/empty.str", "");
  EXPECT_TRUE(FailsWith(run_sylva({"run", kStringIo, "--axiom-from", "empty.str"}, dir), "empty.str: error: ",
                        "the file is empty"));
  // LoadString("saved.str") in Start, saved.str being a folder.
  fs::create_directories(dir + "/saved.str");
  ProcessResult r = run_sylva({"run", kStringIo, "-D", "LOAD", "--string", "out.txt"}, dir);
  EXPECT_TRUE(FailsWith(r, "saved.str: error: ", "cannot read the saved string: it is a directory"));
  EXPECT_FALSE(fs::exists(dir + "/out.txt"));
}

TEST(SavedStrings, AStringOfNoModulesIsSavedAsALineAndReadsBack) {
  const std::string dir = test_dir();
  write_file(dir + "/model.l",
             "module A;\n"
             "derivation length: 1;\n"
             "axiom: A;\n"
             "A : { produce; }\n");
  run_ok({"run", "model.l", "--string", "none.str"}, dir);
  EXPECT_EQ(read_text(dir + "/none.str"), "\n");
  EXPECT_EQ(run_ok({"run", "model.l", "--axiom-from", "none.str", "--steps", "0"}, dir), "\n");
}

TEST(SavedStrings, LoadStringOfAMalformedFileStopsTheRun) {
  const std::string dir = test_dir();
  write_file(dir + "/saved.str", "Apex(0.5,1) C(1)\n");
  ProcessResult r = run_sylva({"run", kStringIo, "-D", "LOAD", "--string", "out.txt"}, dir);
  EXPECT_TRUE(FailsWith(r, "saved.str:1:13: error: ", "module 'C' has 3 parameters but the saved string gives 1"));
  EXPECT_FALSE(fs::exists(dir + "/out.txt"));
}

// ---- OutputFrame ----------------------------------------------------------------

TEST(OutputFrame, WritesAnImageOfTheStepItWasCalledIn) {
  const std::string dir = test_dir();
  write_file(dir + "/model.l",
             "module A;\n"
             "derivation length: 3;\n"
             "axiom: A;\n"
             "EndEach: { if (StepNo() == 1) OutputFrame(\"one.png\"); if (StepNo() == 3) OutputFrame(\"three.obj\"); }\n"
             "A : { produce F(1) A; }\n");
  run_ok({"run", "model.l", "--width", "64", "--height", "48", "--string", "final.txt"}, dir);
  const Image one = read_png(dir + "/one.png");
  EXPECT_EQ(one.width, 64);
  EXPECT_EQ(one.height, 48);
  EXPECT_GT(drawn_pixels(one), 0);
  // After step 3 the string is F(1) F(1) F(1) A: three segments, three OBJ groups named after their F.
  const std::string obj = read_text(dir + "/three.obj");
  EXPECT_EQ(count_lines_starting(obj, "g F_"), "3");
}

TEST(OutputFrame, NoFrameWhenStopIsCalledInTheSameStep) {
  const std::string dir = test_dir();
  write_file(dir + "/model.l",
             "module A;\n"
             "derivation length: 5;\n"
             "axiom: A;\n"
             "EndEach: { OutputFrame(StepNo() == 1 ? \"one.png\" : \"two.png\"); if (StepNo() == 2) Stop(); }\n"
             "A : { produce F(1) A; }\n");
  run_ok({"run", "model.l", "--width", "32", "--height", "32", "--string", "final.txt"}, dir);
  EXPECT_TRUE(fs::exists(dir + "/one.png"));
  EXPECT_FALSE(fs::exists(dir + "/two.png"));
  EXPECT_EQ(read_text(dir + "/final.txt"), "F(1) F(1) A\n");
}

TEST(OutputFrame, AnUnknownFormatIsAnError) {
  const std::string dir = test_dir();
  write_file(dir + "/model.l", "module A;\naxiom: A;\nStart: { OutputFrame(\"x.tiff\"); }\n");
  EXPECT_TRUE(FailsWith(run_sylva({"run", "model.l", "--string", "out.txt"}, dir), "x.tiff: error: ",
                        "unknown output format"));
  EXPECT_FALSE(fs::exists(dir + "/out.txt"));
}

// ---- multi-view -----------------------------------------------------------------

TEST(MultiView, EachViewIsAFileOfItsOwnDrawnWithItsVgroup) {
  const std::string dir = test_dir();
  const std::string model = example_path("multi-view/multi-view.l"), view = example_path("multi-view/multi-view.v");
  run_ok({"run", model, view, "-o", "plant.png", "-o", "plant.obj", "--width", "200", "--height", "100"}, dir);
  // Two windows, each half the width: 100 x 100 pixels.
  const Image stem = read_png(dir + "/plant.png"), crown = read_png(dir + "/plant-Crown.png");
  EXPECT_EQ(stem.width, 100);
  EXPECT_EQ(stem.height, 100);
  EXPECT_EQ(crown.width, 100);
  EXPECT_EQ(crown.height, 100);
  EXPECT_GT(drawn_pixels(stem), 0);
  EXPECT_NE(stem.rgb, crown.rgb);
  // After 4 steps: 8 leaves L. Stem draws them as F (lines) and no spheres;
  // Crown draws each as a Sphere, provenance naming the sphere after itself.
  const std::string stem_obj = read_text(dir + "/plant.obj"), crown_obj = read_text(dir + "/plant-Crown.obj");
  EXPECT_EQ(count_lines_starting(stem_obj, "g Sphere_"), "0");
  EXPECT_EQ(count_lines_starting(crown_obj, "g Sphere_"), "8");
  // OutputFrame("step2.png") in a two-view model: one file per view too.
  EXPECT_EQ(read_png(dir + "/step2.png").width, 100);
  EXPECT_EQ(read_png(dir + "/step2-Crown.png").width, 100);
}

TEST(MultiView, WindowsAreViewsFromOne) {
  // Vgroup 0 is no window (LPFG manual 5.12, footnote 3): the names of the
  // window: commands are 1, 2, ... in order.
  const std::string dir = test_dir();
  write_file(dir + "/model.v", "window: Main 0 0 1 1\nwindow: Small 0 0 0.5 0.5\n");
  write_file(dir + "/model.l", "module R(int);\naxiom: R(Main) R(Small);\n");
  EXPECT_EQ(run_ok({"run", "model.l", "model.v"}, dir), "R(1) R(2)\n");
}

TEST(MultiView, QueryModulesUseTheRulesOfVgroupZero) {
  // The first window is view 1, whose vgroup draws L as F(5); the query pass
  // uses vgroup 0, the rules outside any vgroup, which draw it as F(2): the
  // turtle, heading up, is at height 2 at GetPos.
  const std::string dir = test_dir();
  write_file(dir + "/model.v", "window: Stem 0 0 0.5 1\nwindow: Crown 0.5 0 0.5 1\n");
  write_file(dir + "/model.l",
             "module L;\nmodule A;\nmodule R(float);\n"
             "derivation length: 2;\n"
             "Start: { UseView(Stem); UseView(Crown); }\n"
             "axiom: L A;\n"
             "A : { produce GetPos(0,0,0); }\n"
             "GetPos(x,y,z) : { produce R(y); }\n"
             "interpretation:\n"
             "L : { produce F(2); }\n"
             "vgroup Stem:\n"
             "L : { produce F(5); }\n"
             "vgroup Crown:\n"
             "L : { produce F(7); }\n"
             "endgroup\n");
  EXPECT_EQ(run_ok({"run", "model.l", "model.v"}, dir), "L R(2)\n");
}

TEST(MultiView, UseViewOfNoWindowIsAnError) {
  const std::string dir = test_dir();
  write_file(dir + "/model.v", "window: Main 0 0 0.5 1\nwindow: Side 0.5 0 0.5 1\n");
  write_file(dir + "/model.l", "module L;\nStart: { UseView(Main); UseView(5); }\naxiom: L;\n");
  ProcessResult r = run_sylva({"run", "model.l", "model.v", "-o", "plant.png"}, dir);
  EXPECT_TRUE(FailsWith(r, "model.l: error: ", "UseView(5): no such view; the view file defines 2 windows, views 1 to 2"));
  EXPECT_FALSE(fs::exists(dir + "/plant-view5.png"));
  write_file(dir + "/zero.l", "module L;\nStart: { UseView(0); }\naxiom: L;\n");
  EXPECT_TRUE(FailsWith(run_sylva({"run", "zero.l", "model.v"}, dir), "zero.l: error: ", "UseView(0): no such view"));
  EXPECT_TRUE(FailsWith(run_sylva({"run", "zero.l"}, dir), "zero.l: error: ", "there is no view file"));
}

TEST(MultiView, WithoutUseViewOnlyViewZeroIsDrawn) {
  const std::string dir = test_dir();
  write_file(dir + "/model.v", "window: Main 0 0 1 1\nwindow: Small 0 0 0.5 0.5\n");
  write_file(dir + "/model.l",
             "module L;\n"
             "axiom: L;\n"
             "interpretation:\n"
             "vgroup Small:\n"
             "L : { produce Sphere(1); }\n"
             "endgroup\n"
             "L : { produce F(1); }\n");
  run_ok({"run", "model.l", "model.v", "-o", "plant.obj", "--interpreted", "shown.txt"}, dir);
  EXPECT_EQ(read_text(dir + "/shown.txt"), "F(1)\n");
  EXPECT_FALSE(fs::exists(dir + "/plant-Small.obj"));
}

TEST(MultiView, AVgroupWithoutANumberOrNameIsAnError) {
  const std::string dir = test_dir();
  write_file(dir + "/model.l", "module L;\naxiom: L;\ninterpretation:\nvgroup Nowhere:\nL : { produce F(1); }\n");
  EXPECT_TRUE(FailsWith(run_sylva({"run", "model.l"}, dir), "model.l:4:8: error: ", "expected a view"));
}

// ---- VerifyString ---------------------------------------------------------------

const std::string kVerify = example_path("verify-string/verify-string.l");

TEST(VerifyString, AMatchingStringSaysSuccess) {
  const std::string dir = test_dir();
  ProcessResult r = run_sylva({"run", kVerify}, dir);
  EXPECT_EQ(r.exit_code, 0) << show(r);
  EXPECT_EQ(r.out, "I(0) SB B EB I(1) SB B EB A(2)\n");
  EXPECT_NE(r.err.find("Verify: Success"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/Verify_verify-string.l_actual.txt"));
}

TEST(VerifyString, AMismatchFailsAndWritesBothStrings) {
  const std::string dir = test_dir();
  ProcessResult r = run_sylva({"run", kVerify, "-D", "WRONG", "--string", "out.txt"}, dir);
  // Expected I [ B ] A; derived I [ B ] I [ B ] A: the fifth module differs.
  EXPECT_TRUE(FailsWith(r, kVerify + ": error: ", "module 5 is 'I', expected 'A'"));
  EXPECT_NE(r.err.find("Verify: Fail"), std::string::npos);
  EXPECT_EQ(read_text(dir + "/Verify_verify-string.l_expected.txt"), "I SB B EB A\n");
  EXPECT_EQ(read_text(dir + "/Verify_verify-string.l_actual.txt"), "I SB B EB I SB B EB A\n");
  EXPECT_FALSE(fs::exists(dir + "/out.txt"));
}

TEST(VerifyString, ASecondStatementIsAnError) {
  const std::string dir = test_dir();
  write_file(dir + "/model.l",
             "module A;\n"
             "axiom: A;\n"
             "VerifyString: A;\n"
             "  VerifyString: A A;\n");
  EXPECT_TRUE(FailsWith(run_sylva({"run", "model.l"}, dir), "model.l:4:3: error: ",
                        "only one VerifyString: per model; the first is at line 3"));
}

TEST(VerifyString, FewerStepsAreAMismatch) {
  const std::string dir = test_dir();
  ProcessResult r = run_sylva({"run", kVerify, "--steps", "1"}, dir);
    // One step: I(0) [ B ] A(1), where I [ B ] I [ B ] A is expected.
  EXPECT_TRUE(FailsWith(r, kVerify + ": error: ", "module 5 is 'A', expected 'I'"));
}

}  // namespace
}  // namespace sylva::test

namespace sylva::test {
namespace {

// Parameters the engine prints from their table, and a struct with a
// bit-field, which the model's own printer writes: the same text either way,
// and both read back.
TEST(SavedStrings, TablePrintedAndModelPrintedParametersReadBack) {
  const std::string dir = test_dir();
  write_file(dir + "/m.l", R"(#include <lpfgall.h>
struct Packed { int flag : 3; float size; };
struct Plain { int flag; float size; };
derivation length: 1;
module P(Packed, double);
module Q(Plain, V3f);
module A();
Axiom: A;
A: { Packed p; p.flag = 2; p.size = 0.1f; Plain q = {2, 0.1f}; produce P(p, 0.1) Q(q, V3f(1, 0.5f, -2)); }
)");
  const std::string text = run_ok({"run", "m.l", "--string", "-"}, dir);
  EXPECT_EQ(text, "P({flag=2,size=0.1},0.1) Q({flag=2,size=0.1},(1,0.5,-2))\n");
  write_file(dir + "/saved.str", text);
  EXPECT_EQ(run_ok({"run", "m.l", "--axiom-from", "saved.str", "--steps", "0"}, dir), text);
}

}  // namespace
}  // namespace sylva::test
