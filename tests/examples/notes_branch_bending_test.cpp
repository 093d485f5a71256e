// The course notes' biomechanics in examples/: a branch bending under its own
// weight, against Euler-Bernoulli's cantilever and the elastica (notes_numerical.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "examples/notes_numerical.h"

namespace sylva::test::examples {
namespace {

using notes::field_of;
using notes::model;
using notes::params_of;

// ---------------------------------------------------------------------------
// The branch bending under its own weight (branch-bending.l): the defaults.
namespace bb {
const double kLength = 2.0, kRadius = 0.01, kYoung = 1e10, kDensity = 800, kGravity = 9.81;
const int kSegments = 20;
const double kEI = kYoung * M_PI * std::pow(kRadius, 4) / 4;
const double kQ = kDensity * kGravity * M_PI * kRadius * kRadius;  // weight per unit length

// Euler-Bernoulli cantilever under a uniform load q:
// w(x) = q x^2 (6 L^2 - 4 L x + x^2) / (24 E I), w(L) = q L^4 / (8 E I).
double deflection(double x, double load) {
  return load * kQ * x * x * (6 * kLength * kLength - 4 * kLength * x + x * x) / (24 * kEI);
}

struct Node {
  double x, y;
};

std::vector<Node> tips(const std::string& text) {
  std::vector<Node> out;
  for (const Module& m : parse_modules(text))
    if (m.name == "I") out.push_back({field_of(m.params.at(0), "x"), field_of(m.params.at(0), "y")});
  return out;
}
}  // namespace bb

// The tip sinks by q L^4 / (8 E I) (6.3 cm), and every node lies on the
// elastic curve, within 1% of the tip deflection.
TEST(NotesBranchBending, SmallLoadFollowsEulerBernoulli) {
  std::vector<bb::Node> n = bb::tips(derive_string(model("branch-bending")));
  ASSERT_EQ(n.size(), static_cast<std::size_t>(bb::kSegments));
  const double w_tip = bb::deflection(bb::kLength, 1.0);
  EXPECT_NEAR(w_tip, 0.0625, 0.001);  // a small load: 3% of the length
  EXPECT_NEAR(-n.back().y, w_tip, 0.02 * w_tip);
  for (int i = 0; i < bb::kSegments; ++i) {
    double s = (i + 1) * bb::kLength / bb::kSegments;
    EXPECT_NEAR(-n[i].y, bb::deflection(s, 1.0), 0.01 * w_tip) << "node " << i + 1;
  }
}

// Doubling the load (and halving it) scales the deflection by the same factor,
// up to the second-order effect of the shortened lever arms.
TEST(NotesBranchBending, DeflectionIsLinearInTheLoad) {
  double tip1 = -bb::tips(derive_string(model("branch-bending"))).back().y;
  double tip2 = -bb::tips(derive_with(model("branch-bending"), 10, {"LOAD=2"})).back().y;
  double tip_half = -bb::tips(derive_with(model("branch-bending"), 10, {"LOAD=0.5"})).back().y;
  EXPECT_NEAR(tip2 / tip1, 2.0, 0.01);
  EXPECT_NEAR(tip_half / tip1, 0.5, 0.0025);
  EXPECT_NEAR(-bb::tips(derive_with(model("branch-bending"), 10, {"LOAD=0.5"})).back().y, bb::deflection(2.0, 0.5),
              0.02 * bb::deflection(2.0, 0.5));
}

// The internodes keep their length (the rod is inextensible), and with no load
// the branch stays straight.
TEST(NotesBranchBending, InternodesKeepTheirLength) {
  std::vector<bb::Node> n = bb::tips(derive_with(model("branch-bending"), 10, {"LOAD=20"}));
  ASSERT_EQ(n.size(), static_cast<std::size_t>(bb::kSegments));
  bb::Node previous{0, 0};
  for (const bb::Node& node : n) {
    EXPECT_NEAR(std::hypot(node.x - previous.x, node.y - previous.y), bb::kLength / bb::kSegments, 1e-12);
    previous = node;
  }
  std::vector<bb::Node> straight = bb::tips(derive_with(model("branch-bending"), 10, {"LOAD=0"}));
  EXPECT_EQ(straight.back().y, 0.0);
  EXPECT_NEAR(straight.back().x, bb::kLength, 1e-12);
}

// A heavy branch (50 times the weight, tip deflection 3.1 m by the linear
// theory, longer than the branch) against the large-deflection equilibrium
// solved here by shooting: theta' = -M / EI, M' = -q (L - s) cos(theta),
// theta(0) = 0, M(L) = 0, integrated by RK4 from the base, with the base
// moment M(0) found by bisection.
TEST(NotesBranchBending, HeavyLoadReachesTheElastica) {
  const double load = 50, q = load * bb::kQ, L = bb::kLength;
  auto shoot = [&](double m0, double* x, double* y) {
    const int n = 2000;
    const double h = L / n;
    double th = 0, m = m0;
    *x = *y = 0;
    auto dth = [&](double mm) { return -mm / bb::kEI; };
    auto dm = [&](double s, double t) { return -q * (L - s) * std::cos(t); };
    for (int i = 0; i < n; ++i) {
      const double s = i * h;
      const double t1 = dth(m), m1 = dm(s, th);
      const double t2 = dth(m + h / 2 * m1), m2 = dm(s + h / 2, th + h / 2 * t1);
      const double t3 = dth(m + h / 2 * m2), m3 = dm(s + h / 2, th + h / 2 * t2);
      const double t4 = dth(m + h * m3), m4 = dm(s + h, th + h * t3);
      const double th_end = th + h / 6 * (t1 + 2 * t2 + 2 * t3 + t4), th_mid = th + h / 2 * t2;
      *x += h / 6 * (std::cos(th) + 4 * std::cos(th_mid) + std::cos(th_end));  // Simpson
      *y += h / 6 * (std::sin(th) + 4 * std::sin(th_mid) + std::sin(th_end));
      th = th_end;
      m += h / 6 * (m1 + 2 * m2 + 2 * m3 + m4);
    }
    return m;  // M(L), 0 at the solution
  };
  double lo = 0, hi = q * L * L / 2, x, y;  // M(0) lies between 0 and the straight branch's
  ASSERT_LT(shoot(lo, &x, &y), 0);
  ASSERT_GT(shoot(hi, &x, &y), 0);
  for (int i = 0; i < 100; ++i) (shoot((lo + hi) / 2, &x, &y) > 0 ? hi : lo) = (lo + hi) / 2;
  shoot(lo, &x, &y);

  std::vector<bb::Node> n =
      bb::tips(derive_with(model("branch-bending"), 80, {"LOAD=50", "RELAX=0.5", "ITERATIONS=40"}));
  ASSERT_EQ(n.size(), static_cast<std::size_t>(bb::kSegments));
  EXPECT_NEAR(n.back().x, x, 0.002);  // 1.17 m
  EXPECT_NEAR(n.back().y, y, 0.002);  // -1.50 m
  EXPECT_LT(-n.back().y, 0.5 * bb::deflection(L, load));
}

}  // namespace
}  // namespace sylva::test::examples
