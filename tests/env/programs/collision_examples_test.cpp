// The collision examples (examples/env/): sylva runs each model with its .e
// file and built-in program; the free and stopped tips after each step are
// compared with a simulation written here, on integer lattices (Sierpinski,
// Ulam) or with plain trigonometry and a comparison of all pairs (branch
// tiers), sharing no code with the turtle or the programs.
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
    answer_point_collisions(next);
    modules = next;
    expected.push_back(count_tips(modules));
  }
  // By hand for the first steps: 2 free; then 4 tips of which the two
  // inner ones meet.
  EXPECT_EQ(expected[0], (TipCounts{2, 0}));
  EXPECT_EQ(expected[1], (TipCounts{2, 2}));
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
    answer_point_collisions(next);
    modules = next;
    expected.push_back(count_tips(modules));
  }
  // By hand: after step 1 the 12 new tips lie at 8 points; the 4 diagonal
  // neighbours of the origin each get 2 tips (stopped), the 4 points two
  // steps out along the axes get 1 (free).
  EXPECT_EQ(expected[0], (TipCounts{4, 8}));
  for (int n : {1, 2, 4, 6}) EXPECT_EQ(run_example("ulam", n, "0"), expected[n - 1]) << "step " << n;
}

// Honda's tiers with honda81 (radius 0.3 in 2D): apices of one step compete;
// an apex is stopped when one of higher vigor is closer than 0.6.
TEST(CollisionExamples, BranchTiersMatchAComparisonOfAllApexPairs) {
  const double r1 = 0.94, r2 = 0.87, alpha1 = 24.4, alpha2 = 36.9, phi = 138.5, reach = 0.6;
  struct Apex {
    double x, y, heading, v, vigor;
    bool active;
  };
  auto move = [](double x, double y, double heading, double length) {
    double a = heading * std::numbers::pi / 180;
    return std::pair{x + length * std::cos(a), y + length * std::sin(a)};
  };
  // Headings in degrees from +x; the turtle starts facing +y (90), Right(90)
  // faces +x; Left adds.
  std::vector<Apex> apices;
  for (double origin_x : {0.0, 6.0})
    for (int k = 0; k < 5; ++k) {
      double heading = k * phi;
      auto [x, y] = move(origin_x, 0, heading, 1);
      apices.push_back({x, y, heading, 1, 1, true});
    }
  std::vector<TipCounts> expected;
  for (int n = 1; n <= 8; ++n) {
    std::vector<Apex> born, next;
    for (const Apex& a : apices) {
      if (!a.active) {
        next.push_back(a);
        continue;
      }
      auto [lx, ly] = move(a.x, a.y, a.heading + alpha2, a.v * r2);
      auto [mx, my] = move(a.x, a.y, a.heading - alpha1, a.v * r1);
      born.push_back({lx, ly, a.heading + alpha2, a.v * r2, r2, true});
      born.push_back({mx, my, a.heading - alpha1, a.v * r1, r1, true});
    }
    TipCounts counts;
    for (Apex& a : born) {
      bool beaten = false;
      for (const Apex& b : born) {
        double d = std::hypot(a.x - b.x, a.y - b.y);
        ASSERT_GT(std::abs(d - reach), 1e-4) << "a pair too close to the threshold to compare with floats";
        if (d < reach && b.vigor > a.vigor) beaten = true;
      }
      a.active = !beaten;
      (beaten ? counts.stopped : counts.free)++;
    }
    next.insert(next.end(), born.begin(), born.end());
    apices = next;
    expected.push_back(counts);
  }
  EXPECT_EQ(expected[0], (TipCounts{20, 0}));  // the first ten apices are far apart
  for (int n : {1, 3, 5, 8}) EXPECT_EQ(run_example("branch-tiers", n, "1"), expected[n - 1]) << "step " << n;
  // Growth is limited: fewer than the 10 * 2^8 apices of unlimited branching.
  EXPECT_LT(expected[7].free + expected[7].stopped, 2560);
}

}  // namespace
}  // namespace sylva::test
