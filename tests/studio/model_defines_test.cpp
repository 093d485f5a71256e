// A model's numeric #defines as sliders: which are found, and the ranges
// proposed for them.
#include <gtest/gtest.h>

#include "studio/model_defines.h"

namespace sylva::studio {
namespace {

const char* const kSource =
    "/* #define IN_COMMENT 5\n"                       // 1
    "   #define STILL_IN_COMMENT 6 */\n"              // 2
    "#ifndef PLANT_H\n"                               // 3
    "#define PLANT_H\n"                               // 4
    "#define STEPS 10          // derivation length\n"  // 5
    "#define ANGLE 22.5\r\n"                          // 6
    "  #define TROPISM -3 /* downwards */\n"          // 7
    "#define RATE 2e-3\n"                             // 8
    "#define WIDTH 1.5f\n"                            // 9
    "#define MAX(a,b) ((a)>(b)?(a):(b))\n"            // 10
    "#define SUM 1 + 2\n"                             // 11
    "# define SPACED 4\n"                             // 12
    "#if 0\n"                                         // 13
    "#define DISABLED 7\n"                            // 14
    "#if X\n"                                         // 15
    "#define NESTED 8\n"                              // 16
    "#endif\n"                                        // 17
    "#define STILL_DISABLED 9\n"                      // 18
    "#else\n"                                         // 19
    "#define ENABLED 11\n"                            // 20
    "#endif\n"                                        // 21
    "#define PI 3.14159265\n"                         // 22
    "#define DEG_TO_RAD 0.0174533\n"                  // 23
    "#define _INTERNAL 5\n"                           // 24
    "#define STEPS 20\n"                              // 25
    "// #define LINE_COMMENT 1\n"                     // 26
    "const char* s = \"/*\";\n"                       // 27
    "#define HEX 0x1F\n"                              // 28
    "#define NAME Leaf\n"                             // 29
    "#endif";                                         // 30

TEST(ModelDefines, FindsTheNumericDefinesAUserWouldMove) {
  const std::vector<ModelDefine> defines = find_model_defines(kSource);
  std::vector<std::string> names;
  for (const ModelDefine& d : defines) names.push_back(d.name);
  EXPECT_EQ(names, (std::vector<std::string>{"STEPS", "ANGLE", "TROPISM", "RATE", "WIDTH", "ENABLED", "HEX"}));
  ASSERT_EQ(defines.size(), 7u);

  EXPECT_EQ(defines[0].value_text, "10");
  EXPECT_EQ(defines[0].value, 10);
  EXPECT_TRUE(defines[0].integral);
  EXPECT_EQ(defines[0].line, 5);

  EXPECT_EQ(defines[1].value_text, "22.5");
  EXPECT_EQ(defines[1].value, 22.5);
  EXPECT_FALSE(defines[1].integral);
  EXPECT_EQ(defines[1].line, 6);

  EXPECT_EQ(defines[2].value, -3);
  EXPECT_TRUE(defines[2].integral);
  EXPECT_EQ(defines[2].line, 7);

  EXPECT_EQ(defines[3].value, 0.002);
  EXPECT_FALSE(defines[3].integral);

  EXPECT_EQ(defines[4].value_text, "1.5f");
  EXPECT_EQ(defines[4].value, 1.5);
  EXPECT_FALSE(defines[4].integral);

  EXPECT_EQ(defines[5].line, 20);
  EXPECT_EQ(defines[6].value, 31);
  EXPECT_TRUE(defines[6].integral);
  EXPECT_EQ(defines[6].line, 28);

  // Each comes with its proposed range.
  EXPECT_EQ(defines[0].range.max, 20);
  EXPECT_EQ(defines[1].range.step, 0.1);
}

void expect_range(double value, bool integral, double min, double max, double step) {
  const SliderRange range = propose_slider_range(value, integral);
  EXPECT_DOUBLE_EQ(range.min, min) << value;
  EXPECT_DOUBLE_EQ(range.max, max) << value;
  EXPECT_DOUBLE_EQ(range.step, step) << value;
}

TEST(ModelDefines, ProposedRangesFollowTheValue) {
  expect_range(10, true, 0, 20, 1);
  expect_range(3, true, 0, 10, 1);
  expect_range(0, true, 0, 10, 1);
  expect_range(-3, true, -10, 10, 1);
  expect_range(-30, true, -60, 60, 1);

  expect_range(1.5, false, 0, 3, 0.01);
  expect_range(22.5, false, 0, 45, 0.1);
  expect_range(0.15, false, 0, 0.3, 0.001);
  expect_range(0.002, false, 0, 0.004, 0.00001);
  expect_range(137.51, false, 0, 275.02, 0.01);  // fine enough to stand on 137.51
  expect_range(-0.125, false, -0.25, 0.25, 0.001);
  expect_range(1, false, 0, 2, 0.01);
  expect_range(-3, false, -6, 6, 0.01);
  expect_range(0, false, 0, 1, 0.01);
}

TEST(ModelDefines, NewValuesKeepTheKindOfLiteral) {
  const std::vector<ModelDefine> defines = find_model_defines(kSource);
  EXPECT_EQ(define_value_text(defines[0], 12.4), "12");   // STEPS
  EXPECT_EQ(define_value_text(defines[1], 30), "30.0");   // ANGLE
  EXPECT_EQ(define_value_text(defines[1], 0.25), "0.25");
  EXPECT_EQ(define_value_text(defines[4], 2), "2.0f");    // WIDTH 1.5f
  EXPECT_EQ(define_value_text(defines[4], 2.25), "2.25f");
}

}  // namespace
}  // namespace sylva::studio
