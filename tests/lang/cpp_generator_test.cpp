// The C++ generator on a Model IR built by hand: what the engine will read
// from the compiled model (the pattern, rule, filter and module tables, the
// descriptor's counts) is checked entry by entry, each against the IR.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "lang/cpp_generator.h"
#include "lang/model_ir.h"

namespace sylva::test {
namespace {

using namespace sylva::lang;

Token token_at(int line, const std::string& text = "") {
  Token t;
  t.kind = TokenKind::Identifier;
  t.text = text;
  t.line = line;
  t.column = 1;
  return t;
}

Code code(const std::string& text, int line) { return Code{token_at(line, text)}; }

PatternModule pattern_module(const std::string& name, std::vector<std::string> formals = {}) {
  return PatternModule{name, std::move(formals), token_at(1)};
}

// module A(float); module B;  ignore: B;
// derivation length: 3;  axiom: A(1) B;
// line 7:  A(x) < B: { produce B; }              (production, ignore: B in force)
// line 9:  group 2: A(y): { produce A(y); }      (a decomposition rule)
// line 11: vgroup 4: B: { produce A(2); }        (an interpretation rule)
Model small_model() {
  Model m;
  m.files = {"model.l"};
  m.main_file = "model.l";
  m.modules = predefined_modules();
  m.modules.push_back(ModuleDecl{"A", {"float"}, token_at(1, "A"), {}});
  m.modules.push_back(ModuleDecl{"B", {}, token_at(1, "B"), {}});
  m.filters.push_back(ContextFilter{false, {"B"}, token_at(2)});
  m.groups = {2};
  m.items.emplace_back(Setting{Setting::kDerivationLength, code("3", 3), token_at(3)});
  m.items.emplace_back(Axiom{{ModuleCall{"A", {code("1", 4)}, token_at(4)}, ModuleCall{"B", {}, token_at(4)}}, token_at(4)});

  Rule production;
  production.parts[abi::kLeft] = {pattern_module("A", {"x"})};
  production.parts[abi::kStrict] = {pattern_module("B")};
  production.filter = 0;
  production.body = {BodyPart{BodyPart::kProduce, {}, {ModuleCall{"B", {}, token_at(7)}}, token_at(7)}};
  production.at = token_at(7);
  m.items.emplace_back(production);

  Rule decomposition;
  decomposition.kind = abi::RuleKind::Decomposition;
  decomposition.group = 2;
  decomposition.parts[abi::kStrict] = {pattern_module("A", {"y"})};
  decomposition.body = {BodyPart{BodyPart::kProduce, {}, {ModuleCall{"A", {code("y", 9)}, token_at(9)}}, token_at(9)}};
  decomposition.at = token_at(9);
  m.items.emplace_back(decomposition);

  Rule interpretation;
  interpretation.kind = abi::RuleKind::Interpretation;
  interpretation.view = 4;
  interpretation.parts[abi::kStrict] = {pattern_module("B")};
  interpretation.body = {BodyPart{BodyPart::kProduce, {}, {ModuleCall{"A", {code("2", 11)}, token_at(11)}}, token_at(11)}};
  interpretation.at = token_at(11);
  m.items.emplace_back(interpretation);
  return m;
}

// Every match of `pattern` in `text`, as its capture groups.
std::vector<std::vector<std::string>> matches(const std::string& text, const std::string& pattern) {
  std::vector<std::vector<std::string>> found;
  const std::regex re(pattern);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) {
    std::vector<std::string> groups;
    for (std::size_t k = 1; k < it->size(); ++k) groups.push_back((*it)[k].str());
    found.push_back(groups);
  }
  return found;
}

class CppGenerator : public ::testing::Test {
 protected:
  const std::string cpp_ = generate_cpp(small_model());
  const std::string a_ = std::to_string(predefined_modules().size());      // A's id
  const std::string b_ = std::to_string(predefined_modules().size() + 1);  // B's id
};

TEST_F(CppGenerator, PatternsListTheModuleIdsInPatternPartOrder) {
  const auto patterns = matches(cpp_, R"(ModuleId sylva_pattern_(\d+)\[\] = \{([^}]*)\};)");
  ASSERT_EQ(patterns.size(), 3u);
  EXPECT_EQ(patterns[0], (std::vector<std::string>{"0", a_ + "," + b_ + ","}));  // left A, then strict B
  EXPECT_EQ(patterns[1], (std::vector<std::string>{"1", a_ + ","}));
  EXPECT_EQ(patterns[2], (std::vector<std::string>{"2", b_ + ","}));
}

TEST_F(CppGenerator, OneRuleTableEntryPerRule) {
  // {kind, group, filter, pattern, {part lengths}, body, file, line, view}
  const auto rules = matches(cpp_, R"re(\{::sylva::abi::RuleKind::(\w+), (-?\d+), (-?\d+), (sylva_pattern_\d+), \{([^}]*)\}, &(sylva_rule_\d+), "([^"]*)", (\d+), (\d+)\},)re");
  ASSERT_EQ(rules.size(), 3u);
  EXPECT_EQ(rules[0], (std::vector<std::string>{"Production", "0", "0", "sylva_pattern_0", "0,1,1,0,0,", "sylva_rule_0",
                                                "model.l", "7", "0"}));
  EXPECT_EQ(rules[1], (std::vector<std::string>{"Decomposition", "2", "-1", "sylva_pattern_1", "0,0,1,0,0,",
                                                "sylva_rule_1", "model.l", "9", "0"}));
  EXPECT_EQ(rules[2], (std::vector<std::string>{"Interpretation", "0", "-1", "sylva_pattern_2", "0,0,1,0,0,",
                                                "sylva_rule_2", "model.l", "11", "4"}));
  // Each entry's body is defined.
  for (const char* body : {"sylva_rule_0", "sylva_rule_1", "sylva_rule_2"})
    EXPECT_NE(cpp_.find(std::string("static void ") + body + "("), std::string::npos) << body;
}

TEST_F(CppGenerator, FiltersListTheirModules) {
  EXPECT_EQ(matches(cpp_, R"(ModuleId sylva_filter_ids_(\d+)\[\] = \{([^}]*)\};)"),
            (std::vector<std::vector<std::string>>{{"0", b_ + ","}}));
  EXPECT_EQ(matches(cpp_, R"(\{(true|false), sylva_filter_ids_(\d+), (\d+)\},)"),
            (std::vector<std::vector<std::string>>{{"false", "0", "1"}}));
}

TEST_F(CppGenerator, TheDescriptorCountsWhatTheModelHas) {
  const std::string modules = std::to_string(predefined_modules().size() + 2);
  const std::string predefined = std::to_string(predefined_modules().size());
  EXPECT_NE(cpp_.find("sylva_modules, " + modules + ", " + predefined + ","), std::string::npos);
  EXPECT_NE(cpp_.find("sylva_rules, 3,"), std::string::npos);
  EXPECT_NE(cpp_.find("sylva_filters, 1,"), std::string::npos);
  EXPECT_NE(cpp_.find("&sylva_axiom"), std::string::npos);
  EXPECT_NE(cpp_.find("int DerivationLength() { return sylva_derivation_length(); }"), std::string::npos);
  EXPECT_NE(cpp_.find("int DecompositionMaxDepth() { return 1; }"), std::string::npos);  // no maximum depth:
  EXPECT_NE(cpp_.find("int NumOfTables() { return 3; }"), std::string::npos);            // groups 0 to 2
  EXPECT_NE(cpp_.find("int NumOfViews() { return 5; }"), std::string::npos);             // views 0 to 4
  EXPECT_EQ(matches(cpp_, R"(const int sylva_groups\[\] = \{([^}]*)\};)"),
            (std::vector<std::vector<std::string>>{{"2,"}}));
  // The module table names every module, the model's last.
  const auto names = matches(cpp_, R"(\(\"(\w+)\"\),\n)");
  ASSERT_EQ(names.size(), predefined_modules().size() + 2);
  EXPECT_EQ(names.front(), std::vector<std::string>{"SB"});
  EXPECT_EQ(names[names.size() - 2], std::vector<std::string>{"A"});
  EXPECT_EQ(names.back(), std::vector<std::string>{"B"});
}

// The model's line that the generated text at `offset` is attributed to: the
// last line marker before it, plus the lines since.
int model_line_at(const std::string& cpp, std::size_t offset) {
  const std::size_t marker = cpp.rfind("\n# ", offset);
  if (marker == std::string::npos) return -1;
  int line = std::stoi(cpp.substr(marker + 3));
  for (std::size_t k = cpp.find('\n', marker + 1); k < offset; k = cpp.find('\n', k + 1)) ++line;
  return line - 1;
}

TEST_F(CppGenerator, RuleBodiesStandOnTheirModelLines) {
  // So that compiler errors in a body point at the model's line.
  const int lines[] = {7, 9, 11};
  for (int r = 0; r < 3; ++r) {
    const std::size_t body = cpp_.find("static void sylva_rule_" + std::to_string(r) + "(");
    ASSERT_NE(body, std::string::npos);
    EXPECT_EQ(model_line_at(cpp_, body), lines[r]) << "rule " << r;
  }
  EXPECT_EQ(model_line_at(cpp_, cpp_.find("static void sylva_axiom(")), 4);
}

}  // namespace
}  // namespace sylva::test
