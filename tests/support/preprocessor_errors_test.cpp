// The preprocessor's first error, read from what GCC writes, at its file,
// line and column.
#include <gtest/gtest.h>

#include "support/preprocessor_errors.h"

namespace sylva::test {
namespace {

std::string first(const std::string& err, const std::string& argument = "model.l", const std::string& path = "model.l") {
  std::optional<ModelError> e = first_preprocessor_error(err, argument, path);
  return e ? e->what() : "(none)";
}

TEST(PreprocessorErrors, AFatalErrorIsAnError) {
  EXPECT_EQ(first("model.l:2:10: fatal error: missing.h: No such file or directory\n"
                  "    2 | #include \"missing.h\"\n"
                  "      |          ^~~~~~~~~~~\n"
                  "compilation terminated.\n"),
            "model.l:2:10: error: missing.h: No such file or directory");
}

TEST(PreprocessorErrors, ALineWithoutAColumnGetsColumnOne) {
  EXPECT_EQ(first("model.l:2: error: unterminated #if\n    2 | #if 1\n"), "model.l:2:1: error: unterminated #if");
}

TEST(PreprocessorErrors, TheFirstErrorCountsNotWarningsBeforeIt) {
  EXPECT_EQ(first("model.l:1:9: warning: \"X\" redefined\nmodel.l:4:2: error: #error no\nmodel.l:5:2: error: #error two\n"),
            "model.l:4:2: error: #error no");
}

TEST(PreprocessorErrors, AnIncludedFileSaysWhereItWasIncluded) {
  EXPECT_EQ(first("In file included from inner.h:1,\n"
                  "                 from model.l:3:\n"
                  "deep.h:7:2: error: #error deep\n"),
            "deep.h:7:2: error: #error deep (in a file included from model.l:3)");
  EXPECT_EQ(first("In file included from model.l:3:\ninc.h:1:4: error: #if with no expression\n"),
            "inc.h:1:4: error: #if with no expression (in a file included from model.l:3)");
}

TEST(PreprocessorErrors, TheFileIsNamedAsTheUserGaveIt) {
  EXPECT_EQ(first("./-odd.v:2:2: error: #error x\n", "./-odd.v", "-odd.v"), "-odd.v:2:2: error: #error x");
}

TEST(PreprocessorErrors, NothingLocatedIsNone) {
  EXPECT_EQ(first(""), "(none)");
  EXPECT_EQ(first("g++: fatal error: no input files\n"), "(none)");
  EXPECT_EQ(first("model.l:99999999999999999999:1: error: x\n"), "model.l:1: error: x");
}

}  // namespace
}  // namespace sylva::test
