// Lines and words as the studio's file readers and editors see them.
#include <gtest/gtest.h>

#include "studio/text_lines.h"

namespace sylva::studio {
namespace {

TEST(TextLines, LinesAreViewsWithoutTheirEndsAtTheirOffsets) {
  const std::string text = "a\r\n\nb c\nlast";
  const std::vector<TextLine> lines = split_lines(text);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].text, "a");
  EXPECT_EQ(lines[0].offset, 0u);
  EXPECT_EQ(lines[1].text, "");
  EXPECT_EQ(lines[1].offset, 3u);
  EXPECT_EQ(lines[2].text, "b c");
  EXPECT_EQ(lines[2].offset, 4u);
  EXPECT_EQ(lines[3].text, "last");
  EXPECT_EQ(lines[3].offset, 8u);
  EXPECT_EQ(lines[3].number, 4);
  EXPECT_TRUE(split_lines("").empty());
  EXPECT_EQ(split_lines("x\n").size(), 1u);
}

TEST(TextLines, WordsAndTrimmingSkipSpacesTabsAndCarriageReturns) {
  EXPECT_EQ(split_words(" \t#define\tSIZE  4 \r"), (std::vector<std::string_view>{"#define", "SIZE", "4"}));
  EXPECT_TRUE(split_words(" \t ").empty());
  EXPECT_EQ(trim_blanks("\t name: x \r"), "name: x");
  EXPECT_EQ(trim_blanks("  "), "");
}

}  // namespace
}  // namespace sylva::studio
