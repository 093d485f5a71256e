// The L+C front end from source text to the Model IR, without the C
// preprocessor or a compiler: declarations, rules and their contexts, bodies,
// blocks and groups, filters, settings, and errors at file:line:column. Every
// expected value is read off the source text in the test.
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

TEST(LcParser, ModuleDeclarationsFollowThePredefinedModules) {
  const Model m = parse_lc_text(
      "module A(float, int);\n"
      "module B;\n"
      "  module Cell(CellData);\n");
  const std::size_t predefined = lang::predefined_modules().size();
  ASSERT_EQ(m.modules.size(), predefined + 3);
  EXPECT_EQ(m.modules[0].name, "SB");
  const lang::ModuleDecl& a = m.modules[predefined];
  const lang::ModuleDecl& b = m.modules[predefined + 1];
  const lang::ModuleDecl& cell = m.modules[predefined + 2];
  EXPECT_EQ(a.name, "A");
  EXPECT_EQ(a.param_types, (std::vector<std::string>{"float", "int"}));
  EXPECT_EQ(at(a.at), "1:8");
  EXPECT_EQ(b.name, "B");
  EXPECT_TRUE(b.param_types.empty());
  EXPECT_EQ(at(b.at), "2:8");
  EXPECT_EQ(cell.param_types, std::vector<std::string>{"CellData"});
  EXPECT_EQ(at(cell.at), "3:10");
  EXPECT_EQ(items_of<lang::ModuleDecl>(m).size(), 3u);
  EXPECT_EQ(m.main_file, "model.l");
  EXPECT_FALSE(m.cpfg);
}

TEST(LcParser, EveryContextOfAPredecessorHasItsPart) {
  const Model m = parse_lc_text(
      "module A(float); module B(float); module C(float); module D(float); module E(float);\n"
      "A(a) << B(b) < C(c) > D(d) >> E(e): { produce C(a + b); }\n");
  ASSERT_EQ(rules(m).size(), 1u);
  const Rule& r = *rules(m)[0];
  EXPECT_EQ(r.kind, abi::RuleKind::Production);
  EXPECT_EQ(text(r.parts[abi::kNewLeft]), "A(a)");
  EXPECT_EQ(text(r.parts[abi::kLeft]), "B(b)");
  EXPECT_EQ(text(r.parts[abi::kStrict]), "C(c)");
  EXPECT_EQ(text(r.parts[abi::kRight]), "D(d)");
  EXPECT_EQ(text(r.parts[abi::kNewRight]), "E(e)");
  EXPECT_EQ(text(r.body), "{ | produce C(a + b) | }");
  EXPECT_EQ(at(r.at), "2:1");
  EXPECT_EQ(r.group, 0);
  EXPECT_EQ(r.view, 0);
  EXPECT_EQ(r.filter, -1);
}

TEST(LcParser, BodiesAreCutAtProduceStatements) {
  const Model m = parse_lc_text(
      "module A(float); module B(float); module E(int);\n"
      "A(x) B(y): { if (x > y) produce; nproduce A(x) [ B(y) ]; produce E(1); }\n"
      "A(t) : produce A(t+1);\n"
      "B(y): { float z; if (InLeftContext(A(z))) produce B(z); }\n");
  ASSERT_EQ(rules(m).size(), 3u);
  const Rule& multi = *rules(m)[0];
  EXPECT_EQ(text(multi.parts[abi::kStrict]), "A(x) B(y)");  // a strict predecessor of two modules
  EXPECT_EQ(text(multi.body), "{ if ( x > y ) | produce | nproduce A(x) SB B(y) EB | produce E(1) | }");
  EXPECT_EQ(text(rules(m)[1]->body), "produce A(t + 1)");  // a produce statement as the whole body
  const Rule& in_context = *rules(m)[2];
  EXPECT_EQ(text(in_context.body), "{ float z ; if ( | InLeftContext(A(z)) | ) | produce B(z) | }");
  EXPECT_EQ(at(in_context.body[1].at), "4:22");
}

TEST(LcParser, RuleBlocksAndTheirDepths) {
  const Model m = parse_lc_text(
      "module A(int); module B;\n"
      "decomposition:\n"
      "maximum depth: 4;\n"
      "A(n): { produce B; }\n"
      "interpretation:\n"
      "maximum depth: 2 + 1;\n"
      "B: { produce A(0); }\n"
      "production:\n"
      "B: { produce; }\n");
  ASSERT_EQ(rules(m).size(), 3u);
  EXPECT_EQ(rules(m)[0]->kind, abi::RuleKind::Decomposition);
  EXPECT_EQ(rules(m)[1]->kind, abi::RuleKind::Interpretation);
  EXPECT_EQ(rules(m)[2]->kind, abi::RuleKind::Production);
  const auto settings = items_of<lang::Setting>(m);
  ASSERT_EQ(settings.size(), 2u);
  EXPECT_EQ(settings[0]->kind, lang::Setting::kDecompositionDepth);
  EXPECT_EQ(text(settings[0]->expression), "4");
  EXPECT_EQ(at(settings[0]->at), "3:1");
  EXPECT_EQ(settings[1]->kind, lang::Setting::kInterpretationDepth);
  EXPECT_EQ(text(settings[1]->expression), "2 + 1");
}

TEST(LcParser, GroupsGillespieGroupsAndViews) {
  const Model m = parse_lc_text(
      "module A; module B;\n"
      "A: { produce B; }\n"
      "group 2:\n"
      "A: { produce A; }\n"
      "endgroup\n"
      "ggroup 3:\n"
      "A: { propensity 0.5 produce B; }\n"
      "endgroup\n"
      "interpretation:\n"
      "vgroup 1:\n"
      "B: { produce A; }\n");
  const auto r = rules(m);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0]->group, 0);
  EXPECT_EQ(r[1]->group, 2);
  EXPECT_EQ(r[2]->group, 3);
  EXPECT_EQ(text(r[2]->body), "{ | propensity 0.5 produce B | }");
  EXPECT_EQ(r[3]->group, 0);
  EXPECT_EQ(r[3]->view, 1);
  EXPECT_EQ(r[3]->kind, abi::RuleKind::Interpretation);
  EXPECT_EQ(m.groups, (std::vector<int>{2, 3}));
  EXPECT_EQ(m.gillespie_groups, std::vector<int>{3});
}

TEST(LcParser, IgnoreAndConsiderHoldForTheRulesAfterThem) {
  const Model m = parse_lc_text(
      "module A; module B; module C;\n"
      "ignore: B C;\n"
      "A < A: { produce B; }\n"
      "consider: A;\n"
      "A > A: { produce C; }\n"
      "ignore: ;\n"
      "A: { produce; }\n");
  ASSERT_EQ(m.filters.size(), 2u);
  EXPECT_FALSE(m.filters[0].consider);
  EXPECT_EQ(m.filters[0].names, (std::vector<std::string>{"B", "C"}));
  EXPECT_EQ(at(m.filters[0].at), "2:1");
  EXPECT_TRUE(m.filters[1].consider);
  EXPECT_EQ(m.filters[1].names, std::vector<std::string>{"A"});
  const auto r = rules(m);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0]->filter, 0);
  EXPECT_EQ(r[1]->filter, 1);
  EXPECT_EQ(r[2]->filter, -1);
}

TEST(LcParser, AxiomSettingsAndControlStatements) {
  const Model m = parse_lc_text(
      "module A(float, int); module B;\n"
      "derivation length: 2 * 3;\n"
      "ring L-system: 1;\n"
      "axiom: A(1.5, 2) [ B ] A(-1, n + 1);\n"
      "Start: { n = 0; }\n"
      "EndEach: { }\n");
  const auto settings = items_of<lang::Setting>(m);
  ASSERT_EQ(settings.size(), 2u);
  EXPECT_EQ(settings[0]->kind, lang::Setting::kDerivationLength);
  EXPECT_EQ(text(settings[0]->expression), "2 * 3");
  EXPECT_EQ(at(settings[0]->at), "2:1");
  EXPECT_EQ(settings[1]->kind, lang::Setting::kRing);
  EXPECT_EQ(text(settings[1]->expression), "1");
  const auto axioms = items_of<lang::Axiom>(m);
  ASSERT_EQ(axioms.size(), 1u);
  EXPECT_EQ(text(axioms[0]->modules), "A(1.5, 2) SB B EB A(- 1, n + 1)");
  EXPECT_EQ(at(axioms[0]->at), "4:1");
  EXPECT_EQ(at(axioms[0]->modules[0].at), "4:8");
  const auto control = items_of<lang::ControlStatement>(m);
  ASSERT_EQ(control.size(), 2u);
  EXPECT_EQ(control[0]->kind, lang::ControlStatement::kStart);
  EXPECT_EQ(text(control[0]->body), "{ n = 0 ; }");
  EXPECT_EQ(control[1]->kind, lang::ControlStatement::kEndEach);
  EXPECT_EQ(text(control[1]->body), "{ }");
}

TEST(LcParser, CppPassesThroughAndStructsNameTheirFields) {
  const Model m = parse_lc_text(
      "struct CellData { float size; int kind; };\n"
      "int counter = 0;\n"
      "module A(CellData);\n");
  ASSERT_EQ(m.items.size(), 4u);
  ASSERT_TRUE(std::holds_alternative<lang::Code>(m.items[0]));
  EXPECT_EQ(text(std::get<lang::Code>(m.items[0])), "struct CellData { float size ; int kind ; } ;");
  ASSERT_TRUE(std::holds_alternative<lang::StructFields>(m.items[1]));
  const auto& fields = std::get<lang::StructFields>(m.items[1]);
  EXPECT_EQ(fields.name, "CellData");
  EXPECT_EQ(fields.fields, (std::vector<std::string>{"size", "kind"}));
  ASSERT_TRUE(std::holds_alternative<lang::Code>(m.items[2]));
  EXPECT_EQ(text(std::get<lang::Code>(m.items[2])), "int counter = 0 ;");
  EXPECT_TRUE(std::holds_alternative<lang::ModuleDecl>(m.items[3]));
}

TEST(LcParser, VerifyStringNamesModulesAndBrackets) {
  const Model m = parse_lc_text(
      "module A(int); module B;\n"
      "VerifyString: A(1) [ B ] A;\n");
  EXPECT_TRUE(m.has_verify_string);
  EXPECT_EQ(m.verify_string, (std::vector<std::string>{"A", "SB", "B", "EB", "A"}));
  EXPECT_FALSE(parse_lc_text("module A;\n").has_verify_string);
}

// Malformed input: the message and where it points, counted by hand.
struct BadSource {
  const char* source;
  const char* error;
};

void PrintTo(const BadSource& b, std::ostream* os) { *os << '"' << b.error << '"'; }

class LcParserErrors : public ::testing::TestWithParam<BadSource> {};

TEST_P(LcParserErrors, PointAtTheProblem) {
  EXPECT_EQ(parse_error(parse_lc_text, GetParam().source), GetParam().error);
}

INSTANTIATE_TEST_SUITE_P(
    Table, LcParserErrors,
    ::testing::Values(
        BadSource{"module A;\nmodule A;\n", "model.l:2:8: error: module 'A' is already declared"},
        BadSource{"module A; module B;\nA > B < A: { produce; }\n",
                  "model.l:2:7: error: left context '<' must come before the strict predecessor"},
        BadSource{"module A; module B;\nA > B > A: { produce; }\n",
                  "model.l:2:7: error: the predecessor has two '>' contexts"},
        BadSource{"module A(int); module B(int);\nA(x) < B(x): { produce; }\n",
                  "model.l:2:8: error: parameter name 'x' is bound twice in the predecessor"},
        BadSource{"module A;\nproduce A;\n", "model.l:2:1: error: 'produce' outside a production body"},
        BadSource{"maximum depth: 2;\n",
                  "model.l:1:1: error: 'maximum depth:' belongs in a decomposition: or interpretation: block"},
        BadSource{"ggroup 0:\n", "model.l:1:8: error: group 0 is the main group and cannot be a Gillespie group"},
        BadSource{"group 2:\nendgroup\nggroup 2:\n",
                  "model.l:3:8: error: group 2 is already a regular group ('group 2:'); a Gillespie group needs a "
                  "number of its own"},
        BadSource{"module A;\nVerifyString: A;\nVerifyString: A;\n",
                  "model.l:3:1: error: only one VerifyString: per model; the first is at line 2"},
        BadSource{"module A;\nA: { propensity 1 produce A; }\n",
                  "model.l:2:6: error: 'propensity' is only allowed in the productions of a Gillespie group "
                  "('ggroup N:')"},
        BadSource{"module A;\nggroup 1:\nA << A: { propensity 1 produce A; }\n",
                  "model.l:3:3: error: new context '<<' cannot be used in a Gillespie group (LPFG manual 7.2)"},
        BadSource{"module A;\nA: return;\n",
                  "model.l:2:4: error: expected '{' or a produce statement to begin the body, found 'return'"},
        BadSource{"module A(int, int);\naxiom: A(1,);\n",
                  "model.l:2:12: error: expected a parameter value before ')'"}));

}  // namespace
}  // namespace sylva::test
