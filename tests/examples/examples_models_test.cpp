// Tests of the larger thesis examples in examples/: Anabaena (Listing 37), the
// Borchert-Honda tree (Listing 38), recursive decomposition (appendix A.6.11)
// and the Koch curve (section 9.1.1). Expectations are worked out by hand or
// computed here a second way in plain C++, never copied from the program.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

// ---------------------------------------------------------------------------
// Anabaena (Listing 37). Constants as in the listing.
const float kLonger = 0.55f, kShorter = 1.0f - kLonger, kGrowth = 1.002f, kMaxSize = 1.0f, kThreshold = 0.5f;

struct Cell {
  float hetR, patS, x, vph;
  int p;
  bool heterocyst() const { return hetR > kThreshold; }
};

std::vector<Cell> cells(const std::vector<Module>& s) {
  std::vector<Cell> out;
  for (const Module& m : s) {
    if (m.name != "Cell") continue;
    const std::string& d = m.params.at(0);
    out.push_back({float_number(field(d, "hetR")), float_number(field(d, "patS")), float_number(field(d, "x")),
                   float_number(field(d, "vph")), static_cast<int>(number(field(d, "p")))});
  }
  return out;
}

// Steps a cell of length x needs to reach the maximum size: it grows by
// x *= 1.002 (float) once per step while x < lm, and divides in the step in
// which it reaches lm. About ln(1/0.55)/ln(1.002) = 299.2 -> 300 steps for the
// longer initial cell and ln(1/0.45)/ln(1.002) = 399.6 -> 400 for the shorter.
int steps_to_divide(float x, float* final_x) {
  int n = 0;
  while (x < kMaxSize) x *= kGrowth, ++n;
  *final_x = x;
  return n;
}

// Start sets up two cells (hetR 0.1, patS 100, lengths 0.55 / 0.45, polarity
// plRight = 0); Right(90) only turns the drawing.
TEST(ExampleAnabaena, AxiomIsTheTwoCellsOfStart) {
  Stepper run(model("anabaena"));
  std::vector<Module> s = run.modules();
  ASSERT_EQ(names(s), (std::vector<std::string>{"Right", "Cell", "Cell"}));
  EXPECT_EQ(s[0].params, std::vector<std::string>{"90"});
  std::vector<Cell> c = cells(s);
  for (const Cell& cell : c) {
    EXPECT_EQ(cell.hetR, 0.1f);
    EXPECT_EQ(cell.patS, 100.0f);
    EXPECT_EQ(cell.p, 0);
    EXPECT_EQ(cell.vph, 0.0f);
  }
  EXPECT_EQ(c[0].x, kLonger);
  EXPECT_EQ(c[1].x, kShorter);
}

// The first divisions come at the steps computed above, the longer cell first,
// its daughters split 0.55 : 0.45 with polarities plLeft (1), plRight (0).
TEST(ExampleAnabaena, FirstDivisionsAtTheComputedSteps) {
  float x1, x2;
  int n1 = steps_to_divide(kLonger, &x1), n2 = steps_to_divide(kShorter, &x2);
  EXPECT_EQ(n1, 300);
  EXPECT_EQ(n2, 400);
  Stepper run(model("anabaena"));
  run.step(n1 - 1);
  EXPECT_EQ(cells(run.modules()).size(), 2u);
  run.step();
  std::vector<Cell> c = cells(run.modules());
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].x, x1 * kLonger);
  EXPECT_EQ(c[0].p, 1);
  EXPECT_EQ(c[1].x, x1 * kShorter);
  EXPECT_EQ(c[1].p, 0);
  float grown = kShorter;
  for (int i = 0; i < n1; ++i) grown *= kGrowth;
  EXPECT_EQ(c[2].x, grown);
  run.step(n2 - n1 - 1);
  EXPECT_EQ(cells(run.modules()).size(), 3u);
  run.step();
  c = cells(run.modules());
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[2].x, x2 * kLonger);
  EXPECT_EQ(c[3].x, x2 * kShorter);
  for (const Cell& cell : c) EXPECT_EQ(cell.vph, 0.0f);
}

// Over the 3000 steps cells never disappear, so the count never falls and the
// filament keeps growing. Heterocysts (hetR > thr) were marked when they
// crossed the threshold (vph = size > 0), never divide, and inhibit their
// neighbours through patS, so no two are adjacent. A cell that is not a
// heterocyst divides as soon as it reaches lm, so it is always shorter than lm.
TEST(ExampleAnabaena, FilamentGrowsWithSpacedHeterocysts) {
  Stepper run(model("anabaena"));
  std::size_t previous = 2;
  std::vector<std::size_t> counts;
  for (int step = 1; step <= 3000; ++step) {
    run.step();
    std::string text = run.text();
    std::size_t n = 0;
    for (std::size_t p = text.find("Cell("); p != std::string::npos; p = text.find("Cell(", p + 1)) ++n;
    ASSERT_GE(n, previous) << "step " << step;
    previous = n;
    if (step % 1000 != 0) continue;
    counts.push_back(n);
    std::vector<Cell> c = cells(parse_modules(text));
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i].heterocyst()) {
        EXPECT_GT(c[i].vph, 0.0f) << "cell " << i << " step " << step;
      } else {
        EXPECT_LT(c[i].x, kMaxSize) << "cell " << i << " step " << step;
      }
      if (i > 0) {
        EXPECT_FALSE(c[i].heterocyst() && c[i - 1].heterocyst()) << "cells " << i - 1 << "," << i;
      }
    }
    if (step == 3000) {
      int heterocysts = 0;
      for (const Cell& cell : c) heterocysts += cell.heterocyst();
      EXPECT_GT(heterocysts, 0);
    }
  }
  ASSERT_EQ(counts.size(), 3u);
  EXPECT_LT(counts[0], counts[1]);
  EXPECT_LT(counts[1], counts[2]);
}

// ---------------------------------------------------------------------------
// Borchert-Honda (Listing 38), re-implemented here on a tree of internodes:
// every time unit is three steps, (1) counting apices from the tips (a branch
// internode supports the apices of its lateral and main daughters), (2) flux
// from the base, BaseFlux(k) at the base and parent flux * Flux(...) above it,
// (3) growth. In the growth step the derivation is still forward from step 2,
// so the new left context also refreshes the fluxes (the base sees N(k+1)),
// while an apex branches on its parent's OLD flux (old left context).
const float kSigma0 = 17.0f, kEta = 0.89f, kVth = 5.0f, kLambda = 0.7f;
enum { kBase = 0, kStr = 1, kLat = 2 };

float base_flux(int age) {
  return static_cast<float>(kSigma0 * std::pow(2.0, (age - 1) * std::pow(static_cast<double>(kEta), age)));
}
float flux_factor(int count, int pcount, int st) {
  if (st == kLat) return static_cast<float>((1 - kLambda) * (1.0 * count / (pcount - count)));
  return static_cast<float>(1 - (1 - kLambda) * (1.0 * (pcount - count) / count));
}

struct Internode {
  int st;
  float flux;
  int count;
  int lat = -1, main = -1;  // daughters; -1: an apex follows
};

struct BorchertHonda {
  std::vector<Internode> nodes{{kBase, 0.0f, 1}};
  int n = 1;  // the parameter of N

  void step(int s) {
    if ((s - 1) % 3 == 0) count(0);
    if ((s - 1) % 3 == 1) distribute(0, -1);
    if ((s - 1) % 3 == 2) grow();
  }
  int count(int i) {
    if (nodes[i].lat >= 0) nodes[i].count = count(nodes[i].lat) + count(nodes[i].main);
    return nodes[i].count;
  }
  void distribute(int i, int parent) {
    Internode& x = nodes[i];
    x.flux = parent < 0 ? base_flux(n) : nodes[parent].flux * flux_factor(x.count, nodes[parent].count, x.st);
    if (x.lat >= 0) distribute(x.lat, i), distribute(x.main, i);
  }
  void grow() {
    std::vector<Internode> old = nodes;
    ++n;
    distribute(0, -1);
    for (std::size_t i = 0; i < old.size(); ++i) {
      if (old[i].lat >= 0 || !(old[i].flux > kVth)) continue;
      nodes[i].lat = static_cast<int>(nodes.size());
      nodes.push_back({kLat, old[i].flux * (1 - kLambda), 1});
      nodes[i].main = static_cast<int>(nodes.size());
      nodes.push_back({kStr, old[i].flux * kLambda, 1});
    }
  }
  // The string: SetWidth(0.1) N(n) then the tree in preorder.
  void expect_matches(const std::vector<Module>& s, int step) const {
    std::vector<std::string> expected_names = {"SetWidth", "N"};
    std::vector<const Internode*> order;
    render(0, expected_names, order);
    ASSERT_EQ(names(s), expected_names) << "step " << step;
    EXPECT_EQ(s[1].params, std::vector<std::string>{std::to_string(n)});
    std::size_t k = 0;
    for (const Module& m : s) {
      const std::vector<std::string> angle = {m.name == "RollR" ? "180" : m.name == "Right" ? "32" : "10"};
      if (m.name == "RollR" || m.name == "Right" || m.name == "Left") {
        EXPECT_EQ(m.params, angle);
      }
      if (m.name != "I") continue;
      const Internode& x = *order[k++];
      EXPECT_EQ(number(field(m.params[0], "st")), x.st) << "step " << step << " I #" << k;
      EXPECT_EQ(number(field(m.params[0], "count")), x.count) << "step " << step << " I #" << k;
      EXPECT_FLOAT_EQ(float_number(field(m.params[0], "flux")), x.flux) << "step " << step << " I #" << k;
    }
  }
  void render(int i, std::vector<std::string>& out, std::vector<const Internode*>& order) const {
    out.push_back("I");
    order.push_back(&nodes[i]);
    if (nodes[i].lat < 0) return out.push_back("A");
    out.insert(out.end(), {"RollR", "SB", "Right"});
    render(nodes[i].lat, out, order);
    out.insert(out.end(), {"EB", "Left"});
    render(nodes[i].main, out, order);
  }
};

// First time unit by hand: step 2 gives the base BaseFlux(1) = 17; step 3
// branches (17 > vth = 5) into a lateral with 17 * 0.3 = 5.1 and a main
// internode with 17 * 0.7 = 11.9, and the base gets BaseFlux(2) =
// 17 * 2^(0.89^2) = 29.44.
TEST(ExampleBorchertHonda, FirstTimeUnitByHand) {
  Stepper run(model("borchert-honda"));
  run.step(2);
  EXPECT_FLOAT_EQ(float_number(field(run.modules()[2].params[0], "flux")), 17.0f);
  run.step();
  std::vector<Module> s = run.modules();
  ASSERT_EQ(names(s), (std::vector<std::string>{"SetWidth", "N", "I", "RollR", "SB", "Right", "I", "A", "EB", "Left",
                                                 "I", "A"}));
  EXPECT_NEAR(number(field(s[2].params[0], "flux")), 29.44, 0.01);
  EXPECT_NEAR(number(field(s[6].params[0], "flux")), 5.1, 1e-5);
  EXPECT_NEAR(number(field(s[10].params[0], "flux")), 11.9, 1e-5);
}

TEST(ExampleBorchertHonda, MatchesAnIndependentReimplementation) {
  Stepper run(model("borchert-honda"));
  BorchertHonda tree;
  std::vector<int> apices;
  for (int s = 0; s <= 36; ++s) {
    if (s > 0) run.step(), tree.step(s);
    std::vector<Module> m = run.modules();
    tree.expect_matches(m, s);
    if (s % 3 == 0) apices.push_back(count_named(m, "A"));
  }
  // Apices after each growth step: the branching slows down as flux is shared.
  EXPECT_EQ(apices.front(), 1);
  EXPECT_EQ(apices[1], 2);
  for (std::size_t i = 1; i < apices.size(); ++i) EXPECT_LE(apices[i] - apices[i - 1], apices[i - 1]);
}

// After a counting or flux step (not growth) every internode's count is the
// number of apices above it, so the base's count is the number of A's.
TEST(ExampleBorchertHonda, CountAtTheBaseIsTheNumberOfApices) {
  Stepper run(model("borchert-honda"));
  for (int s = 1; s <= 36; ++s) {
    run.step();
    if (s % 3 == 0) continue;
    std::vector<Module> m = run.modules();
    std::vector<int> counts;
    for (const Module& i : m)
      if (i.name == "I") counts.push_back(static_cast<int>(number(field(i.params[0], "count"))));
    EXPECT_EQ(counts.front(), count_named(m, "A")) << "step " << s;
    EXPECT_EQ(counts, apices_above_I(m)) << "step " << s;
  }
}

// ---------------------------------------------------------------------------
// Appendix A.6.11. Each decomposition level turns A(n) into F(1) A(n-1), so d
// levels make F(1)^d A(5-d); A(0) produces nothing. With maximum depth 6 the
// axiom is fully decomposed before any step: five F(1) and A(0) (the thesis:
// "will generate five modules F(1)"). With depth 4 the axiom stops at A(1) and
// the decomposition after step 1 finishes it; with the default depth (1) one
// level is done after the axiom and one after every step.
std::string fs_then_a(int fs, int a) {
  std::string s;
  for (int i = 0; i < fs; ++i) s += "F(1) ";
  return s + "A(" + std::to_string(a) + ")";
}

// The thesis (section 4.6): "If the maximum depth is reached during the
// execution of a program then a run-time warning message will be printed."
// Depth 6 is enough here (the sixth level is A(0), which produces nothing).
TEST(ExampleDecompositionDepth, DepthSixGivesFiveF) {
  EXPECT_EQ(derive_string(model("decomposition-depth")), fs_then_a(5, 0));
  Stepper run(model("decomposition-depth"));
  EXPECT_EQ(run.text(), fs_then_a(5, 0));
  EXPECT_EQ(run.messages, "");
}

TEST(ExampleDecompositionDepth, SmallerDepthsFinishInLaterSteps) {
  std::string text = read_text(model("decomposition-depth"));
  std::string line = "maximum depth: 6;";
  ASSERT_NE(text.find(line), std::string::npos);
  std::string dir = make_temp_dir("example-decomposition-depth");
  std::string depth4 = dir + "/depth4.l", depth_default = dir + "/default.l";
  std::ofstream(depth4) << std::string(text).replace(text.find(line), line.size(), "maximum depth: 4;");
  std::ofstream(depth_default) << std::string(text).replace(text.find(line), line.size(), "");

  Stepper run4(depth4);
  EXPECT_EQ(run4.text(), fs_then_a(4, 1));
  EXPECT_NE(run4.messages.find("depth"), std::string::npos) << run4.messages;
  run4.step();
  EXPECT_EQ(run4.text(), fs_then_a(5, 0));

  Stepper run1(depth_default);
  for (int k = 0; k <= 5; ++k) {
    EXPECT_EQ(run1.text(), fs_then_a(std::min(k + 1, 5), std::max(4 - k, 0))) << "step " << k;
    run1.step();
  }
}

// ---------------------------------------------------------------------------
// Koch curve (section 9.1.1): F -> F+F--F+F, i.e. F(1) Left(60) F(1)
// Right(120) F(1) Left(60) F(1). After n steps: 4^n F's, 2 Left and 1 Right
// per generator applied (1 + 4 + ... + 4^(n-1) of them).
TEST(ExampleKoch, MatchesStringRewritingInPlainCpp) {
  const std::vector<std::string> generator = {"F(1)", "Left(60)", "F(1)", "Right(120)", "F(1)", "Left(60)", "F(1)"};
  std::vector<std::string> word = {"F(1)"};
  for (int n = 0; n <= 4; ++n) {
    std::string expected;
    for (const std::string& w : word) expected += (expected.empty() ? "" : " ") + w;
    std::vector<Module> m = parse_modules(derive_string(model("koch"), n));
    EXPECT_EQ(derive_string(model("koch"), n), expected) << "step " << n;
    int fs = count_named(m, "F");
    EXPECT_EQ(fs, 1 << (2 * n));
    EXPECT_EQ(count_named(m, "Left"), 2 * (fs - 1) / 3);
    EXPECT_EQ(count_named(m, "Right"), (fs - 1) / 3);

    std::vector<std::string> next;
    for (const std::string& w : word) {
      if (w == "F(1)") next.insert(next.end(), generator.begin(), generator.end());
      else next.push_back(w);
    }
    word = next;
  }
}

// The turn (Left +, Right -) between consecutive F's, without a turtle.
std::vector<int> turns_between_fs(const std::vector<Module>& m) {
  std::vector<int> turns;
  int turn = 0;
  bool seen_f = false;
  for (const Module& x : m) {
    if (x.name == "Left") turn += static_cast<int>(number(x.params[0]));
    if (x.name == "Right") turn -= static_cast<int>(number(x.params[0]));
    if (x.name == "F") {
      if (seen_f) turns.push_back(turn);
      seen_f = true, turn = 0;
    }
  }
  return turns;
}

// Every generator turns +60, -120, +60 (sum 0 mod 360, so a generator leaves
// the heading unchanged); the turns joining generator j to j+1 at step n are
// the turns of step n-1 between its F's j and j+1; all turns sum to 0.
TEST(ExampleKoch, GeneratorTurnsCancel) {
  std::vector<int> previous;  // step 0: one F, no turns
  for (int n = 1; n <= 4; ++n) {
    std::vector<int> turns = turns_between_fs(parse_modules(derive_string(model("koch"), n)));
    ASSERT_EQ(turns.size(), (1u << (2 * n)) - 1);
    int total = 0;
    for (std::size_t g = 0; 4 * g < turns.size(); ++g) {
      EXPECT_EQ(turns[4 * g], 60);
      EXPECT_EQ(turns[4 * g + 1], -120);
      EXPECT_EQ(turns[4 * g + 2], 60);
      EXPECT_EQ((turns[4 * g] + turns[4 * g + 1] + turns[4 * g + 2]) % 360, 0);
      if (4 * g + 3 < turns.size()) {
        EXPECT_EQ(turns[4 * g + 3], previous[g]) << "step " << n;
      }
    }
    for (int t : turns) total += t;
    EXPECT_EQ(total, 0) << "step " << n;
    previous = turns;
  }
}

}  // namespace
}  // namespace sylva::test::examples
