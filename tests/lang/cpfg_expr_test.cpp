// cpfg's expressions and statements (CPFG manual 3.2, 5) to C++ text. The
// expected text is worked out from the translation's rules: numbers as
// doubles, variables as v_<name>, every binary operation parenthesized, ^ as
// a power, % as fmod, functions by their helper with double arguments.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/cpfg_expr.h"

namespace sylva::test {
namespace {

using lang::cpfg::Cursor;
using lang::cpfg::Line;
using lang::cpfg::Scope;

// One line of plant.l holding `source`.
Line line_of(const std::string& source) {
  Line line;
  line.text = source;
  for (std::size_t k = 0; k <= source.size(); ++k) line.pos.push_back({0, 1, static_cast<int>(k) + 1});
  return line;
}

const std::vector<std::string> kFiles = {"plant.l"};

// x and y are the predecessor's formals.
Scope formals_x_y(std::vector<std::string>* warnings = nullptr) {
  Scope scope;
  scope.formals = {"x", "y"};
  scope.warnings = warnings;
  return scope;
}

std::string translate(const std::string& source) {
  const Line line = line_of(source);
  Cursor c(line, kFiles);
  Scope scope = formals_x_y();
  return lang::cpfg::expression(c, scope);
}

struct Translation {
  const char* cpfg;
  const char* cpp;
};
void PrintTo(const Translation& t, std::ostream* os) { *os << '"' << t.cpfg << '"'; }

class CpfgExpression : public ::testing::TestWithParam<Translation> {};

TEST_P(CpfgExpression, TranslatesTo) { EXPECT_EQ(translate(GetParam().cpfg), GetParam().cpp); }

INSTANTIATE_TEST_SUITE_P(
    Table, CpfgExpression,
    ::testing::Values(Translation{"1", "1.0"}, Translation{".5", "0.5"}, Translation{"2.", "2.0"},
                      Translation{"1.5f", "1.5"}, Translation{"1e3", "1e3"}, Translation{"(x)", "(v_x)"},
                      Translation{"x+1", "(v_x + 1.0)"}, Translation{"x*y+1", "((v_x * v_y) + 1.0)"},
                      Translation{"x-y-1", "((v_x - v_y) - 1.0)"},
                      Translation{"x^2^3", "::sylva::rt::cpfg::pow(::sylva::rt::cpfg::pow(v_x, 2.0), 3.0)"},
                      Translation{"2*x^2", "(2.0 * ::sylva::rt::cpfg::pow(v_x, 2.0))"},
                      Translation{"-x*2", "((-v_x) * 2.0)"}, Translation{"x%2", "::std::fmod(v_x, 2.0)"},
                      Translation{"x<1 && y>=2 || !x", "(((v_x < 1.0) && (v_y >= 2.0)) || (!v_x))"},
                      Translation{"x==1 ? 2 : 3", "(((v_x == 1.0)) ? (double)(2.0) : (double)(3.0))"},
                      Translation{"sin(x)", "::sylva::rt::cpfg::sin((double)(v_x))"},
                      Translation{"atan(y, x)", "::sylva::rt::cpfg::atan((double)(v_y), (double)(v_x))"},
                      Translation{"ran(1)", "::sylva::rt::cpfg::ran((double)(1.0))"},
                      Translation{"sqrt(x)", "::std::sqrt((double)(v_x))"},
                      Translation{"x > 1 -->", "(v_x > 1.0)"}));  // stops at the arrow

TEST(CpfgExpression, AnUnknownNameReadsAsANewVariableWithAWarning) {
  std::vector<std::string> warnings;
  const Line line = line_of("x + z");
  Cursor c(line, kFiles);
  Scope scope = formals_x_y(&warnings);
  EXPECT_EQ(lang::cpfg::expression(c, scope), "(v_x + v_z)");
  EXPECT_EQ(warnings, std::vector<std::string>{"plant.l:1:5: warning: unknown variable 'z' read as 0 (as cpfg does)"});
  EXPECT_EQ(scope.locals.count("z"), 1u);
}

TEST(CpfgExpression, StatementsUpToTheClosingBrace) {
  const Line line = line_of("t = x * 2; if (t > 1) { t = 1; } } rest");
  Cursor c(line, kFiles);
  Scope scope = formals_x_y();
  EXPECT_EQ(lang::cpfg::statements(c, scope), "v_t = (v_x * 2.0); if ((v_t > 1.0)) { v_t = 1.0;  } ");
  EXPECT_EQ(scope.locals.count("t"), 1u);  // assigned in a production: a local
  EXPECT_EQ(line.text.substr(c.at()), " rest");  // the closing brace is read, no more
}

TEST(CpfgExpression, ErrorsPointIntoTheLine) {
  auto error = [](const std::string& source) -> std::string {
    try {
      translate(source);
    } catch (const ModelError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error("sin(x, y)"), "plant.l:1:1: error: sin takes 1 argument(s), not 2");
  EXPECT_EQ(error("x + )"), "plant.l:1:5: error: expected an expression, found ')'");
  EXPECT_EQ(error("(x + 1"), "plant.l:1:7: error: expected ')', found the end of the line");
}

}  // namespace
}  // namespace sylva::test
