// Plan text made safe for toml++ 3.3.0, whose whitespace test reaches
// __builtin_unreachable on some non-ASCII code points: stray ones are errors
// at their place, those in multi-line basic strings become escapes of the
// same code points, and the plan reads as TOML says it should.
#include <gtest/gtest.h>

#include <fstream>

#include "experiment/plan.h"
#include "experiment/toml_text.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::experiment {
namespace {

std::string error_of(const std::string& text) {
  try {
    toml_text_for_parser(text, "plan.toml");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TomlText, CommentsLiteralAndOneLineStringsPassAsTheyAre) {
  const std::string text =
      "# widths in \xC2\xB5m\n"                   // µm
      "a = \"r\xC3\xA9sultats\"  # \xCE\x9B\n"  // résultats, Λ
      "b = 'x\xCE\x9B'\n"
      "c = '''\n\xCE\x9B'''\n"
      "\"k\xC3\xA9y\" = 1\n";
  EXPECT_EQ(toml_text_for_parser(text, "plan.toml"), text);
}

TEST(TomlText, MultiLineBasicStringsGetEscapes) {
  // U+039B (two bytes), U+20AC (three) and U+1F331 (four).
  EXPECT_EQ(toml_text_for_parser("a = \"\"\"x \\\n   \xCE\x9B\xE2\x82\xAC\xF0\x9F\x8C\xB1\"\"\"\n", "plan.toml"),
            "a = \"\"\"x \\\n   \\u039B\\u20AC\\U0001F331\"\"\"\n");
  // Quotes and escaped quotes inside do not end it; what follows is outside.
  EXPECT_EQ(toml_text_for_parser("a = \"\"\"\\\"\"\"\xCE\x9B\"\"\"\"\"\n", "plan.toml"),
            "a = \"\"\"\\\"\"\"\\u039B\"\"\"\"\"\n");
  EXPECT_EQ(error_of("a = \"\"\"\\\"\"\"\xCE\x9B\"\"\"\"\"\nb = \xCE\x9B\n").substr(0, 14), "plan.toml:2:5:");
}

TEST(TomlText, StrayCharactersAreErrorsAtTheirPlace) {
  EXPECT_EQ(error_of("a = 1\nA = [1, \xCE\x9B]\n"),
            "plan.toml:2:9: error: expected a key, a value or a comment; TOML allows characters outside ASCII only "
            "in strings and comments");
  // Columns count characters: the string before holds a two-byte one.
  EXPECT_EQ(error_of("a = \"\xC3\xA9\" \xCE\x9B\n").substr(0, 14), "plan.toml:1:9:");
  EXPECT_EQ(error_of("a = \"\"\"\\\xCE\x9B\"\"\"\n").substr(0, 14), "plan.toml:1:9:");
}

TEST(TomlText, APlanReadsAfterALineEndingBackslash) {
  const std::string dir = test::make_temp_dir("toml-text");
  std::ofstream(dir + "/m.l") << "#define A 1\n";
  // TOML: a backslash at a line's end trims the whitespace and line breaks
  // that follow.
  const Plan plan = parse_plan(
      "model = \"m.l\"\noutput = \"\"\"out-\\\n    \xCE\x9B.csv\"\"\"\n[parameters]\nA = [1, 2]\n"
      "[measures]\nn = \"count(A)\"\n",
      dir + "/plan.toml");
  EXPECT_EQ(std::filesystem::path(plan.output).filename().string(), "out-\xCE\x9B.csv");
}

}  // namespace
}  // namespace sylva::experiment
