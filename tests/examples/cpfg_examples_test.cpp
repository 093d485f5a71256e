// Tests of the branching, signalling, fractal and stochastic examples in
// examples/cpfg/ (the cpfg models of the course notes and the CPFG manual's
// own examples). Every expectation is worked out by hand from the text or
// computed here a second way in plain C++ (string generators, tree walks, a
// turtle walk in the plane, frequency counts); none is a recorded output of
// the program.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "examples/cpfg_examples.h"

namespace sylva::test::cpfg_examples {
namespace {

using examples::Stepper;

std::string repeat(const std::string& word, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += word;
  return out;
}

// Index of the ']' that closes the '[' at `open`.
std::size_t closing(const std::vector<CpfgModule>& s, std::size_t open) {
  int level = 0;
  for (std::size_t j = open; j < s.size(); ++j) {
    if (s[j].name == '[') ++level;
    if (s[j].name == ']' && --level == 0) return j;
  }
  return s.size();
}

// The branches that start on the main axis, in order from the base: the
// modules between each top-level '[' and its ']'.
std::vector<std::vector<CpfgModule>> top_branches(const std::vector<CpfgModule>& s) {
  std::vector<std::vector<CpfgModule>> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].name != '[') continue;
    const std::size_t end = closing(s, i);
    out.emplace_back(s.begin() + static_cast<long>(i) + 1, s.begin() + static_cast<long>(end));
    i = end;
  }
  return out;
}

// ---------------------------------------------------------------------------
// Mesotonic D0L (Section 6.4). The pair of branches made in step i+1 carries
// B(i); it then gains one F per step until B reaches 0. After n steps it has
// had n-1-i further steps, so its length is 1 + min(i, n-1-i) F's: largest in
// the middle of the axis (mesotonic). The main axis has n+1 F's.
TEST(CpfgExampleMesotonic, BranchLengthsRiseThenFall) {
  for (int n : {1, 2, 5, 10}) {
    const std::vector<CpfgModule> s = parse_cpfg(derive_string(model("mesotonic-d0l"), n));
    const auto branches = top_branches(s);
    ASSERT_EQ(branches.size(), static_cast<std::size_t>(2 * n));
    for (int i = 0; i < n; ++i)
      for (int side = 0; side < 2; ++side)
        EXPECT_EQ(count(branches[2 * i + side], 'F'), 1 + std::min(i, n - 1 - i)) << "n " << n << " pair " << i;
    int axis = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i].name == '[') i = closing(s, i);
      else axis += s[i].name == 'F';
    }
    EXPECT_EQ(axis, n + 1);
  }
}

// Mesotonic structure by a signal (Section 7.1). The apex makes a branch and
// an internode every m = 3 steps: after n steps 1 + n/3 main internodes and
// n/3 branches. Branches whose apex B the signal has removed are finished,
// and the lower ones had less time to grow: their lengths do not decrease
// upwards (Fig. 12).
TEST(CpfgExampleMesotonic, SignalStopsLowerBranchesFirst) {
  for (int n : {12, 24, 36, 48, 60}) {
    const std::vector<CpfgModule> s = parse_cpfg(derive_string(model("mesotonic-signal"), n));
    const auto branches = top_branches(s);
    EXPECT_EQ(branches.size(), static_cast<std::size_t>(n / 3)) << n;
    int axis = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i].name == '[') i = closing(s, i);
      else axis += s[i].name == 'F';
    }
    EXPECT_EQ(axis, 1 + n / 3) << n;
    int previous = 0, finished = 0;
    for (const auto& b : branches) {
      if (count(b, 'B') > 0) continue;
      EXPECT_GE(count(b, 'F'), previous) << "after " << n << " steps";
      previous = count(b, 'F');
      ++finished;
    }
    if (n >= 36) {
      EXPECT_GT(finished, 0);
    }
  }
}

// ---------------------------------------------------------------------------
// Insect attack (Section 7.2). W(40) counts down to W(0) in 40 steps and
// becomes the insect U in step 41, at the base. By step 120 the insect has
// traversed the structure and eaten every apex: no A, no insect (U, D), no
// marker L or R, no W. The main axis has l_L + 1 = 4 segments F before its
// branching point, grown by step 24 (one F per d+1 = 6 steps), before the
// insect arrives.
TEST(CpfgExampleInsect, InsectAppearsAfterTheDelayAndEatsEveryApex) {
  Stepper run(model("insect-attack"));
  run.step(40);
  std::vector<CpfgModule> s = parse_cpfg(run.text());
  EXPECT_EQ(count(s, 'U') + count(s, 'D'), 0);
  EXPECT_EQ(s.at(0).name, 'W');
  EXPECT_EQ(s.at(0).params.at(0), 0);
  run.step();
  s = parse_cpfg(run.text());
  EXPECT_EQ(s.at(0).name, 'U');
  run.step(79);
  s = parse_cpfg(run.text());
  for (char gone : {'A', 'U', 'D', 'L', 'R', 'W'}) EXPECT_EQ(count(s, gone), 0) << gone << " in " << run.text();
  int axis = 0;
  for (std::size_t i = 0; i < s.size() && s[i].name != '['; ++i) axis += s[i].name == 'F';
  EXPECT_EQ(axis, 4);
  // growth before the insect arrives: main axis F F F F L [ + F ... ] [ - F ... ] at step 24
  EXPECT_EQ(derive_string(model("insect-attack"), 24), "W(16)FFFFL[+FA(3,5)][-FA(5,5)]");
}

// ---------------------------------------------------------------------------
// Borchert-Honda resource allocation (Section 7.3). At the start of cycle k
// (a flux message m = 1 in the base internode) the base receives the flux
// v = sigma0 * 2^((k-1) eta^k) (the closed form of the text). At the end of
// the fifth cycle (step 35): the apex count c of every internode is the
// number of apices A in its subtree (a tree walk), and at every branching
// point the flux is split without loss: v = v_lateral + v_straight.
struct Internode {
  std::size_t at;
  double v, c;
};

TEST(CpfgExampleResourceAllocation, FluxFollowsTheFormulaAndIsConserved) {
  Stepper run(model("resource-allocation"));
  int cycles = 0;
  for (int step = 1; step <= 35; ++step) {
    run.step();
    const std::vector<CpfgModule> s = parse_cpfg(run.text());
    ASSERT_EQ(s.at(1).name, 'I');
    if (s.at(1).params.at(1) != 1) continue;  // no flux message at the base
    const int k = ++cycles;
    EXPECT_EQ(s.at(0).params.at(0), k + 1) << "N counts the cycles";
    const double flux = 17 * std::pow(2.0, (k - 1) * std::pow(0.89, k));
    EXPECT_NEAR(s.at(1).params.at(2), flux, 1e-4 * flux) << "cycle " << k << " at step " << step;
  }
  EXPECT_EQ(cycles, 5);
  const std::vector<CpfgModule> s = parse_cpfg(run.text());
  int checked_counts = 0, checked_splits = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].name != 'I') continue;
    // subtree of the internode: the modules after it up to the end of its branch
    int apices = 0, level = 0;
    std::size_t j = i + 1;
    for (; j < s.size(); ++j) {
      if (s[j].name == '[') ++level;
      if (s[j].name == ']' && level-- == 0) break;
      apices += s[j].name == 'A';
    }
    EXPECT_EQ(s[i].params.at(3), apices) << "internode at " << i;
    ++checked_counts;
    // a branching point: I / [ - I(lateral) ... ] + I(straight)
    std::size_t k = i + 1;
    while (k < s.size() && s[k].name == '/') ++k;
    if (k < s.size() && s[k].name == '[') {
      std::size_t lateral = k + 1;
      while (s[lateral].name != 'I') ++lateral;
      std::size_t straight = closing(s, k) + 1;
      while (s[straight].name != 'I') ++straight;
      const double v = s[i].params.at(2), sum = s[lateral].params.at(2) + s[straight].params.at(2);
      EXPECT_NEAR(sum, v, 1e-3 * v) << "branching at " << i;
      ++checked_splits;
    }
  }
  EXPECT_EQ(s.at(0).name, 'N');
  EXPECT_GT(checked_splits, 3);
  EXPECT_GT(checked_counts, 10);
}

// ---------------------------------------------------------------------------
// Shedding (Section 6.5), generated by hand: after n steps the main axis is
// n internodes F(1) and A; the pair of branches made in step k is X(3)B and
// then, one step older each time, X(2)F(1)B, X(1)F(1)F(1)B, X(0)F(1)F(1)F(1)B,
// U%F(1)F(1)F(1)F(1)B, and from age 5 on the cut has removed the branch and U
// left the scar F(0.3).
std::string shedding_by_hand(int n) {
  std::string out;
  for (int k = 1; k <= n; ++k) {
    const int age = n - k;
    std::string branch;
    if (age <= 3) branch = "X(" + std::to_string(3 - age) + ")" + repeat("F(1)", age) + "B";
    else if (age == 4) branch = "U%" + repeat("F(1)", 4) + "B";
    else branch = "F(0.3)";
    out += "F(1)[-" + branch + "][+" + branch + "]";
  }
  return out + "A";
}

TEST(CpfgExampleShedding, CrownOfConstantSizeMovesUp) {
  Stepper run(model("shedding"));
  for (int n = 0; n <= 9; ++n) {
    EXPECT_EQ(run.text(), shedding_by_hand(n)) << "after step " << n;
    // dynamic equilibrium: from step 5 on, 5 pairs of living branches
    if (n >= 5) {
      EXPECT_EQ(count(parse_cpfg(run.text()), 'B'), 10);
    }
    run.step();
  }
}

// The cut rule by hand: a % removes the rest of its branch up to the ']' that
// closes it. In a[b%[cd[e%f]]g[h%i]j]k the first % is in the branch [b...j],
// so everything after it in that branch goes: a[b]k. (The notes print
// a[b]g[h][j]k, which does not follow from the rule they state.)
TEST(CpfgExampleCut, CutRemovesTheRestOfTheBranch) {
  EXPECT_EQ(derive_string(model("cut-example"), 1), "a[b]k");
}

// ---------------------------------------------------------------------------
// Snowflake (Section 6.1): after n steps 3*4^n segments F(3^-n), and the curve
// is closed: a turtle walk in the plane (+ turns left, - right) returns to its
// start. The signed turns add up to +/-(60+60-120) = 0 per production, so
// their sum stays -240 (the axiom's two -120).
TEST(CpfgExampleSnowflake, SegmentCountLengthAndClosure) {
  for (int n : {0, 1, 2, 3}) {
    const std::vector<CpfgModule> s = parse_cpfg(derive_string(model("snowflake"), n));
    EXPECT_EQ(count(s, 'F'), 3 * static_cast<int>(std::pow(4, n)));
    double x = 0, y = 0, heading = 0, turns = 0;
    for (const CpfgModule& m : s) {
      if (m.name == 'F') {
        EXPECT_NEAR(m.params.at(0), std::pow(3.0, -n), 1e-6);
        x += m.params[0] * std::cos(heading * M_PI / 180);
        y += m.params[0] * std::sin(heading * M_PI / 180);
      }
      if (m.name == '+') heading += m.params.at(0), turns += m.params[0];
      if (m.name == '-') heading -= m.params.at(0), turns -= m.params[0];
    }
    EXPECT_NEAR(x, 0, 1e-5) << n;
    EXPECT_NEAR(y, 0, 1e-5) << n;
    EXPECT_DOUBLE_EQ(turns, -240);
  }
}

// Compound leaf (Section 6.2): an apex F gives two internodes G and three
// apices, so after n steps 3^n apices F(1); the internodes made in step j have
// doubled n-j times: 2*3^(j-1) internodes of length 2^(n-j), j = 1..n.
TEST(CpfgExampleCompoundLeaf, ApicesTripleAndInternodesDouble) {
  for (int n : {1, 2, 5}) {
    const std::vector<CpfgModule> s = parse_cpfg(derive_string(model("compound-leaf"), n));
    EXPECT_EQ(count(s, 'F'), static_cast<int>(std::pow(3, n)));
    for (int j = 1; j <= n; ++j) {
      int with_length = 0;
      for (const CpfgModule& m : s) with_length += m.name == 'G' && m.params.at(0) == std::pow(2, n - j);
      EXPECT_EQ(with_length, 2 * static_cast<int>(std::pow(3, j - 1))) << "n " << n << " j " << j;
    }
    for (const CpfgModule& m : s)
      if (m.name == 'F') {
        EXPECT_EQ(m.params.at(0), 1);
      }
  }
}

// Honda tree, Figure 8a (Section 6.3): min = 0, so every apex branches every
// step: 2^n - 1 internodes and 2^n apices after n steps. An internode at
// branching depth d reached by i straight and d-i lateral turns has length
// 100 r1^i r2^(d-i), so the lengths at depth d add up to 100 (r1+r2)^d. With
// e = 0.4, w1^(1/e) + w2^(1/e) = w^(1/e) (q + 1 - q): the width sums
// w^(2.5) at every depth equal w0^2.5 (da Vinci's rule in the text).
TEST(CpfgExampleHondaTree, CountsLengthsAndDaVinciWidths) {
  const int n = 10;
  const std::vector<CpfgModule> s = parse_cpfg(derive_string(model("honda-tree"), n));
  EXPECT_EQ(count(s, 'F'), (1 << n) - 1);
  EXPECT_EQ(count(s, 'A'), 1 << n);
  std::vector<double> lengths(n, 0), widths(n, 0);
  int depth = 0;
  double width = 0;
  for (const CpfgModule& m : s) {
    if (m.name == '[') ++depth;
    if (m.name == ']') --depth;
    if (m.name == '!') width = m.params.at(0);
    if (m.name == 'F') lengths.at(depth) += m.params.at(0), widths.at(depth) += std::pow(width, 2.5);
  }
  for (int d = 0; d < n; ++d) {
    const double expected = 100 * std::pow(0.75 + 0.77, d);
    EXPECT_NEAR(lengths[d], expected, 1e-4 * expected) << "depth " << d;
    EXPECT_NEAR(widths[d], std::pow(30, 2.5), 1e-3 * std::pow(30, 2.5)) << "depth " << d;
  }
}

// ---------------------------------------------------------------------------
// Light-competition tree without an environment. The apex waits Del = 30
// steps (A(vig,del) counts del), and the leaf asks for light (?E) in the step
// where its delay reaches Del-1: after k <= 28 steps the string is the axiom
// with A(1,k) and L(1,8,0,k); in step 30 (del == Del-1 at its start)
// ?E(vig*0.5) = ?E(0.5) follows L.
// From step 1 the basal width module carries p10's balance: w = (0^2 +
// 0.02^2)^0.5 = 0.02, p = 0 + 0 + 8 - 0.32 (w/W)^1.5 = 7.68, n = 0 + 1.
TEST(CpfgExampleLightCompetition, ApexAndLeafCountTheDelay) {
  Stepper run(model("light-competition-tree"));
  for (int k = 0; k <= 29; ++k) {
    const std::string ks = std::to_string(k);
    const std::string expected = std::string(k == 0 ? "!(0.02,1,1)" : "!(0.02,7.68,1)") + "F(2)L(1,8,0," + ks + ")A(1," + ks +
                                 ")[!(0,0,0)]!(0.02,0,1)";
    EXPECT_EQ(run.text(), expected) << "after step " << k;
    run.step();
  }
  EXPECT_NE(run.text().find("L(1,8,0,30)?E(0.5)A(1,30)"), std::string::npos) << run.text();
}

// ---------------------------------------------------------------------------
// The stochastic example of the open L-systems paper. p3 is deterministic:
// in step 1 B(3) between A(1) and A(5) always becomes B(6)[A(3)]. p1 and p2
// choose A(x+1) with probability 0.4 and B(x-1) with 0.6: with 2000 A(1) in
// the axiom one step gives about 800 A(2) (within 5 standard deviations,
// sqrt(2000*0.4*0.6) = 22); with any seed A(1) becomes A(2) or B(0).
TEST(CpfgExampleStochastic, FrequenciesApproachTheProbabilities) {
  Stepper many(modified_copy("stochastic", {{"Axiom: A(1)B(3)A(5)", "Axiom: " + repeat("A(1)", 2000)}}, "stochastic-many"));
  many.step();
  const std::vector<CpfgModule> s = parse_cpfg(many.text());
  ASSERT_EQ(s.size(), 2000u);
  const int a = count(s, 'A');
  EXPECT_EQ(a + count(s, 'B'), 2000);
  EXPECT_NEAR(a, 800, 110);
  // cpfg in batch never seeds drand48 (the string does not depend on the
  // seed: value); whatever the seed, A(1) becomes A(2) or B(0).
  for (int i = 0; i < 12; ++i) {
    const int seed = 1 + 5003 * i;
    Stepper run(modified_copy("stochastic", {{"seed: 1", "seed: " + std::to_string(seed)}}, "stochastic-seed"));
    run.step();
    const std::string text = run.text();
    EXPECT_NE(text.find("B(6)[A(3)]"), std::string::npos) << text;
    EXPECT_TRUE(text.rfind("A(2)", 0) == 0 || text.rfind("B(0)", 0) == 0) << text;
  }
}

// ---------------------------------------------------------------------------
// The CPFG manual's examples.

// Homomorphism (4.3): A -> I[+A][-A]IA, I -> II. Apices triple: a(n) = 3^n;
// internodes i(n) = 2 i(n-1) + 2 a(n-1). The homomorphism draws A as ;F and
// I as F and does not change the derived string.
TEST(CpfgExampleManual, HomomorphismCountsAndDrawing) {
  Stepper run(model("manual-homomorphism"));
  long a = 1, i = 0;
  for (int n = 1; n <= 4; ++n) {
    run.step();
    i = 2 * i + 2 * a;
    a = 3 * a;
    const std::vector<CpfgModule> s = parse_cpfg(run.text()), drawn = parse_cpfg(run.interpreted());
    EXPECT_EQ(count(s, 'A'), a) << n;
    EXPECT_EQ(count(s, 'I'), i) << n;
    EXPECT_EQ(count(drawn, 'A') + count(drawn, 'I'), 0);
    EXPECT_EQ(count(drawn, ';'), a);
    EXPECT_EQ(count(drawn, 'F'), a + i);
  }
  EXPECT_EQ(derive_string(model("manual-homomorphism"), 1), "I[+A][-A]IA");
}

// Stochastic (4.5): whichever production is chosen, every step triples the
// F's and adds one branch per old F.
TEST(CpfgExampleManual, StochasticTriplesTheSegments) {
  Stepper run(model("manual-stochastic"));
  for (int n = 1; n <= 3; ++n) {
    run.step();
    const std::vector<CpfgModule> s = parse_cpfg(run.text());
    EXPECT_EQ(count(s, 'F'), static_cast<int>(std::pow(3, n)));
    EXPECT_EQ(count(s, '['), (static_cast<int>(std::pow(3, n)) - 1) / 2);
  }
}

// Cut (6.4): D(1) ages to D(20) in 19 steps, becomes % in step 20, and the %
// cuts the rest of its branch in step 21, leaving the empty branch.
TEST(CpfgExampleManual, BranchIsCutAtAgeTwenty) {
  Stepper run(model("manual-cut"));
  run.step(19);
  EXPECT_EQ(run.text(), "F[D(20)]F");
  run.step();
  EXPECT_EQ(run.text(), "F[%]F");
  run.step();
  EXPECT_EQ(run.text(), "F[]F");
  EXPECT_EQ(derive_string(model("manual-cut")), "F[]F");
}

// Derivation length (9.2): A counts the 50 steps and adds a B in each step
// that starts with x >= 40, i.e. the last 10: A(50) and ten B's.
TEST(CpfgExampleManual, DerivationLengthDefine) {
  EXPECT_EQ(derive_string(model("manual-derivation-length")), "A(50)" + repeat("B", 10));
  EXPECT_EQ(derive_string(model("manual-derivation-length"), 41), "A(41)B");
}

}  // namespace
}  // namespace sylva::test::cpfg_examples
