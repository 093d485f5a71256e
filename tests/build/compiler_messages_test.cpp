// The C++ compiler's messages as the user sees them: about the model's
// lines, never at a column past the end of one.
#include <gtest/gtest.h>

#include <map>

#include "build/compiler_messages.h"

namespace sylva::test {
namespace {

using build::compiler_messages;

// model.l as the messages below point into it.
const std::map<int, std::string> kModel = {
    {3, "A(x) : {"},
    {4, "  produce A(\"text\");"},
    {5, "\tproduce B;"},
    {6, ""},
};

std::string messages(const std::string& err) {
  return compiler_messages(err, [](const std::string& file, int line) -> std::optional<std::string> {
    auto it = kModel.find(line);
    if (file != "model.l" || it == kModel.end()) return std::nullopt;
    return it->second;
  });
}

TEST(CompilerMessages, LinesAboutGeneratedFunctionsAreDropped) {
  EXPECT_EQ(messages("model.l: In function 'void sylva_rule_0(RuleCall*)':\n"
                     "model.l:4:13: error: cannot convert 'const char*' to 'float'\n"
                     "model.l: At global scope:\n"
                     "compilation terminated.\n"),
            "model.l:4:13: error: cannot convert 'const char*' to 'float'");
}

TEST(CompilerMessages, AColumnOnTheLineStays) {
  const std::string err =
      "model.l:4:20: error: expected ';'\n"
      "    4 |   produce A(\"text\");\n"
      "      |                    ^";
  EXPECT_EQ(messages(err), err);
}

TEST(CompilerMessages, AColumnPastTheLineMovesToItsFirstStatement) {
  EXPECT_EQ(messages("model.l:4:218: error: cannot convert 'const char*' to 'float'\n"
                     "    4 |   produce A(\"text\");\n"
                     "      |                                                                           ^\n"
                     "      |                                                                           |\n"
                     "      |                                                                           const char*\n"
                     "model.l:3:1: note: here\n"),
            "model.l:4:3: error: cannot convert 'const char*' to 'float'\n"
            "    4 |   produce A(\"text\");\n"
            "      |   ^\n"
            "model.l:3:1: note: here");
}

TEST(CompilerMessages, ColumnsCountATabToTheNextStop) {
  // "\tproduce B;" ends at column 18; column 9 is 'p'.
  EXPECT_EQ(messages("model.l:5:18: error: x"), "model.l:5:18: error: x");
  EXPECT_EQ(messages("model.l:5:40: warning: y"), "model.l:5:9: warning: y");
  EXPECT_EQ(messages("model.l:6:30: error: z"), "model.l:6:1: error: z");
}

TEST(CompilerMessages, FilesThatCannotBeReadKeepTheirColumns) {
  EXPECT_EQ(messages("other.h:4:218: error: x"), "other.h:4:218: error: x");
  EXPECT_EQ(messages("model.l:99:218: error: x"), "model.l:99:218: error: x");
}

}  // namespace
}  // namespace sylva::test
