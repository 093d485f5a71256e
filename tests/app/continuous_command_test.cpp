// `sylva run --time`: a differential L-system run in time from the command
// line, its recorded parameters and plot, and the errors of a run that cannot
// be carried out (an explicit method on a stiff system, a discrete model, a
// module that is not declared).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace sylva::test {
namespace {

std::string test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

// A fresh folder holding `text` as model.l.
std::string folder_with_model(const std::string& text) {
  const std::string dir = make_temp_dir("continuous-" + test_name());
  std::ofstream(dir + "/model.l") << text;
  return dir;
}

// dx/dt = x (1 - x) from x = 0.5: x(t) = 1 / (1 + e^-t).
const std::string kLogistic =
    "#include <lpfgall.h>\n"
    "module A(double);\n"
    "axiom: A(0.5);\n"
    "derivatives:\n"
    "A(x) : { d(x) = x * (1 - x); }\n";

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(ContinuousCommand, RecordsParametersAtEverySample) {
  const std::string dir = folder_with_model(kLogistic);
  const ProcessResult r = run_sylva({"run", "model.l", "--time", "2", "--dt", "0.5", "--record", "A",
                                     "--tolerance", "1e-10"},
                                    dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(r.out);
  ASSERT_EQ(rows.size(), 1u + 5u) << r.out;  // the header, t = 0, 0.5, 1, 1.5, 2
  EXPECT_EQ(rows[0], (std::vector<std::string>{"t", "index", "module", "parameter", "value"}));
  for (std::size_t k = 1; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 5u);
    const double t = std::stod(rows[k][0]);
    EXPECT_DOUBLE_EQ(t, 0.5 * static_cast<double>(k - 1));
    EXPECT_EQ(rows[k][1], "0");
    EXPECT_EQ(rows[k][2], "A");
    EXPECT_EQ(rows[k][3], "p1");
    EXPECT_NEAR(std::stod(rows[k][4]), 1 / (1 + std::exp(-t)), 1e-8) << "t = " << t;
  }
}

TEST(ContinuousCommand, WritesTheRecordAndItsPlotToFiles) {
  const std::string dir = folder_with_model(kLogistic);
  const ProcessResult r = run_sylva(
      {"run", "model.l", "--time", "1", "--dt", "0.25", "--record", "A", "--record-file", "a.csv", "--plot", "a.png"},
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");  // neither the record nor the string on standard output
  EXPECT_EQ(csv_rows(read_text(dir + "/a.csv")).size(), 1u + 5u);
  const std::string png = read_text(dir + "/a.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(ContinuousCommand, FramesHoldTheStateAtEverySample) {
  const std::string dir = folder_with_model(kLogistic);
  const ProcessResult r = run_sylva({"run", "model.l", "--time", "1", "--dt", "0.5", "--tolerance", "1e-10", "--frames",
                                     "frames", "--frame-format", "str", "--frame-format", "obj"},
                                    dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (int k = 0; k <= 2; ++k) {
    const std::string stem = dir + "/frames/frame-000" + std::to_string(k);
    const std::string text = read_text(stem + ".str");
    ASSERT_EQ(text.rfind("A(", 0), 0u) << text;
    EXPECT_NEAR(std::stod(text.substr(2)), 1 / (1 + std::exp(-0.5 * k)), 1e-8) << "sample " << k;
    EXPECT_TRUE(std::filesystem::exists(stem + ".obj"));
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/frames/frame-0003.str"));
}

TEST(ContinuousCommand, TheAnimationFileCanGiveTheTimes) {
  const std::string dir = folder_with_model(kLogistic);
  std::ofstream(dir + "/model.a") << "end time: 1\ntime step: 0.5\n";
  const ProcessResult r =
      run_sylva({"run", "model.l", "model.a", "--frames", "f", "--frame-format", "str", "--string", "end.str"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/f/frame-0002.str"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/f/frame-0003.str"));
  EXPECT_NEAR(std::stod(read_text(dir + "/end.str").substr(2)), 1 / (1 + std::exp(-1.0)), 1e-6);
}

TEST(ContinuousCommand, AnUnknownFrameFormatIsAnError) {
  const std::string dir = folder_with_model(kLogistic);
  const ProcessResult r = run_sylva({"run", "model.l", "--time", "1", "--frames", "f", "--frame-format", "jpg"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--frame-format jpg: error: unknown frame format"), std::string::npos) << r.err;
}

TEST(ContinuousCommand, AnExplicitMethodOnAStiffSystemStopsWithTheTimeReached) {
  const std::string dir = folder_with_model(
      "#include <lpfgall.h>\nmodule A(double);\naxiom: A(1);\nderivatives:\nA(x) : { d(x) = -1000 * x; }\n");
  const ProcessResult r =
      run_sylva({"run", "model.l", "--time", "5", "--integrator", "rk4", "--step", "0.1", "--string", "out.str"}, dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("model.l: error: the solution stopped being finite at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--integrator cvode"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.str")) << "no string written with NaN in it";
  // The stiff method takes it in its stride: x(5) = e^-5000, 0 to any tolerance.
  const ProcessResult cvode = run_sylva({"run", "model.l", "--time", "5", "--integrator", "cvode"}, dir);
  ASSERT_EQ(cvode.exit_code, 0) << cvode.err;
  EXPECT_LT(std::abs(std::stod(cvode.out.substr(2))), 1e-6) << cvode.out;
}

TEST(ContinuousCommand, TimeNeedsADifferentialLSystem) {
  const std::string dir = folder_with_model("#include <lpfgall.h>\nmodule A;\naxiom: A;\nA : { produce A A; }\n");
  const ProcessResult r = run_sylva({"run", "model.l", "--time", "1"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--time needs a model with derivative or event rules"), std::string::npos) << r.err;
}

TEST(ContinuousCommand, RecordingAModuleTheModelDoesNotDeclareIsAnError) {
  const std::string dir = folder_with_model(kLogistic);
  const ProcessResult r = run_sylva({"run", "model.l", "--time", "1", "--record", "B", "--record-file", "b.csv"}, dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--record B: the model declares no module 'B'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/b.csv"));
}

}  // namespace
}  // namespace sylva::test
