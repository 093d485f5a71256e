// Numbers a model writes out where a whole number is expected: one out of
// range is an error at its line and column, not a wrapped value or a bare
// "stoi" from deep inside the reader.
#include <gtest/gtest.h>

#include <climits>
#include <string>

#include "lang/literal_numbers.h"
#include "lang/model_ir.h"
#include "lang/model_ir_text.h"

namespace sylva::test {
namespace {

const std::string kLcHead = "module A;\naxiom: A;\n";

TEST(NumbersInRange, WholeNumbersAsCxxWritesThem) {
  EXPECT_EQ(lang::nonnegative_int("0"), 0);
  EXPECT_EQ(lang::nonnegative_int("2147483647"), INT_MAX);
  EXPECT_EQ(lang::nonnegative_int("0x10"), 16);
  EXPECT_EQ(lang::nonnegative_int("010"), 8);
  EXPECT_EQ(lang::nonnegative_int("7u"), 7);
  EXPECT_EQ(lang::nonnegative_int("2147483648"), std::nullopt);
  EXPECT_EQ(lang::nonnegative_int("99999999999999999999999"), std::nullopt);
  EXPECT_EQ(lang::nonnegative_int("1.5"), std::nullopt);
  EXPECT_EQ(lang::nonnegative_int("x"), std::nullopt);
}

TEST(NumbersInRange, SettingsWrittenAsNumbers) {
  using lang::Setting;
  EXPECT_EQ(lang::setting_range_error(Setting::kDerivationLength, "2147483647"), "");
  EXPECT_EQ(lang::setting_range_error(Setting::kDerivationLength, "N"), "");  // computed: checked when read
  EXPECT_EQ(lang::setting_range_error(Setting::kDecompositionDepth, "0"), "");
  EXPECT_EQ(lang::setting_range_error(Setting::kDerivationLength, "2147483648"),
            "the derivation length 2147483648 is too large (at most 2147483647)");
  EXPECT_EQ(lang::setting_range_error(Setting::kDerivationLength, "( 4294967298 )"),
            "the derivation length ( 4294967298 ) is too large (at most 2147483647)");
  EXPECT_EQ(lang::setting_range_error(Setting::kDecompositionDepth, "- 1"),
            "the maximum depth - 1 is out of range (0 to 2147483647)");
  EXPECT_EQ(lang::setting_range_error(Setting::kInterpretationDepth, "-(3)"),
            "the maximum depth -(3) is out of range (0 to 2147483647)");
}

TEST(NumbersInRange, LcGroupsViewsAndSettings) {
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "group 99999999999:\nendgroup\n"),
            "model.l:3:7: error: expected a group number from 0 to 2147483647, found 99999999999");
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "ggroup 4294967296:\nendgroup\n"),
            "model.l:3:8: error: expected a group number from 0 to 2147483647, found 4294967296");
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "interpretation:\nvgroup 3000000000:\nendgroup\n"),
            "model.l:4:8: error: expected a view number from 0 to 2147483647, found 3000000000");
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "derivation length: 2147483648;\n"),
            "model.l:3:20: error: the derivation length 2147483648 is too large (at most 2147483647)");
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "derivation length: 4294967298;\n"),
            "model.l:3:20: error: the derivation length 4294967298 is too large (at most 2147483647)");
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "decomposition:\nmaximum depth: -1;\n"),
            "model.l:4:16: error: the maximum depth -1 is out of range (0 to 2147483647)");
  EXPECT_EQ(parse_error(parse_lc_text, kLcHead + "derivation length: 2147483647;\ngroup 2147483647:\nendgroup\n"
                                              "decomposition:\nmaximum depth: 0;\n"),
            "no error");
}

TEST(NumbersInRange, CpfgLabelsAndSettings) {
  EXPECT_EQ(parse_error(parse_cpfg_text, "Lsystem: 99999999999\naxiom: A\nendlsystem\n"),
            "plant.l:1:10: error: the L-system label 99999999999 is too large (at most 2147483647)");
  EXPECT_EQ(parse_error(parse_cpfg_text, "Lsystem: 1\nderivation length: 2147483648\naxiom: A\nendlsystem\n"),
            "plant.l:2:20: error: the derivation length 2147483648 is too large (at most 2147483647)");
  EXPECT_EQ(parse_error(parse_cpfg_text, "Lsystem: 1\naxiom: A\ndecomposition\nmaximum depth: -2\nendlsystem\n"),
            "plant.l:4:16: error: the maximum depth -2 is out of range (0 to 2147483647)");
  EXPECT_EQ(parse_error(parse_cpfg_text, "Lsystem: 1\nseed: 99999999999\naxiom: A\nendlsystem\n"),
            "plant.l:2:7: error: the seed 99999999999 is too large (at most 2147483647)");
  EXPECT_EQ(parse_error(parse_cpfg_text, "Lsystem: 1\nderivation length: 2147483647\naxiom: A\nendlsystem\n"), "no error");
}

}  // namespace
}  // namespace sylva::test
