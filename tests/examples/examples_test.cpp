// Tests of the thesis examples in examples/ (information transfer, chapter 3;
// the branching model and its variants, chapter 4). Every expectation is
// worked out by hand from the thesis text or computed here a second way in
// plain C++; none is a recorded output of the program.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

std::string repeat(const std::string& word, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += (out.empty() ? "" : " ") + word;
  return out;
}

std::string join(const std::string& a, const std::string& b) { return a.empty() ? b : b.empty() ? a : a + " " + b; }

// ---------------------------------------------------------------------------
// Listing 17. S(n) < A -> A S(n+1) moves the counter one A to the right per
// step, so after k <= 8 steps the string is A^k S(k) A^(8-k) (the thesis:
// "AS(1)AAAAAAA", "AAS(2)AAAAAA"). In step 9 S(8) has no A on its right and
// becomes R(8); R has no production, so step 10 changes nothing.
TEST(ExampleLinearContext, CounterWalksOneAPerStepAndEndsAsR8) {
  Stepper run(model("linear-context"));
  for (int k = 0; k <= 10; ++k) {
    std::string expected = k <= 8 ? join(join(repeat("A", k), "S(" + std::to_string(k) + ")"), repeat("A", 8 - k))
                                  : repeat("A", 8) + " R(8)";
    EXPECT_EQ(run.text(), expected) << "after step " << k;
    run.step();
  }
}

TEST(ExampleLinearContext, DerivationLengthIsNine) {
  EXPECT_EQ(derive_string(model("linear-context")), repeat("A", 8) + " R(8)");
}

// ---------------------------------------------------------------------------
// Listing 18. In one forward step every A increments the global n; the last A
// (no A to its right) produces A R(n) with n = 8 (the thesis' trace table).
// n is never reset, so step k adds R(8k) right after the A's, before the R's of
// the earlier steps, which have no production and are copied.
TEST(ExampleFitGlobalVariable, CountsTheEightAsInOneStep) {
  EXPECT_EQ(derive_string(model("fit-global-variable")), repeat("A", 8) + " R(8)");
  Stepper run(model("fit-global-variable"));
  std::string rs;
  for (int k = 1; k <= 3; ++k) {
    run.step();
    rs = join("R(" + std::to_string(8 * k) + ")", rs);
    EXPECT_EQ(run.text(), repeat("A", 8) + " " + rs) << "after step " << k;
  }
}

// ---------------------------------------------------------------------------
// Information transfer in branching structures (section 3.3.2) on the two
// trees of the thesis (the examples take Figure 24 with -D FIGURE24):
//   Figure 27: I1 [ I2 A ] I3 A
//   Figure 24: I0 [ I1 [ I2 A_e ] I3 A_d ] I4 [ I5 A_c ] I6 [ I7 A_b ] I8 A_a
// By hand (I's in string order):
//   developmental labels (root = 1, child = parent + 1):
//     Figure 27: 1 2 2            Figure 24: 1 2 3 3 2 3 3 4 4
//   functional labels (apices supported):
//     Figure 27: 2 1 1            Figure 24: 5 2 1 1 3 1 2 1 1
// The tests also compute them a second way with depths_of_I / apices_above_I.
const std::vector<int> kFig27Depths = {1, 2, 2};
const std::vector<int> kFig24Depths = {1, 2, 3, 3, 2, 3, 3, 4, 4};
const std::vector<int> kFig27Apices = {2, 1, 1};
const std::vector<int> kFig24Apices = {5, 2, 1, 1, 3, 1, 2, 1, 1};

std::vector<std::string> tree(bool fig24) { return fig24 ? std::vector<std::string>{"FIGURE24"} : std::vector<std::string>{}; }

std::vector<int> labels_after(const std::string& name, int steps, bool fig24) {
  return labels_of_I(parse_modules(derive_with(model(name), steps, tree(fig24))));
}

TEST(ExampleBranchingTrees, HandLabelsAgreeWithTheTreeWalks) {
  std::vector<Module> f27 = parse_modules(derive_with(model("fit-new-left-context"), 0, tree(false)));
  std::vector<Module> f24 = parse_modules(derive_with(model("fit-new-left-context"), 0, tree(true)));
  EXPECT_EQ(names(f27), (std::vector<std::string>{"I", "SB", "I", "A", "EB", "I", "A"}));
  EXPECT_EQ(depths_of_I(f27), kFig27Depths);
  EXPECT_EQ(depths_of_I(f24), kFig24Depths);
  EXPECT_EQ(apices_above_I(f27), kFig27Apices);
  EXPECT_EQ(apices_above_I(f24), kFig24Apices);
}

// Listing 19: the thesis' trace ends with I1(1,1)[I2(2,0)A]I3(2,1)A. The
// second parameter (main 1 / lateral 0) is never changed; in the axiom an I is
// lateral exactly when it opens a branch (follows SB).
TEST(ExampleFitStackForward, DevelopmentalLabelsInOneStep) {
  EXPECT_EQ(derive_string(model("fit-stack-forward")), "I(1,1) SB I(2,0) A EB I(2,1) A");
  for (bool fig24 : {false, true}) {
    std::vector<Module> axiom = parse_modules(derive_with(model("fit-stack-forward"), 0, tree(fig24)));
    std::vector<Module> after = parse_modules(derive_with(model("fit-stack-forward"), 1, tree(fig24)));
    EXPECT_EQ(labels_of_I(after), depths_of_I(axiom));
    EXPECT_EQ(labels_of_I(after), fig24 ? kFig24Depths : kFig27Depths);
    EXPECT_EQ(labels_of_I(after, 1), labels_of_I(axiom, 1));
    EXPECT_EQ(names(after), names(axiom));
    for (std::size_t i = 1; i < axiom.size(); ++i)
      if (axiom[i].name == "I") {
        EXPECT_EQ(number(axiom[i].params[1]), axiom[i - 1].name == "SB" ? 0 : 1) << i;
      }
  }
}

// Listing 21: the thesis' trace ends with I(1)[I(2)A]I(2)A, the same labels as
// Listing 19. p2 (I(n) -> I(n+1)) applies only to the root, so a second step
// starts from root 2 and every label becomes depth + 1.
TEST(ExampleFitNewLeftContext, DevelopmentalLabelsInOneStep) {
  EXPECT_EQ(derive_string(model("fit-new-left-context")), "I(1) SB I(2) A EB I(2) A");
  for (bool fig24 : {false, true}) {
    std::vector<int> depths = fig24 ? kFig24Depths : kFig27Depths;
    EXPECT_EQ(labels_after("fit-new-left-context", 1, fig24), depths);
    EXPECT_EQ(labels_after("fit-new-left-context", 1, fig24), labels_after("fit-stack-forward", 1, fig24));
    std::vector<int> plus_one = depths;
    for (int& d : plus_one) ++d;
    EXPECT_EQ(labels_after("fit-new-left-context", 2, fig24), plus_one);
  }
}

// Section 3.3.2.1, developmental: p2 gives the root 1 and p1 gives every other
// I its parent's old label + 1, so label_k(depth d) = label_{k-1}(d-1) + 1 with
// label_0 = 0, i.e. label_k = min(d, k): one level per step, final after 4
// steps (the longest path has 4 internodes), then equal to the FIT versions.
TEST(ExampleContextDevelopmental, OneLevelPerStepUntilTheDepths) {
  Stepper run(model("context-developmental"));
  for (int k = 0; k <= 5; ++k) {
    std::vector<int> expected;
    for (int d : kFig24Depths) expected.push_back(std::min(d, k));
    EXPECT_EQ(labels_of_I(run.modules()), expected) << "after step " << k;
    if (k < 5) run.step();
  }
  EXPECT_EQ(labels_of_I(run.modules()), labels_after("fit-new-left-context", 1, true));
  EXPECT_EQ(labels_of_I(run.modules()), labels_after("fit-stack-forward", 1, true));
}

// Listing 20: the thesis' trace ends with I1(2)[I2(1)A]I3(1)A.
TEST(ExampleFitStackBackward, ApexCountsInOneBackwardStep) {
  EXPECT_EQ(derive_string(model("fit-stack-backward")), "I(2) SB I(1) A EB I(1) A");
  EXPECT_EQ(labels_after("fit-stack-backward", 1, true), kFig24Apices);
}

// Listing 22: the (corrected) trace ends with I(2)[I(1)A]I(1)A.
TEST(ExampleFitNewRightContext, ApexCountsInOneBackwardStep) {
  EXPECT_EQ(derive_string(model("fit-new-right-context")), "I(2) SB I(1) A EB I(1) A");
  for (bool fig24 : {false, true}) {
    std::vector<Module> axiom = parse_modules(derive_with(model("fit-new-right-context"), 0, tree(fig24)));
    EXPECT_EQ(labels_after("fit-new-right-context", 1, fig24), apices_above_I(axiom));
    EXPECT_EQ(labels_after("fit-new-right-context", 1, fig24), fig24 ? kFig24Apices : kFig27Apices);
    EXPECT_EQ(labels_after("fit-new-right-context", 1, fig24), labels_after("fit-stack-backward", 1, fig24));
  }
}

// Section 3.3.2.1, functional: in step k an I followed by A gets 1 and an I
// followed by [I_lat] I_main gets the sum of their labels from step k-1. The
// recurrence is run here on the tree itself; after 4 steps (the tree's
// height) it reaches the apex counts, which Listings 20 and 22 get in one step.
TEST(ExampleContextFunctional, SignalClimbsOneLevelPerStep) {
  Stepper run(model("context-functional"));
  std::vector<Module> s = run.modules();
  std::vector<int> label(s.size(), 0);  // by module index; 0 in the axiom
  for (int k = 0; k <= 5; ++k) {
    std::vector<int> expected;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i].name == "I") expected.push_back(label[i]);
    EXPECT_EQ(labels_of_I(run.modules()), expected) << "after step " << k;
    std::vector<int> next = label;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i].name != "I") continue;
      if (s[i + 1].name == "A") next[i] = 1;
      if (s[i + 1].name == "SB") next[i] = label[i + 2] + label[end_of_branch(s, i + 2) + 1];
    }
    label = next;
    if (k < 5) run.step();
  }
  std::vector<int> final_labels = labels_of_I(run.modules());
  EXPECT_EQ(final_labels, kFig24Apices);
  EXPECT_EQ(final_labels, labels_after("fit-stack-backward", 1, true));
  EXPECT_EQ(final_labels, labels_after("fit-new-right-context", 1, true));
}

// ---------------------------------------------------------------------------
// Listings 26-30: an apex ages by dt = 0.03 per step and, past t_max = 1.0,
// becomes I [A] [A] I A with every new organ aged new_t - t_max. Ages are float
// parameters: new_t = t + dt is computed in double and rounded to float, as C++
// does. All apices of a model are created together, so they share one age;
// this loop follows it the way Listing 26 computes it. (Listing 28 ages first,
// A(t+dt), then decomposes if t > t_max: the same float values tested in the
// same step, so the two models agree at every step, not just at the end.)
struct AgeHistory {
  std::vector<float> age;  // apex age after each step
  std::vector<int> waves;  // number of branchings done by each step
};

AgeHistory apex_ages(int steps, bool test_old_age) {
  AgeHistory h{{0.0f}, {0}};
  float t = 0.0f;
  for (int s = 1; s <= steps; ++s) {
    float new_t = static_cast<float>(t + 0.03);
    float tested = test_old_age ? t : new_t;  // Listing 30 tests the old age
    bool branch = tested > 1.0;
    t = branch ? static_cast<float>(tested - 1.0) : new_t;
    h.age.push_back(t);
    h.waves.push_back(h.waves.back() + branch);
  }
  return h;
}

std::vector<int> branching_steps(const AgeHistory& h) {
  std::vector<int> steps;
  for (std::size_t s = 1; s < h.waves.size(); ++s)
    if (h.waves[s] > h.waves[s - 1]) steps.push_back(static_cast<int>(s));
  return steps;
}

// Each branching replaces every apex by 3 apices, 2 internodes and 4 brackets
// (and, in Listing 29, one Left and one Right).
struct Counts {
  int a = 1, i = 0, brackets = 0, turns = 0;
};
Counts after_waves(int waves) {
  Counts c;
  for (int w = 0; w < waves; ++w) c = {3 * c.a, c.i + 2 * c.a, c.brackets + 4 * c.a, c.turns + 2 * c.a};
  return c;
}

std::vector<Module> without_turns(const std::vector<Module>& s) {
  std::vector<Module> out;
  for (const Module& m : s)
    if (m.name != "Left" && m.name != "Right") out.push_back(m);
  return out;
}

// 1.0 / 0.03 = 33.3, so the 34th step takes the age past 1.0; the new apices
// start at about 0.02 and need 33 more steps (step 67); the next ones start at
// about 0.01, and 0.01 + 33 * 0.03 is exactly 1.0 in real arithmetic, so the
// third branching depends on rounding: with float ages it comes at step 101
// (with double ages it would come at step 100).
TEST(ExampleBranching, FirstBranchingAtStep34) {
  AgeHistory h = apex_ages(101, false);
  EXPECT_EQ(branching_steps(h), (std::vector<int>{34, 67, 101}));
  std::vector<Module> s33 = parse_modules(derive_string(model("branching"), 33));
  ASSERT_EQ(names(s33), std::vector<std::string>{"A"});
  EXPECT_EQ(float_number(s33[0].params[0]), h.age[33]);
  EXPECT_NEAR(h.age[33], 0.99, 1e-5);
  std::vector<Module> s34 = parse_modules(derive_string(model("branching"), 34));
  EXPECT_EQ(names(s34), (std::vector<std::string>{"I", "SB", "A", "EB", "SB", "A", "EB", "I", "A"}));
  EXPECT_NEAR(float_number(s34[0].params[0]), 0.02, 1e-5);
}

// Listings 26, 27 and 28 derive the same string at every step; module counts
// follow the branching recurrence and every apex has the age of the loop above.
TEST(ExampleBranching, ListingsTwentySixToTwentyEightAgreeAtEveryStep) {
  AgeHistory h = apex_ages(101, false);
  Stepper l26(model("branching")), l27(model("multiple-successors")), l28(model("decomposition"));
  for (int s = 0; s <= 101; ++s) {
    std::string text = l26.text();
    EXPECT_EQ(l27.text(), text) << "step " << s;
    EXPECT_EQ(l28.text(), text) << "step " << s;
    std::vector<Module> m = parse_modules(text);
    Counts c = after_waves(h.waves[s]);
    EXPECT_EQ(count_named(m, "A"), c.a) << "step " << s;
    EXPECT_EQ(count_named(m, "I"), c.i) << "step " << s;
    EXPECT_EQ(count_named(m, "SB") + count_named(m, "EB"), c.brackets) << "step " << s;
    EXPECT_EQ(static_cast<int>(m.size()), c.a + c.i + c.brackets) << "step " << s;
    for (const Module& a : m)
      if (a.name == "A") {
        ASSERT_EQ(float_number(a.params[0]), h.age[s]) << "step " << s;
      }
    l26.step(), l27.step(), l28.step();
  }
}

// Listing 29 is Listing 28 plus Left(35)/Right(35) at the start of the lateral
// branches: without them its string is Listing 28's at every step.
TEST(ExampleInterpretation, IsTheDecompositionModelWithTurns) {
  AgeHistory h = apex_ages(101, false);
  Stepper l28(model("decomposition")), l29(model("interpretation"));
  for (int s = 0; s <= 101; ++s) {
    std::vector<Module> m = l29.modules();
    std::vector<Module> plain = l28.modules();
    EXPECT_EQ(names(without_turns(m)), names(plain)) << "step " << s;
    for (std::size_t i = 0; i < plain.size() && i < without_turns(m).size(); ++i)
      ASSERT_EQ(without_turns(m)[i].params, plain[i].params) << "step " << s;
    EXPECT_EQ(count_named(m, "Left") + count_named(m, "Right"), after_waves(h.waves[s]).turns) << "step " << s;
    for (std::size_t i = 0; i < m.size(); ++i)
      if (m[i].name == "Left" || m[i].name == "Right") {
        EXPECT_EQ(m[i].params, std::vector<std::string>{"35"});
        EXPECT_EQ(m[i - 1].name, "SB");
      }
    l28.step(), l29.step();
  }
}

// The interpretation rules draw A(t) as SetColor(1) Circle(0.2*t) and I(t) as
// SetColor(2) F(t); everything else is drawn as it is. The expected drawing is
// built here from the derived string.
TEST(ExampleInterpretation, InterpretedStringDrawsApicesAndInternodes) {
  for (int steps : {34, 100}) {
    Stepper run(model("interpretation"));
    run.step(steps);
    std::vector<std::string> expected_names;
    std::vector<std::vector<double>> expected_values;
    for (const Module& m : run.modules()) {
      if (m.name == "A" || m.name == "I") {
        float t = float_number(m.params[0]);
        expected_names.insert(expected_names.end(), {"SetColor", m.name == "A" ? "Circle" : "F"});
        expected_values.push_back({m.name == "A" ? 1.0 : 2.0});
        expected_values.push_back({m.name == "A" ? static_cast<float>(0.2 * t) : t});
      } else {
        expected_names.push_back(m.name);
        std::vector<double> p;
        for (const std::string& v : m.params) p.push_back(number(v));
        expected_values.push_back(p);
      }
    }
    std::vector<Module> drawn = parse_modules(run.interpreted());
    ASSERT_EQ(names(drawn), expected_names) << "step " << steps;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      ASSERT_EQ(drawn[i].params.size(), expected_values[i].size()) << i;
      for (std::size_t p = 0; p < drawn[i].params.size(); ++p)
        EXPECT_FLOAT_EQ(number(drawn[i].params[p]), expected_values[i][p]) << i;
    }
    EXPECT_EQ(count_named(drawn, "Circle"), count_named(run.modules(), "A"));
    EXPECT_EQ(count_named(drawn, "F"), count_named(run.modules(), "I"));
  }
}

// Listing 30 tests the OLD age (t <= t_max), so each branching comes one step
// later than in Listing 26: steps 35 and 69 (and none more by step 100). EndEach
// writes one line per step with the apices counted in that step: an apex that
// only ages counts 1, one that branches counts 3, so the count is 3^waves.
TEST(ExampleControlStatements, OutputFileCountsApicesEachStep) {
  AgeHistory h = apex_ages(100, true);
  EXPECT_EQ(branching_steps(h), (std::vector<int>{35, 69}));
  std::string expected;
  for (int s = 1; s <= 100; ++s)
    expected += "Step: " + std::to_string(s) + "\t, Number of apices: " + std::to_string(after_waves(h.waves[s]).a) +
                "\n";

  std::string dir = make_temp_dir("example-control-statements");
  std::ofstream(dir + "/control-statements.l") << read_text(model("control-statements"));
  ProcessResult r = run_sylva({"run", "control-statements.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(dir + "/output.dat"), expected);
  std::vector<Module> final_string = parse_modules(r.out);
  EXPECT_EQ(count_named(final_string, "A"), 9);
  EXPECT_EQ(count_named(final_string, "I"), after_waves(2).i);
  for (const Module& a : final_string)
    if (a.name == "A") {
      EXPECT_EQ(float_number(a.params[0]), h.age[100]);
    }
}

}  // namespace
}  // namespace sylva::test::examples
