// Erroneous models whose C++ the compiler rejects: the error names the
// model's line and a column on that line (the token it is about where the
// model has one), never one inside the generated code.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "test_support.h"

namespace sylva::test {
namespace {

struct BadModel {
  std::string name;
  std::string text;
  int line;
  int column;  // 0: only that it lies on the line
  std::string what;
};

const BadModel kBadModels[] = {
    {"TypeErrorInAProduceArgument",
     "module A(float);\naxiom: A(1);\nA(x) : {\n  produce A(\"text\");\n}\n", 4, 13, "cannot convert"},
    {"UndeclaredNameInACondition",
     "module A(float);\naxiom: A(1);\nA(x) : {\n  if (x < undeclared_limit) produce A(x + 1);\n}\n", 4, 11,
     "undeclared_limit"},
    {"WrongArgumentCount", "module A(float);\naxiom: A(1);\nA(x) : {\n  produce A(x, 2);\n}\n", 4, 11,
     "has 1 parameter but is given 2"},
    {"ErrorInStart", "module A(float);\nStart: {\n  int n = \"not a number\";\n}\naxiom: A(1);\n", 3, 11,
     "invalid conversion"},
    {"ErrorInAFunction",
     "module A(float);\nfloat grow(float x) {\n  return x * missing_factor;\n}\naxiom: A(1);\n"
     "A(x) : { produce A(grow(x)); }\n",
     3, 14, "missing_factor"},
    {"ErrorAfterAMultiLineProduce",
     "module A(float);\nmodule B(float, float);\naxiom: A(1);\nA(x) : {\n  produce A(x)\n          B(x, 2)\n"
     "          A(x);\n  float y = x + no_such_name;\n  produce A(y);\n}\n",
     8, 17, "no_such_name"},
    {"ErrorAfterGeneratedTextOnTheLine",
     "module A(float);\naxiom: A(1);\nA(x) : { produce A(x) A(nothing_here); }\n", 3, 25, "nothing_here"},
    {"ErrorInTheAxiom", "module A(float);\naxiom: A(1) A(nope);\n", 2, 15, "nope"},
    {"ErrorInNproduce", "module A(float);\naxiom: A(1);\nA(x) : {\n  nproduce A(x) A(undefined_var);\n  produce;\n}\n",
     4, 19, "undefined_var"},
    {"ErrorInASetting", "module A(float);\nderivation length: bogus_len;\naxiom: A(1);\n", 2, 20, "bogus_len"},
    {"ErrorInAContextTest",
     "module A(float);\nmodule B(float);\naxiom: A(1) B(2);\nB(y) : {\n  const char* p;\n"
     "  if (InLeftContext(A(p))) produce B(y);\n}\n",
     6, 23, "invalid initialization"},
    {"ParameterTypeThatCannotBeCopied", "#include <string>\nmodule A(std::string);\naxiom: A(\"x\");\n", 2, 0,
     "trivially copyable"},
};

class CompilerErrorColumns : public ::testing::TestWithParam<BadModel> {};

TEST_P(CompilerErrorColumns, PointAtTheModelsLine) {
  const BadModel& bad = GetParam();
  const std::string dir = make_temp_dir("error-columns-" + bad.name);
  {
    std::ofstream(dir + "/model.l") << bad.text;
  }
  const ProcessResult r = run_sylva({"run", "model.l", "--string", "out.txt"}, dir);
  ASSERT_NE(r.exit_code, 0);
  std::smatch m;
  static const std::regex located(R"((?:^|\n)model\.l:(\d+):(\d+): error: ([^\n]*))");
  ASSERT_TRUE(std::regex_search(r.err, m, located)) << r.err;
  std::vector<std::string> lines;
  std::istringstream text(bad.text);
  for (std::string l; std::getline(text, l);) lines.push_back(l);
  const int line = std::stoi(m[1].str()), column = std::stoi(m[2].str());
  EXPECT_EQ(line, bad.line) << r.err;
  ASSERT_GE(line, 1);
  ASSERT_LE(line, static_cast<int>(lines.size()));
  EXPECT_GE(column, 1) << r.err;
  EXPECT_LE(column, static_cast<int>(lines[static_cast<std::size_t>(line - 1)].size())) << r.err;
  if (bad.column != 0) {
    EXPECT_EQ(column, bad.column) << r.err;
  }
  EXPECT_NE(r.err.find(bad.what), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Models, CompilerErrorColumns, ::testing::ValuesIn(kBadModels),
                         [](const ::testing::TestParamInfo<BadModel>& info) { return info.param.name; });

}  // namespace
}  // namespace sylva::test
