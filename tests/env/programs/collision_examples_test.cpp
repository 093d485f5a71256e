// The collision examples (examples/env/): sylva runs each model with its .e
// file and built-in program; the free and stopped tips after each step are
// compared with a simulation written here, on integer lattices (Sierpinski,
// Ulam) or with plain trigonometry and a comparison of all pairs (branch
// tiers), sharing no code with the turtle or the programs. As in lpfg, the
// environment answers in a pass before each step: the tips a step makes
// are unanswered (E1(0)) in the string it leaves.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace sylva::test {
namespace {

struct TipCounts {
  int free = 0;     // E1(0) in the lattice models, E1(1) for honda81
  int stopped = 0;  // any other E1 value
  bool operator==(const TipCounts&) const = default;
};

std::ostream& operator<<(std::ostream& out, const TipCounts& c) {
  return out << c.free << " free, " << c.stopped << " stopped";
}

// E1 modules of the final string with value `free_value`, and the others.
TipCounts run_example(const std::string& name, int steps, const std::string& free_value) {
  std::string folder = example_path("env/" + name + "/");
  ProcessResult run = run_sylva({"run", folder + name + ".l", folder + name + ".e", "--steps", std::to_string(steps)});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  TipCounts counts;
  std::istringstream words(run.out);
  std::string word;
  while (words >> word) {
    if (word.rfind("E1(", 0) != 0) continue;
    if (word == "E1(" + free_value + ")")
      ++counts.free;
    else
      ++counts.stopped;
  }
  return counts;
}

// A communication module on a lattice: its point, heading (index into the
// lattice's unit steps), the sense of its left (+1, or -1 after a roll by
// 180 degrees), and the value the environment answered (0 = free).
struct LatticeTip {
  int x = 0, y = 0, heading = 0, sense = 1, value = 0;
  bool marker = false;  // Ulam's E2 at a point a tip grew from
};

// The density program with a tiny radius: the number of other modules at the
// same point.
void answer_point_collisions(std::vector<LatticeTip>& modules) {
  std::map<std::pair<int, int>, int> at;
  for (const LatticeTip& m : modules) ++at[{m.x, m.y}];
  for (LatticeTip& m : modules)
    if (!m.marker) m.value = at[{m.x, m.y}] - 1;
}

TipCounts count_tips(const std::vector<LatticeTip>& modules) {
  TipCounts counts;
  for (const LatticeTip& m : modules)
    if (!m.marker) (m.value == 0 ? counts.free : counts.stopped)++;
  return counts;
}

TEST(CollisionExamples, SierpinskiMatchesTheTriangularLattice) {
  // Axial coordinates: six unit steps 60 degrees apart, counterclockwise.
  const int step[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  std::vector<LatticeTip> modules = {{}};
  std::vector<TipCounts> expected;
  for (int n = 1; n <= 8; ++n) {
    answer_point_collisions(modules);  // the pass before step n
    std::vector<LatticeTip> next;
    for (const LatticeTip& m : modules) {
      if (m.value != 0) {
        next.push_back(m);
        continue;
      }
      // [F E1(0)]: straight on. Right(60) RollR(180) [F E1(0)]: turned
      // right (against the sense of left), then left and right swap.
      int h1 = m.heading, h2 = ((m.heading - m.sense) % 6 + 6) % 6;
      next.push_back({m.x + step[h1][0], m.y + step[h1][1], h1, m.sense, 0});
      next.push_back({m.x + step[h2][0], m.y + step[h2][1], h2, -m.sense, 0});
    }
    modules = next;
    expected.push_back(count_tips(modules));
  }
  // By hand for the first steps: 2 tips, then 4; the pass before step 3
  // finds the two inner ones at one point.
  EXPECT_EQ(expected[0], (TipCounts{2, 0}));
  EXPECT_EQ(expected[1], (TipCounts{4, 0}));
  EXPECT_EQ(expected[2], (TipCounts{4, 2}));
  for (int n : {1, 2, 3, 5, 8}) EXPECT_EQ(run_example("sierpinski", n, "0"), expected[n - 1]) << "step " << n;
}

TEST(CollisionExamples, UlamMatchesTheSquareLattice) {
  // Headings: 0 up (+y), 1 left (-x), 2 down, 3 right; Left(90) adds 1.
  const int step[4][2] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};
  std::vector<LatticeTip> modules;
  LatticeTip origin;
  origin.marker = true;
  modules.push_back(origin);
  for (int heading : {0, 1, 3, 2}) modules.push_back({step[heading][0], step[heading][1], heading, 1, 0});
  std::vector<TipCounts> expected;
  for (int n = 1; n <= 8; ++n) {
    answer_point_collisions(modules);  // the pass before step n
    std::vector<LatticeTip> next;
    for (const LatticeTip& m : modules) {
      if (m.marker || m.value != 0) {
        next.push_back(m);
        continue;
      }
      LatticeTip marker = m;
      marker.marker = true;
      next.push_back(marker);
      for (int turn : {1, 3, 0}) {  // Left(90), Right(90), straight on
        int h = (m.heading + turn) % 4;
        next.push_back({m.x + step[h][0], m.y + step[h][1], h, 1, 0});
      }
    }
    modules = next;
    expected.push_back(count_tips(modules));
  }
  // By hand: the four tips of the axiom are apart, so step 1 makes 12 tips;
  // the pass before step 2 finds the 4 diagonal neighbours of the origin
  // reached twice each (8 stopped) and the 4 points two steps out once.
  EXPECT_EQ(expected[0], (TipCounts{12, 0}));
  EXPECT_EQ(expected[1], (TipCounts{12, 8}));
  for (int n : {1, 2, 4, 6}) EXPECT_EQ(run_example("ulam", n, "0"), expected[n - 1]) << "step " << n;
}

// Honda's tiers with honda81 (radius 0.6; "3d case: on", since honda81's 2D
// case compares x and z and the tiers lie in the x y plane): the new apices
// of a step compete in the pass before the next; an apex is stopped by
// another new apex at 0.6 or closer whose vigor is equal or higher. The
// string a step leaves holds an E1 for each apex that step made.
TEST(CollisionExamples, BranchTiersMatchAComparisonOfAllApexPairs) {
  const double r1 = 0.94, r2 = 0.87, alpha1 = 24.4, alpha2 = 36.9, phi = 138.5, reach = 0.6;
  struct Apex {
    double x, y, heading, v, vigor;
  };
  auto move = [](double x, double y, double heading, double length) {
    double a = heading * std::numbers::pi / 180;
    return std::pair{x + length * std::cos(a), y + length * std::sin(a)};
  };
  // Headings in degrees from +x; the turtle starts facing +y (90), Right(90)
  // faces +x; Left adds.
  std::vector<Apex> born;
  for (double origin_x : {0.0, 6.0})
    for (int k = 0; k < 5; ++k) {
      double heading = k * phi;
      auto [x, y] = move(origin_x, 0, heading, 1);
      born.push_back({x, y, heading, 1, 1});
    }
  std::vector<int> expected;  // E1 modules after each step
  for (int n = 1; n <= 8; ++n) {
    std::vector<Apex> next;
    for (const Apex& a : born) {
      bool beaten = false;
      for (const Apex& b : born) {
        if (&a == &b) continue;
        double d = std::hypot(a.x - b.x, a.y - b.y);
        ASSERT_GT(std::abs(d - reach), 1e-4) << "a pair too close to the threshold to compare with floats";
        if (d <= reach && b.vigor >= a.vigor) beaten = true;
      }
      if (beaten) continue;
      auto [lx, ly] = move(a.x, a.y, a.heading + alpha2, a.v * r2);
      auto [mx, my] = move(a.x, a.y, a.heading - alpha1, a.v * r1);
      next.push_back({lx, ly, a.heading + alpha2, a.v * r2, r2});
      next.push_back({mx, my, a.heading - alpha1, a.v * r1, r1});
    }
    born = next;
    expected.push_back(static_cast<int>(born.size()));
  }
  EXPECT_EQ(expected[0], 20);  // the first ten apices are far apart
  for (int n : {1, 3, 5, 8}) {
    const TipCounts tips = run_example("branch-tiers", n, "-");
    EXPECT_EQ(tips.free + tips.stopped, expected[n - 1]) << "step " << n;
  }
  // Growth is limited: fewer than the 10 * 2^8 apices of unlimited branching.
  EXPECT_LT(expected[7], 2560);
  EXPECT_LT(expected[7], 2 * expected[6]);
}

}  // namespace
}  // namespace sylva::test
