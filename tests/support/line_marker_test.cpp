// The preprocessor's line markers, read from the lines gcc -E writes.
#include "support/line_marker.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

TEST(LineMarker, LineAndFile) {
  std::optional<LineMarker> m = parse_line_marker("# 12 \"plant.l\"");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->line, 12);
  EXPECT_EQ(m->file, "plant.l");
  EXPECT_FALSE(m->enters_file);
  EXPECT_FALSE(m->system_header);
}

TEST(LineMarker, Flags) {
  std::optional<LineMarker> entering = parse_line_marker("# 1 \"/usr/include/stdio.h\" 1 3 4");
  ASSERT_TRUE(entering);
  EXPECT_EQ(entering->line, 1);
  EXPECT_TRUE(entering->enters_file);
  EXPECT_TRUE(entering->system_header);
  std::optional<LineMarker> returning = parse_line_marker("# 30 \"plant.l\" 2");
  ASSERT_TRUE(returning);
  EXPECT_FALSE(returning->enters_file);
  EXPECT_FALSE(returning->system_header);
}

TEST(LineMarker, EscapedFileName) {
  std::optional<LineMarker> m = parse_line_marker(R"(# 3 "a \"quoted\" dir\\x.v")");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->file, R"(a "quoted" dir\x.v)");
}

TEST(LineMarker, TheLineDirectiveForm) {
  std::optional<LineMarker> m = parse_line_marker("#line 7 \"view.v\"");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->line, 7);
  EXPECT_EQ(m->file, "view.v");
  EXPECT_TRUE(parse_line_marker("#  \t5 \"x\""));
}

TEST(LineMarker, BuiltInNamesAreKept) {
  std::optional<LineMarker> m = parse_line_marker("# 1 \"<command-line>\"");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->file, "<command-line>");
}

TEST(LineMarker, OtherLinesAreNotMarkers) {
  EXPECT_FALSE(parse_line_marker(""));
  EXPECT_FALSE(parse_line_marker("#pragma once"));
  EXPECT_FALSE(parse_line_marker("# F"));  // cpfg's # symbol, passed through as text
  EXPECT_FALSE(parse_line_marker("#(0.1) F"));
  EXPECT_FALSE(parse_line_marker("# 12"));             // no file
  EXPECT_FALSE(parse_line_marker("# 12 \"unclosed"));  // no closing quote
  EXPECT_FALSE(parse_line_marker("#12\"x\""));         // no space before the file
  EXPECT_FALSE(parse_line_marker("F # 12 \"x\""));
  EXPECT_FALSE(parse_line_marker("#lines 3 \"x\""));
}

TEST(LineMarker, LineNumbersPastAnyRealFileAreNotMarkers) {
  EXPECT_TRUE(parse_line_marker("# 1073741824 \"x\""));
  EXPECT_FALSE(parse_line_marker("# 1073741825 \"x\""));
  EXPECT_FALSE(parse_line_marker("# 777777777777777777777 \"x\""));
  std::optional<LineMarker> m = parse_line_marker("# 3 \"x\" 99999999999999999999 1");
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->enters_file);
  EXPECT_FALSE(m->system_header);
}

}  // namespace
}  // namespace sylva
