// The derivation engine on models built by hand (tests/hand_built_model.h):
// no translator and no C++ compiler, so each test shows the engine's part
// alone. Every expected string is worked out by hand from the rules.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "derive/derivation.h"
#include "hand_built_model.h"
#include "io/string_text.h"

namespace sylva::test {
namespace {

using abi::RuleKind;

// The model's own modules, after the predefined ones, in the order the
// fixture declares them: A(float) B(float) C.
constexpr abi::ModuleId kA = rt::mid::PredefinedCount, kB = kA + 1, kC = kA + 2;
constexpr abi::ModuleId kSB = rt::mid::SB, kEB = rt::mid::EB;

class HandBuiltDerivation : public ::testing::Test {
 protected:
  HandBuiltDerivation() {
    EXPECT_EQ(model_.module("A", 1), kA);
    EXPECT_EQ(model_.module("B", 1), kB);
    EXPECT_EQ(model_.module("C"), kC);
  }

  derive::Derivation& derivation() {
    if (!derivation_)
      derivation_ = std::make_unique<derive::Derivation>(
          model_.descriptor(), [this](const std::string& text) { messages_.push_back(text); });
    return *derivation_;
  }
  std::string text() {
    std::string s = io::format_string(derivation().string(), derivation().types());
    s.pop_back();  // the newline
    return s;
  }

  HandBuiltModel model_;
  std::vector<std::string> messages_;
  std::unique_ptr<derive::Derivation> derivation_;
};

TEST_F(HandBuiltDerivation, ForwardStepsForTheModelsDerivationLength) {
  // A(x) -> A(x+1) B(x), B unchanged: A(1) -> A(2) B(1) -> A(3) B(2) B(1).
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {1}}}); });
  model_.set_derivation_length([] { return 2; });
  model_.production({.strict = {kA}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kA, {param(p, 0) + 1}}, {kB, {param(p, 0)}}});
  });
  derivation().begin();
  EXPECT_EQ(text(), "A(1)");
  derivation().run();
  EXPECT_EQ(derivation().steps_done(), 2);
  EXPECT_EQ(text(), "A(3) B(2) B(1)");
  EXPECT_TRUE(messages_.empty());
}

TEST_F(HandBuiltDerivation, ABodyThatDoesNotProduceLeavesTheModuleToTheNextRule) {
  // A(1): the first rule gives up, the second makes C; A(2): the first makes B(20).
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {1}}, {kA, {2}}}); });
  model_.production({.strict = {kA}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    if (param(p, 0) > 1) produce(call, {{kB, {param(p, 0) * 10}}});
  });
  model_.production({.strict = {kA}}, [](abi::RuleCall* call, const unsigned char* const*) { produce(call, {{kC}}); });
  derivation().run(1);
  EXPECT_EQ(text(), "C B(20)");
}

TEST_F(HandBuiltDerivation, LeftContextAcrossABranchAndRightContext) {
  // A(x) < B(y) > C -> B(x+y). B(2) has A(1) as parent but its branch ends
  // before any C; B(3) has A(1) as parent (its sibling branch is skipped) and C on its right.
  model_.set_axiom([](abi::ModuleBuffer* out) {
    write_modules(out, {{kA, {1}}, {kSB}, {kB, {2}}, {kEB}, {kB, {3}}, {kC}});
  });
  model_.production({.left = {kA}, .strict = {kB}, .right = {kC}},
                    [](abi::RuleCall* call, const unsigned char* const* p) {
                      produce(call, {{kB, {param(p, 0) + param(p, 1)}}});
                    });
  derivation().run(1);
  EXPECT_EQ(text(), "A(1) SB B(2) EB B(4) C");
}

TEST_F(HandBuiltDerivation, NewLeftContextReadsTheStringBeingBuilt) {
  // A(x) << B(y) -> B(x); B(x) << B(y) -> B(x+1): each B sees the B just made.
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {1}}, {kB, {0}}, {kB, {0}}, {kB, {0}}}); });
  model_.production({.new_left = {kA}, .strict = {kB}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kB, {param(p, 0)}}});
  });
  model_.production({.new_left = {kB}, .strict = {kB}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kB, {param(p, 0) + 1}}});
  });
  derivation().run(1);
  EXPECT_EQ(text(), "A(1) B(1) B(2) B(3)");
}

TEST_F(HandBuiltDerivation, BackwardStepReadsNewRightContext) {
  // Right to left: B(y) >> A(x) -> B(x); B(y) >> B(x) -> B(x+1). The
  // parameters come in pattern order: the strict B first, then the new right context.
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kB, {0}}, {kB, {0}}, {kB, {0}}, {kA, {1}}}); });
  model_.production({.strict = {kB}, .new_right = {kA}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kB, {param(p, 1)}}});
  });
  model_.production({.strict = {kB}, .new_right = {kB}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kB, {param(p, 1) + 1}}});
  });
  derivation().begin();
  model_.control().forward = false;  // what Backward() in Start does
  derivation().step();
  EXPECT_EQ(text(), "B(3) B(2) B(1) A(1)");
}

TEST_F(HandBuiltDerivation, DecompositionAfterTheAxiomAndEachStepUpToItsDepth) {
  // A(x) -> B(1) A(x-1) while x > 0, three levels deep: A(5) -> B B B A(2),
  // and a warning that the depth was reached with A(2) still decomposable.
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {5}}}); });
  model_.set_decomposition_depth([] { return 3; });
  model_.rule(RuleKind::Decomposition, {.strict = {kA}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    if (param(p, 0) > 0) produce(call, {{kB, {1}}, {kA, {param(p, 0) - 1}}});
  });
  derivation().begin();
  EXPECT_EQ(text(), "B(1) B(1) B(1) A(2)");
  EXPECT_EQ(messages_, std::vector<std::string>{"warning: maximum decomposition depth (3) reached for module A\n"});
  // A step without productions decomposes again: A(2) -> B A(1) -> B B A(0), and A(0) stays.
  derivation().step();
  EXPECT_EQ(text(), "B(1) B(1) B(1) B(1) B(1) A(0)");
}

TEST_F(HandBuiltDerivation, IgnoredModulesAreSkippedByTheRulesAfterTheFilter) {
  // ignore: C holds for the first rule only: A(x) < B(y) sees A(1) past C.
  // The second, B(x) < A(y), comes after the filter ends: the C before A(10)
  // hides B(2) from it (with the filter it would have made A(12)).
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {1}}, {kC}, {kB, {2}}, {kC}, {kA, {10}}}); });
  model_.filter(false, {kC});
  model_.production({.left = {kA}, .strict = {kB}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kB, {param(p, 0) + param(p, 1)}}});
  });
  model_.filter(false, {});
  model_.production({.left = {kB}, .strict = {kA}}, [](abi::RuleCall* call, const unsigned char* const* p) {
    produce(call, {{kA, {param(p, 0) + param(p, 1)}}});
  });
  derivation().run(1);
  EXPECT_EQ(text(), "A(1) C B(3) C A(10)");
}

TEST_F(HandBuiltDerivation, RulesOfAGroupApplyOnlyWhileItIsSelected) {
  model_.set_axiom([](abi::ModuleBuffer* out) { write_modules(out, {{kA, {1}}}); });
  model_.rule(RuleKind::Production, {.strict = {kA}},
              [](abi::RuleCall* call, const unsigned char* const* p) { produce(call, {{kB, {param(p, 0)}}}); }, 1);
  derivation().begin();
  derivation().step();  // group 0: no rule for A
  EXPECT_EQ(text(), "A(1)");
  model_.control().next_group = 1;  // what UseGroup(1) does
  derivation().step();
  EXPECT_EQ(text(), "B(1)");
}

}  // namespace
}  // namespace sylva::test
