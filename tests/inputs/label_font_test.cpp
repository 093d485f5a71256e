// The labels' font from the view file's font names.
#include "inputs/label_font.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

// lpfg's and cpfg's reading of an X font name (field 2 the family, 3 the
// weight, 4 the slant, 7 or else 6 the size).
TEST(LabelFont, FromAnXFontName) {
  geometry::LabelFont f = io::parse_x_font("-*-courier-bold-r-*-*-12-*-*-*-*-*-*-*");
  EXPECT_EQ(f.family, "courier");
  EXPECT_TRUE(f.bold);
  EXPECT_FALSE(f.italic);
  EXPECT_EQ(f.points, 12);
  geometry::LabelFont g = io::parse_x_font("-adobe-new_century_schoolbook-medium-italic-normal--*-240-*-*-*-*-*-*");
  EXPECT_EQ(g.family, "new century schoolbook");
  EXPECT_FALSE(g.bold);
  EXPECT_TRUE(g.italic);
  EXPECT_EQ(g.points, 12);  // fields 7 and 6 are '*': the default size
  geometry::LabelFont h = io::parse_x_font("fixed");
  EXPECT_EQ(h.family, "Times");
}

}  // namespace
}  // namespace sylva
