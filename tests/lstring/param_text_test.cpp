// Module parameters written by the engine from their type table: the text
// each kind of value takes (worked by hand from the format the runtime's
// compiled printers document), numbers that read back exactly, and cpfg's
// %g.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "lstring/param_text.h"
#include "lstring/param_type_constants.h"

namespace sylva::test {
namespace {

using abi::ParamField;
using abi::ParamKind;
using abi::ParamType;

// A block of parameters packed in order, with the fields that describe it.
struct Block {
  std::vector<unsigned char> bytes;
  std::vector<ParamField> fields;
  template <class T>
  Block& add(const ParamType& type, T value) {
    fields.push_back(ParamField{nullptr, static_cast<std::uint32_t>(bytes.size()), &type});
    bytes.resize(bytes.size() + sizeof value);
    std::memcpy(bytes.data() + bytes.size() - sizeof value, &value, sizeof value);
    return *this;
  }
  std::string text(NumberStyle style = NumberStyle::kExact) const {
    std::string out;
    append_params_text(fields, bytes.data(), style, out);
    return out;
  }
};

TEST(ParamText, NumbersInTheirShortestExactForm) {
  EXPECT_EQ(Block().add(kFloat, 0.1f).add(kFloat, 1.0f).add(kFloat, -2.5f).text(), "0.1,1,-2.5");
  EXPECT_EQ(Block().add(kFloat, 1.0f / 3.0f).text(), "0.33333334");
  EXPECT_EQ(Block().add(kFloat, 1e-5f).add(kFloat, 3e20f).text(), "1e-05,3e+20");
  EXPECT_EQ(Block().add(kDouble, 0.1).add(kDouble, 1.0 / 3.0).text(), "0.1,0.3333333333333333");
  EXPECT_EQ(Block().add(kInt, -42).add(kByte, std::uint8_t{200}).add(kBool, true).add(kBool, false).text(),
            "-42,200,1,0");
}

TEST(ParamText, FloatsReadBackToTheSameValue) {
  std::mt19937 random(7);
  std::uniform_int_distribution<std::uint32_t> bits;
  for (int k = 0; k < 20000; ++k) {
    std::uint32_t b = bits(random);
    float value;
    std::memcpy(&value, &b, sizeof value);
    if (!std::isfinite(value)) continue;
    const std::string text = Block().add(kFloat, value).text();
    const float back = std::strtof(text.c_str(), nullptr);
    ASSERT_EQ(std::memcmp(&back, &value, sizeof value), 0) << text;
  }
}

// Whole numbers and repeated values take shortcuts past the shortest-text
// search; the text must be what that search gives: the digits up to 99999,
// the exponent form from 100000 on where it is shorter ("1e+05" has five
// characters, "100000" six), the sign of -0, and a repeated value's text in
// either style.
TEST(ParamText, WholeAndRepeatedNumbersWriteTheSameText) {
  EXPECT_EQ(Block().add(kFloat, 60.0f).add(kFloat, -120.0f).add(kFloat, 99999.0f).text(), "60,-120,99999");
  EXPECT_EQ(Block().add(kFloat, 100000.0f).add(kFloat, 110000.0f).add(kDouble, -1e5).text(), "1e+05,110000,-1e+05");
  EXPECT_EQ(Block().add(kFloat, -0.0f).add(kFloat, 0.0f).add(kDouble, -0.0).text(), "-0,0,-0");
  EXPECT_EQ(Block().add(kFloat, 0.5f).add(kFloat, 0.5f).add(kFloat, 0.25f).add(kFloat, 0.5f).text(),
            "0.5,0.5,0.25,0.5");
  const float third = 1.0f / 3.0f;
  EXPECT_EQ(Block().add(kFloat, third).text(), "0.33333334");
  EXPECT_EQ(Block().add(kFloat, third).text(NumberStyle::kCpfg), "0.333333");
  EXPECT_EQ(Block().add(kFloat, third).text(), "0.33333334");
  EXPECT_EQ(Block().add(kDouble, 1.0 / 3.0).add(kFloat, third).text(), "0.3333333333333333,0.33333334");
}

TEST(ParamText, CpfgWritesPercentG) {
  EXPECT_EQ(Block().add(kFloat, 1.0f / 3.0f).add(kFloat, 1234567.0f).add(kFloat, 2.0f).text(NumberStyle::kCpfg),
            "0.333333,1.23457e+06,2");
}

TEST(ParamText, VectorsArraysStructsAndText) {
  const ParamType vector3{ParamKind::kVector, 12, &kFloat, 3};
  const ParamType array2{ParamKind::kArray, 8, &kInt, 2};
  const ParamField cell_fields[] = {{"a", 0, &kFloat}, {"n", 4, &kInt}};
  const ParamType cell{ParamKind::kStruct, 8, nullptr, 0, cell_fields, 2};
  struct Cell {
    float a;
    std::int32_t n;
  };
  struct Pair {
    std::int32_t x[2];
  };
  Block block;
  block.add(vector3, std::array<float, 3>{1, 0.5f, -3}).add(array2, Pair{{4, -5}}).add(cell, Cell{0.25f, 7});
  EXPECT_EQ(block.text(), "(1,0.5,-3),[4,-5],{a=0.25,n=7}");
  EXPECT_EQ(Block().add(kText, static_cast<const char*>("say \"hi\" \\ ok")).text(), "\"say \\\"hi\\\" \\\\ ok\"");
}

TEST(ParamText, UnknownLayoutAsHexBytes) {
  const ParamType other{ParamKind::kOther, 2};
  EXPECT_EQ(Block().add(other, std::uint16_t{0xab01}).text(), "#01ab");
}

TEST(ParamText, WhatTheTableCannotWrite) {
  const ParamField unlocated[] = {{"bits", 0, nullptr}};
  const ParamType with_bit_field{ParamKind::kStruct, 4, nullptr, 0, unlocated, 1};
  const ParamType unknown_struct{ParamKind::kStruct, 4};
  EXPECT_TRUE(params_text_from_table(Block().add(kFloat, 1.0f).add(kText, "x").fields, NumberStyle::kExact));
  EXPECT_FALSE(params_text_from_table(Block().add(with_bit_field, 0).fields, NumberStyle::kExact));
  EXPECT_FALSE(params_text_from_table(Block().add(unknown_struct, 0).fields, NumberStyle::kExact));
  // cpfg quotes a label's text with escapes of its own.
  EXPECT_FALSE(params_text_from_table(Block().add(kText, "x").fields, NumberStyle::kCpfg));
}

}  // namespace
}  // namespace sylva::test
