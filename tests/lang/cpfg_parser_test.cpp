// The cpfg front end from L-system text to the Model IR, without the C
// preprocessor: symbols as module types, productions with contexts,
// conditions and probabilities, decomposition and homomorphism, ignore:,
// sub-L-systems, and errors at file:line:column. Expected values are read
// off the text: a symbol s with n parameters is module cpfg_<s>_<n> (other
// characters than letters and digits as x<hex>), a formal x is v_x, and a
// number is written as a double.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/model_ir.h"
#include "lang/model_ir_text.h"

namespace sylva::test {
namespace {

using lang::Model;
using lang::Rule;

std::vector<const Rule*> rules(const Model& m) { return items_of<Rule>(m); }

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << part << "\" is not in \"" << text << "\"";
}

// The C++ of a cpfg rule's statements, condition and probability (its first body part).
std::string rule_code(const Rule& r) { return r.body.size() > 1 ? text(r.body.front().code) : ""; }

TEST(CpfgParser, SymbolsBecomeModulesAndProductionsRules) {
  const Model m = parse_cpfg_text(
      "Lsystem: 1\n"
      "derivation length: 3\n"
      "axiom: A(1)B\n"
      "A(x) : x < 3 --> A(x+1)[+B]\n"
      "B < A(x) > B : * --> A(x*2)\n"
      "endlsystem\n");
  EXPECT_TRUE(m.cpfg);
  const std::size_t predefined = lang::predefined_modules().size();
  ASSERT_EQ(m.modules.size(), predefined + 3);
  EXPECT_EQ(m.modules[predefined].name, "cpfg_A_1");
  EXPECT_EQ(m.modules[predefined].display_name, "A");
  EXPECT_EQ(m.modules[predefined].param_types, std::vector<std::string>{"float"});
  EXPECT_EQ(m.modules[predefined + 1].name, "cpfg_B_0");
  EXPECT_EQ(m.modules[predefined + 2].name, "cpfg_x2B_0");
  EXPECT_EQ(m.modules[predefined + 2].display_name, "+");

  const auto settings = items_of<lang::Setting>(m);
  ASSERT_EQ(settings.size(), 1u);
  EXPECT_EQ(settings[0]->kind, lang::Setting::kDerivationLength);
  EXPECT_EQ(text(settings[0]->expression), "(3.0)");
  const auto axioms = items_of<lang::Axiom>(m);
  ASSERT_EQ(axioms.size(), 1u);
  EXPECT_EQ(text(axioms[0]->modules), "cpfg_A_1(static_cast<float>(1.0)) cpfg_B_0");
  EXPECT_EQ(at(axioms[0]->at), "3:1");

  const auto r = rules(m);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0]->kind, abi::RuleKind::Production);
  EXPECT_EQ(text(r[0]->parts[abi::kStrict]), "cpfg_A_1(v_x)");
  EXPECT_TRUE(r[0]->parts[abi::kLeft].empty());
  EXPECT_TRUE(Contains(rule_code(*r[0]), "if (!((v_x < 3.0))) return;"));
  EXPECT_EQ(r[0]->body.back().kind, lang::BodyPart::kProduce);
  EXPECT_EQ(text(r[0]->body.back().modules), "cpfg_A_1(static_cast<float>((v_x + 1.0))) SB cpfg_x2B_0 cpfg_B_0 EB");
  EXPECT_EQ(at(r[0]->at), "4:1");

  EXPECT_EQ(text(r[1]->parts[abi::kLeft]), "cpfg_B_0");
  EXPECT_EQ(text(r[1]->parts[abi::kStrict]), "cpfg_A_1(v_x)");
  EXPECT_EQ(text(r[1]->parts[abi::kRight]), "cpfg_B_0");
  ASSERT_EQ(r[1]->body.size(), 2u);  // code, then the successor
  EXPECT_FALSE(Contains(rule_code(*r[1]), "if (!("));  // the condition `*`: none
  EXPECT_EQ(text(r[1]->body.back().modules), "cpfg_A_1(static_cast<float>((v_x * 2.0)))");
  EXPECT_TRUE(m.warnings.empty());
}

TEST(CpfgParser, ALineThatStartsWithATabContinuesTheStatement) {
  const Model tab = parse_cpfg_text("Lsystem: 1\naxiom: A\nA --> B\n\tC\nendlsystem\n");
  ASSERT_EQ(rules(tab).size(), 1u);
  EXPECT_EQ(text(rules(tab)[0]->body.back().modules), "cpfg_B_0 cpfg_C_0");
  // Spaces begin a statement of their own: "C" alone is a production without an arrow.
  EXPECT_EQ(parse_error(parse_cpfg_text, "Lsystem: 1\naxiom: A\nA --> B\n  C\nendlsystem\n"),
            "plant.l:4:4: error: expected '-->' after the predecessor, found the end of the line");
}

TEST(CpfgParser, ProbabilitiesMakeTheLsystemStochasticWhenItHasASeed) {
  const Model m = parse_cpfg_text(
      "Lsystem: 1\n"
      "seed: 7\n"
      "axiom: A\n"
      "A --> B : 0.3\n"
      "A --> C : 0.7\n"
      "endlsystem\n");
  EXPECT_TRUE(m.cpfg_stochastic);
  const auto r = rules(m);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(Contains(rule_code(*r[0]), "sylva_cpfg_applies(0, static_cast<float>(0.3))"));
  EXPECT_TRUE(Contains(rule_code(*r[1]), "sylva_cpfg_applies(1, static_cast<float>(0.7))"));
  EXPECT_TRUE(m.warnings.empty());

  // Without seed: the probability is read past, with a warning where it stands.
  const Model plain = parse_cpfg_text("Lsystem: 1\naxiom: A\nA --> B : 0.3\nendlsystem\n");
  EXPECT_FALSE(plain.cpfg_stochastic);
  ASSERT_EQ(rules(plain)[0]->body.size(), 2u);
  EXPECT_FALSE(Contains(rule_code(*rules(plain)[0]), "sylva_cpfg_applies"));
  EXPECT_EQ(plain.warnings, std::vector<std::string>{"plant.l:3:11: warning: probability ignored: the L-system has "
                                                     "no seed:, so its productions are not chosen at random"});
}

TEST(CpfgParser, DecompositionAndHomomorphismWithTheirDepths) {
  const Model m = parse_cpfg_text(
      "Lsystem: 0\n"
      "axiom: A\n"
      "A --> A\n"
      "decomposition\n"
      "maximum depth: 5\n"
      "A --> B B\n"
      "homomorphism\n"
      "maximum depth: 2\n"
      "B --> F\n"
      "endlsystem\n");
  const auto r = rules(m);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0]->kind, abi::RuleKind::Production);
  EXPECT_EQ(r[1]->kind, abi::RuleKind::Decomposition);
  EXPECT_EQ(text(r[1]->body.back().modules), "cpfg_B_0 cpfg_B_0");
  EXPECT_EQ(r[2]->kind, abi::RuleKind::Interpretation);
  const auto settings = items_of<lang::Setting>(m);
  ASSERT_EQ(settings.size(), 2u);
  EXPECT_EQ(settings[0]->kind, lang::Setting::kDecompositionDepth);
  EXPECT_EQ(text(settings[0]->expression), "(5.0)");
  EXPECT_EQ(settings[1]->kind, lang::Setting::kInterpretationDepth);
  EXPECT_EQ(text(settings[1]->expression), "(2.0)");
  EXPECT_FALSE(m.cpfg_sub_lsystems);
}

TEST(CpfgParser, IgnoreNamesTheModulesOfItsCharacters) {
  const Model m = parse_cpfg_text(
      "Lsystem: 1\n"
      "axiom: A+B-C\n"
      "ignore: +-\n"
      "A < B --> C\n"
      "endlsystem\n");
  ASSERT_EQ(m.filters.size(), 1u);
  EXPECT_FALSE(m.filters[0].consider);
  EXPECT_EQ(m.filters[0].names, (std::vector<std::string>{"cpfg_x2B_0", "cpfg_x2D_0"}));
  const auto r = rules(m);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0]->filter, 0);
  EXPECT_EQ(text(r[0]->parts[abi::kLeft]), "cpfg_A_0");
  EXPECT_EQ(text(r[0]->parts[abi::kStrict]), "cpfg_B_0");
}

TEST(CpfgParser, StartBlockVariablesAreGlobal) {
  const Model m = parse_cpfg_text(
      "Lsystem: 1\n"
      "Start: {n = 2;}\n"
      "derivation length: n\n"
      "axiom: A\n"
      "endlsystem\n");
  const auto settings = items_of<lang::Setting>(m);
  ASSERT_EQ(settings.size(), 1u);
  EXPECT_EQ(text(settings[0]->expression), "(v_n)");
  const auto control = items_of<lang::ControlStatement>(m);
  ASSERT_EQ(control.size(), 1u);
  EXPECT_EQ(control[0]->kind, lang::ControlStatement::kStart);
  EXPECT_TRUE(Contains(text(control[0]->body), "v_n = 2.0;"));
}

TEST(CpfgParser, SubLsystemsLabelTheirRules) {
  const Model m = parse_cpfg_text(
      "Lsystem: 1\n"
      "axiom: A?(2,1)B$\n"
      "A --> A\n"
      "endlsystem\n"
      "Lsystem: 2\n"
      "B --> C\n"
      "endlsystem\n");
  EXPECT_TRUE(m.cpfg_sub_lsystems);
  EXPECT_EQ(m.main_lsystem, 1);
  EXPECT_EQ(m.lsystem_labels, (std::vector<int>{1, 2}));
  EXPECT_EQ(m.call_module, "cpfg_x3F_2");
  EXPECT_EQ(m.return_module, "cpfg_x24_0");
  const auto r = rules(m);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0]->group, 1);
  EXPECT_EQ(r[1]->group, 2);
}

struct BadLsystem {
  const char* source;
  const char* error;
};

void PrintTo(const BadLsystem& b, std::ostream* os) { *os << '"' << b.error << '"'; }

class CpfgParserErrors : public ::testing::TestWithParam<BadLsystem> {};

TEST_P(CpfgParserErrors, PointAtTheProblem) {
  EXPECT_EQ(parse_error(parse_cpfg_text, GetParam().source), GetParam().error);
}

INSTANTIATE_TEST_SUITE_P(
    Table, CpfgParserErrors,
    ::testing::Values(
        BadLsystem{"axiom: A\n", "plant.l:1:1: error: expected 'Lsystem:' before the L-system"},
        BadLsystem{"Lsystem: 1\naxiom: A\n", "plant.l:1:1: error: expected 'endlsystem' at the end of the L-system"},
        BadLsystem{"Lsystem: 1\nA --> B\naxiom: A\nendlsystem\n",
                   "plant.l:2:1: error: expected 'Axiom:' before the productions"},
        BadLsystem{"Lsystem: 1\naxiom: A\nA B\nendlsystem\n",
                   "plant.l:3:4: error: expected '-->' after the predecessor, found the end of the line"},
        BadLsystem{"Lsystem: 1\naxiom: A\nA --> B(foo(1))\nendlsystem\n",
                   "plant.l:3:9: error: unknown function 'foo'"},
        BadLsystem{"Lsystem: 1\naxiom: A\nmaximum depth: 2\nendlsystem\n",
                   "plant.l:3:1: error: 'maximum depth:' belongs after 'decomposition' or 'homomorphism'"},
        BadLsystem{"Lsystem: 1\naxiom: A\nendlsystem\nLsystem: 1\nendlsystem\n",
                   "plant.l:4:10: error: a second L-system with label 1"},
        BadLsystem{"Lsystem: 1\naxiom: A?(3,1)\nendlsystem\n",
                   "plant.l:2:11: error: ?(3,...) calls L-system 3, but no 'Lsystem: 3' is defined"},
        BadLsystem{"Lsystem: 1\naxiom: A(1\nendlsystem\n",
                   "plant.l:2:11: error: expected ',' or ')' in the parameters of A in the axiom, found the end of "
                   "the line"}));

}  // namespace
}  // namespace sylva::test
