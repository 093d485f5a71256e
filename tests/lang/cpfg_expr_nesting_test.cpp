// cpfg's expressions and statements nested deeper than any model nests them
// (thousands of parentheses, unary operators, arguments, conditionals or
// blocks): an error where the nesting gets too deep, not a stack overflow.
// 256 levels are allowed; far fewer than that are read as before.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/cpfg_expr.h"
#include "lang/model_ir_text.h"

namespace sylva::test {
namespace {

using lang::cpfg::Cursor;
using lang::cpfg::Line;
using lang::cpfg::Scope;

const std::vector<std::string> kFiles = {"plant.l"};
const std::string kTooDeep = "nested more than 256 levels deep (parentheses, operators, arguments or blocks)";

Line line_of(const std::string& source) {
  Line line;
  line.text = source;
  for (std::size_t k = 0; k <= source.size(); ++k) line.pos.push_back({0, 1, static_cast<int>(k) + 1});
  return line;
}

std::string repeated(const std::string& part, int times) {
  std::string text;
  for (int k = 0; k < times; ++k) text += part;
  return text;
}

// The expression's C++, or the error it stops with.
std::string expression(const std::string& source) {
  const Line line = line_of(source);
  Cursor c(line, kFiles);
  Scope scope;
  scope.formals = {"x"};
  try {
    return lang::cpfg::expression(c, scope);
  } catch (const ModelError& e) {
    return e.what();
  }
}

std::string statements(const std::string& source) {
  const Line line = line_of(source);
  Cursor c(line, kFiles);
  Scope scope;
  scope.formals = {"x"};
  try {
    return lang::cpfg::statements(c, scope);
  } catch (const ModelError& e) {
    return e.what();
  }
}

std::string error_at(int column) { return "plant.l:1:" + std::to_string(column) + ": error: " + kTooDeep; }

TEST(CpfgNesting, ParenthesesNestedAsDeepAsAModelNestsThemAreRead) {
  EXPECT_EQ(expression(repeated("(", 100) + "x" + repeated(")", 100)),
            repeated("(", 100) + "v_x" + repeated(")", 100));
}

TEST(CpfgNesting, ThousandsOfParenthesesStopAtTheLevelPastTheLimit) {
  // The whole expression is level 1, each parenthesis one more: the 256th
  // parenthesis opens level 257, whose expression starts in column 257.
  EXPECT_EQ(expression(repeated("(", 2000) + "x" + repeated(")", 2000)), error_at(257));
}

TEST(CpfgNesting, ChainsOfUnaryOperatorsStop) {
  EXPECT_EQ(expression(repeated("-", 40000) + "x"), error_at(256));
  EXPECT_EQ(expression(repeated("! ", 40000) + "x"), error_at(511));
}

TEST(CpfgNesting, NestedArgumentsAndIndicesStop) {
  EXPECT_EQ(expression(repeated("sin(", 5000) + "x" + repeated(")", 5000)), error_at(1025));
  const Line line = line_of("a[" + repeated("a[", 3000) + "0" + repeated("]", 3001));
  Cursor c(line, kFiles);
  Scope scope;
  scope.arrays = {"a"};
  try {
    lang::cpfg::expression(c, scope);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), error_at(513));
  }
}

TEST(CpfgNesting, ConditionalsNestedInTheirBranchesStop) {
  // Level k's condition starts in column 8(k-1)+1 and its first branch, a
  // level deeper, 4 columns on.
  EXPECT_EQ(expression(repeated("x ? 1 : ", 5000) + "0"), error_at(8 * 255 + 5));
}

TEST(CpfgNesting, BlocksNestedInBlocksStop) {
  // Each `if (x) {` is a statement (one level) whose condition, 4 columns
  // on, is read a level deeper: the 256th statement's condition is refused.
  EXPECT_EQ(statements(repeated("if (x) { ", 3000) + repeated("} ", 3001)), error_at(9 * 255 + 5));
  const std::string hundred = statements(repeated("while (x) { ", 100) + repeated("} ", 101));
  EXPECT_EQ(hundred.find("error"), std::string::npos) << hundred;
  EXPECT_EQ(hundred.rfind("while (v_x) { while (v_x) {", 0), 0u);
}

TEST(CpfgNesting, AProductionNestedTooDeepIsAnErrorAtItsLineAndColumn) {
  const std::string model = "Lsystem: 1\n"
                            "derivation length: 1\n"
                            "axiom: A(1)\n"
                            "A(x) --> A(" + repeated("(", 1750) + "x" + repeated(")", 1750) + ")\n"
                            "endlsystem\n";
  EXPECT_EQ(parse_error(parse_cpfg_text, model).rfind("plant.l:4:", 0), 0u) << parse_error(parse_cpfg_text, model);
  EXPECT_NE(parse_error(parse_cpfg_text, model).find(kTooDeep), std::string::npos);
}

}  // namespace
}  // namespace sylva::test
