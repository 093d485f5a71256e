// Module parameters read back by the engine from their type table: what the
// writer writes reads back to the same bytes; bad text fails where, and with
// the words, that the readers compiled into models use (checked against
// sylva/runtime/parse_params.h on the same texts, and worked by hand for
// structs, whose compiled readers the translator writes).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "lstring/param_text.h"
#include "lstring/param_type_constants.h"
#include "sylva/runtime/modules.h"

namespace sylva::test {
namespace {

using abi::ParamField;
using abi::ParamKind;
using abi::ParamType;

const ParamType kShort{ParamKind::kSigned, 2};
const ParamType kVector3{ParamKind::kVector, 12, &kFloat, 3};
const ParamType kEnum{ParamKind::kEnum, 4, &kInt};

// struct Cell { float a; int n; };  struct Pod { V3f at; Cell cell; short id[2]; };
struct Cell {
  float a;
  std::int32_t n;
};
struct Pod {
  std::array<float, 3> at;
  Cell cell;
  std::int16_t id[2];
};
const ParamField kCellFields[] = {{"a", 0, &kFloat}, {"n", 4, &kInt}};
const ParamType kCell{ParamKind::kStruct, 8, nullptr, 0, kCellFields, 2, "Cell"};
const ParamType kShorts{ParamKind::kArray, 4, &kShort, 2};
const ParamField kPodFields[] = {{"at", 0, &kVector3}, {"cell", 12, &kCell}, {"id", 20, &kShorts}};
const ParamType kPod{ParamKind::kStruct, sizeof(Pod), nullptr, 0, kPodFields, 3, "Pod"};

// Parameters packed in order, as a module's block.
std::vector<ParamField> packed(std::initializer_list<const ParamType*> types) {
  std::vector<ParamField> fields;
  std::uint32_t offset = 0;
  for (const ParamType* type : types) {
    fields.push_back(ParamField{nullptr, offset, type});
    offset += type->size;
  }
  return fields;
}
std::size_t block_size(const std::vector<ParamField>& fields) {
  return fields.empty() ? 0 : fields.back().offset + fields.back().type->size;
}

struct Reading {
  bool ok;
  std::size_t at;  // where the reader stopped
  std::string expected;
  std::vector<unsigned char> block;
};
Reading read(const std::vector<ParamField>& fields, const std::string& text) {
  Reading r{false, 0, "", std::vector<unsigned char>(block_size(fields), 0)};
  abi::TextSource in{text.c_str(), text.c_str() + text.size()};
  r.ok = read_params_text(fields, &in, r.block.data());
  r.at = static_cast<std::size_t>(in.at - text.c_str());
  r.expected = in.expected ? in.expected : "";
  return r;
}

TEST(ParamTextReader, WhatTheWriterWritesReadsBackToTheSameBytes) {
  const std::vector<ParamField> fields = packed({&kFloat, &kDouble, &kInt, &kByte, &kBool, &kEnum, &kPod});
  std::vector<unsigned char> block(block_size(fields));
  auto put = [&](std::size_t k, const auto& value) { std::memcpy(block.data() + fields[k].offset, &value, sizeof value); };
  put(0, 1.0f / 3.0f);
  put(1, -1e-300);
  put(2, std::int32_t{-2147483647 - 1});
  put(3, std::uint8_t{255});
  put(4, true);
  put(5, std::int32_t{7});
  put(6, Pod{{1.5f, -0.0f, 3e38f}, {0.1f, 42}, {-32768, 32767}});
  std::string text;
  append_params_text(fields, block.data(), NumberStyle::kExact, text);
  const Reading back = read(fields, text);
  ASSERT_TRUE(back.ok) << text << ": " << back.expected;
  EXPECT_EQ(back.at, text.size());
  EXPECT_EQ(back.block, block) << text;
}

TEST(ParamTextReader, FieldsByNameInAnyOrderAndSpaces) {
  const std::vector<ParamField> fields = packed({&kCell, &kFloat});
  const Reading r = read(fields, " { n = -3 ,\ta=0.5 } ,\n2");
  ASSERT_TRUE(r.ok) << r.expected;
  Cell cell;
  std::memcpy(&cell, r.block.data(), sizeof cell);
  EXPECT_EQ(cell.a, 0.5f);
  EXPECT_EQ(cell.n, -3);
  float second;
  std::memcpy(&second, r.block.data() + 8, sizeof second);
  EXPECT_EQ(second, 2.0f);
}

// Where each text fails and why; offsets counted by hand.
TEST(ParamTextReader, AStructGivesEachFieldOnce) {
  struct Case {
    const ParamType* type;
    std::string text;
    std::size_t at;
    std::string expected;
  };
  const Case cases[] = {
      {&kCell, "{a=1,a=2}", 5, "field 'a' only once"},
      {&kCell, "{a=1}", 4, "field 'n' (a saved struct gives all its fields)"},
      {&kCell, "{}", 1, "field 'a' (a saved struct gives all its fields)"},
      {&kCell, "{a=1,b=2}", 5, "a field of Cell"},
      {&kPod, "{at=(0,0,0),id=[1,2],cell={a=1,m=2}}", 31, "a field of Cell"},
      {&kCell, "{a 1}", 3, "'=' after the field name"},
      {&kCell, "{=1}", 1, "a field name"},
      {&kCell, "(a=1)", 0, "'{' to begin a struct"},
      {&kCell, "{a=1,n=2", 8, "'}' to end the struct"},
  };
  for (const Case& c : cases) {
    const Reading r = read(packed({c.type}), c.text);
    EXPECT_FALSE(r.ok) << c.text;
    EXPECT_EQ(r.at, c.at) << c.text;
    EXPECT_EQ(r.expected, c.expected) << c.text;
  }
}

TEST(ParamTextReader, TextAndUnknownLayouts) {
  EXPECT_EQ(read(packed({&kText}), "\"x\"").expected, "a value that can be read back (a pointer cannot)");
  const ParamType other{ParamKind::kOther, 2};
  const Reading r = read(packed({&other}), "#01ab");
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.block, (std::vector<unsigned char>{0x01, 0xab}));
  EXPECT_EQ(read(packed({&other}), "#01a").expected, "two hexadecimal digits per byte of the value");
  EXPECT_EQ(read(packed({&other}), "01ab").expected, "'#' and the bytes of the value");
}

// The same texts through the compiled reader of parameters
// (float, int, bool, V3f, unsigned char, short): the same success, the same
// bytes, the same place and words on failure.
TEST(ParamTextReader, AgreesWithTheCompiledReader) {
  const std::vector<ParamField> fields = packed({&kFloat, &kInt, &kBool, &kVector3, &kByte, &kShort});
  const std::string texts[] = {
      "1.5,-7,1,(1,2,3),200,-300",  " 0.1 , 2147483647 , 0 , ( -1 , 0.5 , 1e3 ) , 0 , 32767 ",
      "x,1,1,(1,2,3),1,1",          "1,2147483648,1,(1,2,3),1,1",
      "1,1,2,(1,2,3),1,1",          "1,1,1,[1,2,3],1,1",
      "1,1,1,(1,2),1,1",            "1,1,1,(1,2,3,4),1,1",
      "1,1,1,(1,2,3),-1,1",         "1,1,1,(1,2,3),256,1",
      "1,1,1,(1,2,3),1,-32769",     "1,1,1,(1,2,3),1",
      "1;1,1,(1,2,3),1,1",          "1e,1,1,(1,2,3),1,1",
  };
  for (const std::string& text : texts) {
    const Reading table = read(fields, text);
    std::vector<unsigned char> compiled_block(block_size(fields), 0);
    abi::TextSource in{text.c_str(), text.c_str() + text.size()};
    const bool compiled_ok = rt::parse_params<float, int, bool, V3f, unsigned char, short>(&in, compiled_block.data());
    EXPECT_EQ(table.ok, compiled_ok) << text;
    EXPECT_EQ(table.at, static_cast<std::size_t>(in.at - text.c_str())) << text;
    EXPECT_EQ(table.expected, in.expected ? in.expected : "") << text;
    if (compiled_ok) {
      EXPECT_EQ(table.block, compiled_block) << text;
    }
  }
}

}  // namespace
}  // namespace sylva::test
