// Modules whose arguments are literals are encoded by the translator: the
// bytes must be those the compiled put_module call writes, and anything the
// translator cannot convert exactly as the compiler does stays code.
#include <gtest/gtest.h>

#include <cstring>

#include "lang/constant_modules.h"
#include "sylva/runtime/modules.h"

namespace sylva::test {
namespace {

using namespace sylva::lang;

Token token(TokenKind kind, const std::string& text) {
  Token t;
  t.kind = kind;
  t.text = text;
  return t;
}

// An argument as the L+C lexer splits it: numbers, names and punctuation.
Code lc(const std::vector<std::string>& texts) {
  Code code;
  for (const std::string& text : texts) {
    const char c = text[0];
    const TokenKind kind = std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && text.size() > 1)
                               ? TokenKind::Number
                           : std::isalpha(static_cast<unsigned char>(c)) || c == '_' ? TokenKind::Identifier
                                                                                      : TokenKind::Punct;
    code.push_back(token(kind, text));
  }
  return code;
}

// An argument as the cpfg front end writes it: one token of C++ text.
Code cpfg(const std::string& text) { return Code{token(TokenKind::Identifier, text)}; }

// The encoding sylva/abi.h states: an id below 255 is one byte; a wider one
// is 0xFF and its two bytes (low first) at a module's start, its two bytes
// and 0xFF at its end, and 0xFF, the two bytes, 0xFF without parameters.
template <class... T>
std::string expected_bytes(abi::ModuleId id, T... values) {
  const std::string low_high{static_cast<char>(id & 0xFF), static_cast<char>(id >> 8)};
  const bool wide = id >= 255;
  std::string bytes = wide ? "\xFF" + low_high : std::string(1, static_cast<char>(id));
  if constexpr (sizeof...(T) > 0) {
    ((bytes.append(reinterpret_cast<const char*>(&values), sizeof values)), ...);
    bytes += wide ? low_high + "\xFF" : std::string(1, static_cast<char>(id));
  } else if (wide) {
    bytes += "\xFF";
  }
  return bytes;
}

// What the compiled call writes.
template <class... T>
std::string put_module_bytes(abi::ModuleId id, T... values) {
  std::string bytes(rt::module_bytes<T...>, '\0');  // room for the widest id
  unsigned char* at = reinterpret_cast<unsigned char*>(bytes.data());
  rt::put_module<T...>(at, id, values...);
  const auto written = static_cast<std::size_t>(at - reinterpret_cast<unsigned char*>(bytes.data()));
  EXPECT_LE(written, bytes.size());
  bytes.resize(written);
  return bytes;
}

std::optional<std::string> one(const std::string& type, const Code& arg) {
  return constant_module_bytes(7, {type}, {arg});
}

TEST(ConstantModules, AModuleWithoutParametersIsItsIdAlone) {
  EXPECT_EQ(constant_module_bytes(9, {}, {}), std::string("\x09"));
  EXPECT_EQ(constant_module_bytes(300, {}, {}), std::string("\xFF\x2C\x01\xFF"));
  EXPECT_EQ(constant_module_bytes(254, {}, {}), expected_bytes(254));
}

TEST(ConstantModules, AWideIdFramesTheParameters) {
  EXPECT_EQ(constant_module_bytes(300, {"int"}, {lc({"5"})}), std::string("\xFF\x2C\x01\x05\0\0\0\x2C\x01\xFF", 10));
  EXPECT_EQ(constant_module_bytes(300, {"int"}, {lc({"5"})}), expected_bytes(300, 5));
}

TEST(ConstantModules, TheBytesAreThosePutModuleWrites) {
  EXPECT_EQ(constant_module_bytes(300, {}, {}), put_module_bytes(300));
  EXPECT_EQ(constant_module_bytes(9, {"float", "int"}, {lc({"1"}), lc({"2"})}), put_module_bytes(9, 1.0f, 2));
  EXPECT_EQ(constant_module_bytes(511, {"float", "int"}, {lc({"1"}), lc({"2"})}), put_module_bytes(511, 1.0f, 2));
}

// A struct parameter is copied a word at a time (rt::put_param): what it
// writes is still the struct's bytes, between the ids, beside other parameters.
struct Cell {
  float a, h, x;
  int age, pol;
};
struct Wide {
  double d;
  int k, m;
};

TEST(ConstantModules, PutModuleWritesAStructAsItsBytes) {
  const Cell cell{0.5f, 1.25f, -3.0f, 7, 1};
  const Wide wide{2.5, -4, 9};
  EXPECT_EQ(put_module_bytes(12, cell), expected_bytes(12, cell));
  EXPECT_EQ(put_module_bytes(300, cell, 2.0f), expected_bytes(300, cell, 2.0f));
  EXPECT_EQ(put_module_bytes(12, 1, wide, cell), expected_bytes(12, 1, wide, cell));
}

TEST(ConstantModules, LiteralsConvertAsAnArgumentWould) {
  EXPECT_EQ(one("float", lc({"1.5"})), expected_bytes(7, 1.5f));
  EXPECT_EQ(one("float", lc({"0.1"})), expected_bytes(7, static_cast<float>(0.1)));
  EXPECT_EQ(one("float", lc({"0.1f"})), expected_bytes(7, 0.1f));
  EXPECT_EQ(one("float", lc({"16777217"})), expected_bytes(7, static_cast<float>(16777217)));
  EXPECT_EQ(one("double", lc({"0.1"})), expected_bytes(7, 0.1));
  EXPECT_EQ(one("double", lc({"0.1f"})), expected_bytes(7, static_cast<double>(0.1f)));
  EXPECT_EQ(one("double", lc({"1e-3"})), expected_bytes(7, 1e-3));
  EXPECT_EQ(one("double", lc({".5"})), expected_bytes(7, .5));
  EXPECT_EQ(one("double", lc({"2."})), expected_bytes(7, 2.));
  EXPECT_EQ(one("int", lc({"-", "2.7"})), expected_bytes(7, -2));
  EXPECT_EQ(one("int", lc({"3000000000"})), expected_bytes(7, static_cast<int>(3000000000LL)));
  EXPECT_EQ(one("unsigned int", lc({"-", "1"})), expected_bytes(7, static_cast<unsigned>(-1)));
  EXPECT_EQ(one("char", lc({"65"})), expected_bytes(7, 'A'));
  EXPECT_EQ(one("bool", lc({"0.5"})), expected_bytes(7, true));
  EXPECT_EQ(one("bool", lc({"0"})), expected_bytes(7, false));
  EXPECT_EQ(one("long", lc({"-", "(", "-", "9", ")"})), expected_bytes(7, 9L));
  EXPECT_EQ(constant_module_bytes(9, {"float", "int"}, {lc({"1"}), lc({"2"})}), expected_bytes(9, 1.0f, 2));
}

TEST(ConstantModules, CpfgConstantsAreCastToFloat) {
  EXPECT_EQ(one("float", cpfg("static_cast<float>(1.0)")), expected_bytes(7, 1.0f));
  EXPECT_EQ(one("float", cpfg("static_cast<float>((-30.0))")), expected_bytes(7, -30.0f));
  EXPECT_EQ(one("double", cpfg("static_cast<float>(0.1)")), expected_bytes(7, static_cast<double>(0.1f)));
}

TEST(ConstantModules, AnythingElseStaysCode) {
  EXPECT_FALSE(one("float", lc({"x"})));
  EXPECT_FALSE(one("float", lc({"1", "+", "2"})));
  EXPECT_FALSE(one("float", lc({"--", "1"})));
  EXPECT_FALSE(one("float", lc({"(", "1"})));
  EXPECT_FALSE(one("float", lc({"1", ")"})));
  EXPECT_FALSE(one("float", lc({"0x10"})));
  EXPECT_FALSE(one("float", lc({"010"})));
  EXPECT_FALSE(one("float", lc({"1u"})));
  EXPECT_FALSE(one("float", lc({"1.5L"})));
  EXPECT_FALSE(one("float", lc({"1'000"})));
  EXPECT_FALSE(one("float", lc({"1e400"})));
  EXPECT_FALSE(one("float", lc({"1e300"})));                  // past float's range
  EXPECT_FALSE(one("int", lc({"1e10"})));                     // past int's range
  EXPECT_FALSE(one("unsigned", lc({"-", "1.5"})));            // negative to unsigned
  EXPECT_FALSE(one("float", lc({"99999999999999999999"})));  // past long
  EXPECT_FALSE(one("float", Code{token(TokenKind::String, "\"1\"")}));
  EXPECT_FALSE(one("float", cpfg("static_cast<float>(x)")));
  EXPECT_FALSE(one("float", lc({"static_cast", "<", "float", ">", "(", "1", ")"})));
  EXPECT_FALSE(one("Real", lc({"1"})));  // a typedef, or a class
  EXPECT_FALSE(one("long double", lc({"1"})));
  EXPECT_FALSE(constant_module_bytes(7, {"float"}, {}));  // the compiler reports the count
  EXPECT_FALSE(constant_module_bytes(7, {}, {lc({"1"})}));
}

TEST(ConstantModules, DeepSignsAndParenthesesAreReadWithoutRecursion) {
  std::string deep;
  for (int k = 0; k < 100000; ++k) deep += "- (";
  deep += "1";
  for (int k = 0; k < 100000; ++k) deep += ")";
  EXPECT_EQ(one("int", cpfg(deep)), expected_bytes(7, 1));
}

TEST(ConstantModules, BytesLiteralKeepsEveryByte) {
  EXPECT_EQ(bytes_literal(std::string("A\0\"\\?\x7f\xff" "1", 8)), "\"A\\000\\042\\134\\077\\177\\3771\"");
}

}  // namespace
}  // namespace sylva::test
