// The differential L-system sections of L+C (docs/continuous-time.md):
// derivative rules with `d(p) = ...;`, events with `when (condition)`, the
// margins the engine locates events with, and the errors at file:line:column.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/event_margin.h"
#include "lang/model_ir.h"
#include "lang/model_ir_text.h"

namespace sylva::test {
namespace {

using lang::BodyPart;
using lang::Model;
using lang::Rule;

TEST(DifferentialRules, RatesNameTheirParametersByIndex) {
  const Model m = parse_lc_text(
      "module A(double, double);\n"
      "derivatives:\n"
      "A(x, y) : { d(y) = -x; d(x) = y; }\n");
  const std::vector<const Rule*> rules = items_of<Rule>(m);
  ASSERT_EQ(rules.size(), 1u);
  EXPECT_EQ(rules[0]->kind, abi::RuleKind::Derivative);
  std::vector<std::pair<std::string, int>> rates;
  for (const BodyPart& part : rules[0]->body)
    if (part.kind == BodyPart::kRate) rates.emplace_back(part.rate_of, part.rate_index);
  EXPECT_EQ(rates, (std::vector<std::pair<std::string, int>>{{"y", 1}, {"x", 0}}));
}

TEST(DifferentialRules, EventsKeepTheirCondition) {
  const Model m = parse_lc_text(
      "module A(double);\nmodule B;\n"
      "events:\n"
      "A(x) : when (x >= 2 * (1 + 1)) { produce B; }\n");
  const std::vector<const Rule*> rules = items_of<Rule>(m);
  ASSERT_EQ(rules.size(), 1u);
  EXPECT_EQ(rules[0]->kind, abi::RuleKind::Event);
  EXPECT_EQ(text(rules[0]->event_condition), "x >= 2 * ( 1 + 1 )");
}

// The margin of each condition, worked out from the rules in event_margin.h.
std::string margin_of(const std::string& condition) {
  const Model m = parse_lc_text("module A(double, double);\nevents:\nA(x, c) : when (" + condition +
                                ") { produce A(x, c); }\n");
  const Rule& rule = *items_of<Rule>(m).at(0);
  return lang::margin_text(rule.event_condition, lang::event_margin(rule.event_condition));
}

TEST(DifferentialRules, MarginsCrossZeroWhereTheConditionStartsToHold) {
  // Operands are compared as doubles, whatever their types.
  auto diff = [](const std::string& a, const std::string& b) {
    return "(static_cast<double>(" + a + ") - static_cast<double>(" + b + "))";
  };
  auto wide = [](const std::string& m) { return "static_cast<double>(" + m + ")"; };
  EXPECT_EQ(margin_of("x >= 1"), diff("x", "1"));
  EXPECT_EQ(margin_of("x > 1"), diff("x", "1"));
  EXPECT_EQ(margin_of("x <= c"), diff("c", "x"));
  EXPECT_EQ(margin_of("x > 1 && c < 5"), "::std::min(" + wide(diff("x", "1")) + ", " + wide(diff("5", "c")) + ")");
  EXPECT_EQ(margin_of("x > 1 || c < 5"), "::std::max(" + wide(diff("x", "1")) + ", " + wide(diff("5", "c")) + ")");
  EXPECT_EQ(margin_of("(x >= 1)"), diff("x", "1"));
  EXPECT_EQ(margin_of("x == 1"), "((x == 1) ? 1.0 : -1.0)");
  // Where a comparison is not alone its margin says nothing: the condition is bisected.
  EXPECT_EQ(margin_of("x >= std::max<double>(c, 1)"), "((x >= std :: max < double > ( c , 1 )) ? 1.0 : -1.0)");
  EXPECT_EQ(margin_of("x > 1 ? c > 2 : c < 3"), "((x > 1 ? c > 2 : c < 3) ? 1.0 : -1.0)");
}

TEST(DifferentialRules, EqualityOnAContinuousParameterIsWarnedOf) {
  const Model m = parse_lc_text(
      "module A(double, int);\n"
      "events:\n"
      "A(x, k) : when (k == 0 && x >= 1) { produce A(x, 1); }\n"
      "A(x, k) : when (k == 1 && x == 2) { produce A(x, 2); }\n");
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_EQ(m.warnings[0].rfind("model.l:4:29: warning: '==' on a parameter that changes continuously", 0), 0u)
      << m.warnings[0];
}

struct BadSource {
  const char* source;
  const char* error;
};
void PrintTo(const BadSource& b, std::ostream* os) { *os << '"' << b.error << '"'; }

class DifferentialRuleErrors : public ::testing::TestWithParam<BadSource> {};

TEST_P(DifferentialRuleErrors, PointAtTheProblem) {
  EXPECT_EQ(parse_error(parse_lc_text, GetParam().source), GetParam().error);
}

INSTANTIATE_TEST_SUITE_P(
    Table, DifferentialRuleErrors,
    ::testing::Values(
        BadSource{"module A(double);\nderivatives:\nA(x) : { d(y) = 1; }\n",
                  "model.l:3:10: error: an equation for 'y', which is not a parameter of A, the module this "
                  "derivative rule is for"},
        BadSource{"module A(double);\nderivatives:\nA(x) A(y) : { d(x) = 1; }\n",
                  "model.l:3:6: error: a derivative rule gives the rates of one module: its strict predecessor "
                  "must be a single module"},
        BadSource{"module A(double);\nderivatives:\nA(x) : { produce A(x); }\n",
                  "model.l:3:10: error: a derivative rule gives rates ('d(x) = ...;'), not a successor: "
                  "productions at an instant belong in an events: block"},
        BadSource{"module A(double);\nevents:\nA(x) : { produce A(x); }\n",
                  "model.l:3:8: error: expected 'when (condition)' after ':' in an event, found '{'"},
        BadSource{"module A(double);\nevents:\nA(x) : when () { produce A(x); }\n",
                  "model.l:3:14: error: expected a condition in 'when ( )'"},
        BadSource{"module A(double);\nderivatives:\nA(x) : { d(x) = ; }\n",
                  "model.l:3:17: error: expected the rate of 'x' after 'd(x) ='"}));

}  // namespace
}  // namespace sylva::test
