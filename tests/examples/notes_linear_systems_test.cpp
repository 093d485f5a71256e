// The course notes' linear solvers in examples/: the five-diagonal system and
// the RC circuit, compared with Eigen's dense solvers (notes_numerical.h).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "examples/notes_numerical.h"

namespace sylva::test::examples {
namespace {

using notes::field_of;
using notes::model;
using notes::params_of;

// ---------------------------------------------------------------------------
// Five-diagonal systems (five-diagonal.l).
namespace fd {
struct Row {
  double a1, a2, a3, a4, a5, rhs;
};

std::vector<Row> rows(const std::string& text) {
  std::vector<Row> out;
  for (const Module& m : parse_modules(text)) {
    if (m.name != "M") continue;
    const std::string& r = m.params.at(0);
    out.push_back({field_of(r, "a1"), field_of(r, "a2"), field_of(r, "a3"), field_of(r, "a4"), field_of(r, "a5"),
                   field_of(r, "rhs")});
  }
  return out;
}

// The dense matrix of the real rows (the phony first and last rows dropped).
void dense(const std::vector<Row>& r, Eigen::MatrixXd* A, Eigen::VectorXd* b) {
  const int n = static_cast<int>(r.size()) - 2;
  A->setZero(n, n);
  b->resize(n);
  for (int k = 0; k < n; ++k) {
    const Row& row = r[k + 1];
    const double c[5] = {row.a1, row.a2, row.a3, row.a4, row.a5};
    for (int j = 0; j < 5; ++j) {
      int col = k + j - 2;
      if (col >= 0 && col < n) (*A)(k, col) = c[j];
      else EXPECT_EQ(c[j], 0.0) << "row " << k + 1 << " has an entry outside the matrix";
    }
    (*b)(k) = row.rhs;
  }
}

// The model's generator, Knuth's MMIX LCG, restated.
struct Lcg {
  std::uint64_t state;
  double next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  }
};
}  // namespace fd

// The notes' example: after step 2, x = (580, -492, -462, -432, 2099, -1054)/151.
TEST(NotesFiveDiagonal, SolvesTheNotesExample) {
  std::vector<fd::Row> r = fd::rows(derive_string(model("five-diagonal")));
  ASSERT_EQ(r.size(), 8u);
  const double x[6] = {580, -492, -462, -432, 2099, -1054};
  for (int k = 0; k < 6; ++k) {
    const fd::Row& row = r[k + 1];
    EXPECT_NEAR(row.rhs / row.a3, x[k] / 151, 1e-12) << "x" << k + 1;
    EXPECT_EQ(row.a1, 0.0);
    EXPECT_EQ(row.a2, 0.0);
    EXPECT_EQ(row.a4, 0.0);
    EXPECT_EQ(row.a5, 0.0);
  }
}

// The same against Eigen on the notes' matrix written out here, and after the
// forward step: nothing below the diagonal, and back substitution of the
// upper band gives the same solution.
TEST(NotesFiveDiagonal, NotesExampleAgreesWithEigen) {
  Eigen::MatrixXd A(6, 6);
  A << 7, 8, -3, 0, 0, 0,  //
      4, -1, 3, 4, 0, 0,   //
      -1, 0, 1, 0, 1, 0,   //
      0, 1, -2, 1, 0, 0,   //
      0, 0, 1, 2, 3, 4,    //
      0, 0, 0, 2, 4, 6;
  Eigen::VectorXd b(6);
  b << 10, -2, 7, 0, 5, 8;
  Eigen::VectorXd x = A.fullPivLu().solve(b);

  Eigen::MatrixXd A0;
  Eigen::VectorXd b0;
  fd::dense(fd::rows(derive_string(model("five-diagonal"), 0)), &A0, &b0);
  EXPECT_EQ(A0, A);
  EXPECT_EQ(b0, b);

  std::vector<fd::Row> r1 = fd::rows(derive_string(model("five-diagonal"), 1));
  ASSERT_EQ(r1.size(), 8u);
  std::vector<double> y(9, 0.0);  // y[k], k = 1..6, and two zeros past the end
  for (int k = 6; k >= 1; --k) {
    const fd::Row& row = r1[k];
    EXPECT_EQ(row.a1, 0.0);
    EXPECT_EQ(row.a2, 0.0);
    y[k] = (row.rhs - row.a4 * y[k + 1] - row.a5 * y[k + 2]) / row.a3;
  }
  std::vector<fd::Row> r2 = fd::rows(derive_string(model("five-diagonal"), 2));
  for (int k = 1; k <= 6; ++k) {
    EXPECT_NEAR(y[k], x(k - 1), 1e-12) << k;
    EXPECT_NEAR(r2[k].rhs / r2[k].a3, x(k - 1), 1e-12) << k;
  }
}

// A random diagonally dominant system of 50 equations (-D SIZE=50): the rows
// of the axiom are the ones the generator gives, and the solution is Eigen's.
TEST(NotesFiveDiagonal, RandomSystemOfFiftyAgreesWithEigen) {
  const int n = 50;
  const std::uint64_t seed = 7;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b(n);
  fd::Lcg lcg{seed};
  for (int k = 0; k < n; ++k) {
    double c[5];
    for (double& v : c) v = 2 * lcg.next() - 1;  // a1, a2, a4, a5, rhs
    const int cols[4] = {k - 2, k - 1, k + 1, k + 2};
    double off = 0;
    for (int j = 0; j < 4; ++j) {
      if (cols[j] < 0 || cols[j] >= n) continue;
      A(k, cols[j]) = c[j];
      off += std::fabs(c[j]);
    }
    A(k, k) = off + 1 + lcg.next();
    b(k) = c[4];
  }
  Eigen::VectorXd x = A.partialPivLu().solve(b);
  ASSERT_LT((A * x - b).norm(), 1e-12);

  std::vector<std::string> defines{"SIZE=50", "SEED=7"};
  Eigen::MatrixXd A0;
  Eigen::VectorXd b0;
  std::vector<fd::Row> r0 = fd::rows(derive_with(model("five-diagonal"), 0, defines));
  ASSERT_EQ(r0.size(), static_cast<std::size_t>(n + 2));
  fd::dense(r0, &A0, &b0);
  EXPECT_LT((A0 - A).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((b0 - b).cwiseAbs().maxCoeff(), 1e-15);

  std::vector<fd::Row> r2 = fd::rows(derive_with(model("five-diagonal"), 2, defines));
  ASSERT_EQ(r2.size(), static_cast<std::size_t>(n + 2));
  for (int k = 0; k < n; ++k) EXPECT_NEAR(r2[k + 1].rhs / r2[k + 1].a3, x(k), 1e-12 * (1 + std::fabs(x(k)))) << k;
}

// ---------------------------------------------------------------------------
// The RC circuit (circuit-solver.l).
namespace cs {
struct Segment {
  double Rh, Rv, Rp, Cap, I, V;
};

struct Circuit {
  int n;
  double dt, Vs, Rs;
  std::vector<Segment> seg;
};

Circuit uniform(int n, double dt) {
  return {n, dt, 1.0, 1.0, std::vector<Segment>(n, Segment{1, 1, 1, 1, 0, 0})};
}

// The model's -D GRADED values, segment k from 1.
Circuit graded(int n, double dt) {
  Circuit c{n, dt, 1.0, 1.0, {}};
  for (int k = 1; k <= n; ++k) c.seg.push_back({1 + (k - 1) / 4.0, 1.0 / k, 1.0 + k % 3, 1 + (k % 2) / 2.0, 0, 0});
  return c;
}

// One Crank-Nicolson time step: equations 12-17 of the notes as printed,
// assembled into a dense 2n x 2n system for x = (I_1, V_1, ..., I_n, V_n) and
// solved by Eigen.
void step(Circuit& c) {
  const int n = c.n;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * n);
  auto I = [](int k) { return 2 * (k - 1); };  // columns, k from 1
  auto V = [](int k) { return 2 * (k - 1) + 1; };
  for (int k = 1; k <= n; ++k) {
    const Segment& s = c.seg[k - 1];
    const int row = 2 * (k - 1);
    if (k == 1) {  // equation 12
      A(row, I(1)) = c.Rs + s.Rh + s.Rv;
      A(row, V(1)) = 1;
      if (n > 1) A(row, I(2)) = -s.Rv;
      b(row) = c.Vs;
    } else {  // equations 14 and 16 (no I_{n+1})
      const Segment& l = c.seg[k - 2];
      A(row, I(k - 1)) = l.Rv;
      A(row, V(k - 1)) = 1;
      A(row, I(k)) = -(l.Rv + s.Rh + s.Rv);
      A(row, V(k)) = -1;
      if (k < n) A(row, I(k + 1)) = s.Rv;
    }
    // equations 13, 15 and 17
    A(row + 1, I(k)) = -c.dt * s.Rp;
    A(row + 1, V(k)) = 2 * s.Rp * s.Cap + c.dt;
    b(row + 1) = (2 * s.Rp * s.Cap - c.dt) * s.V + c.dt * s.Rp * s.I;
    if (k < n) {
      A(row + 1, I(k + 1)) = c.dt * s.Rp;
      b(row + 1) -= c.dt * s.Rp * c.seg[k].I;
    }
  }
  Eigen::VectorXd x = A.fullPivLu().solve(b);
  EXPECT_LT((A * x - b).norm(), 1e-12);
  for (int k = 1; k <= n; ++k) c.seg[k - 1].I = x(I(k)), c.seg[k - 1].V = x(V(k));
}

std::vector<Segment> segments(const std::string& text) {
  std::vector<Segment> out;
  for (const Module& m : parse_modules(text)) {
    if (m.name != "S") continue;
    const std::string& p = m.params.at(0);
    out.push_back({field_of(p, "Rh"), field_of(p, "Rv"), field_of(p, "Rp"), field_of(p, "Cap"), field_of(p, "I"),
                   field_of(p, "V")});
  }
  return out;
}

// The model after `time_steps` time steps (4 derivation steps each) against
// the direct solve, to 1e-9.
void expect_matches_direct_solve(Circuit c, const std::vector<std::string>& defines, const std::vector<int>& checks) {
  Stepper run(model("circuit-solver"), defines);
  int done = 0;
  for (int k : checks) {
    for (; done < k; ++done) step(c);
    run.step(4 * k - run.steps_done());
    std::vector<Segment> s = segments(run.text());
    ASSERT_EQ(static_cast<int>(s.size()), c.n) << "after " << k << " time steps";
    for (int i = 0; i < c.n; ++i) {
      EXPECT_NEAR(s[i].Rh, c.seg[i].Rh, 1e-15);
      EXPECT_NEAR(s[i].Rv, c.seg[i].Rv, 1e-15);
      EXPECT_NEAR(s[i].Rp, c.seg[i].Rp, 1e-15);
      EXPECT_NEAR(s[i].Cap, c.seg[i].Cap, 1e-15);
      EXPECT_NEAR(s[i].I, c.seg[i].I, 1e-9) << "I_" << i + 1 << " after " << k << " time steps";
      EXPECT_NEAR(s[i].V, c.seg[i].V, 1e-9) << "V_" << i + 1 << " after " << k << " time steps";
    }
  }
}
}  // namespace cs

// The notes' circuit of the golden run (4 segments, all 1, dt = 0.1): after one
// time step (4 derivation steps) the (I, V) of the real lpfg's run.
TEST(NotesCircuitSolver, GoldenValuesAtTimeOneTenth) {
  std::vector<cs::Segment> s = cs::segments(derive_string(model("circuit-solver"), 4));
  ASSERT_EQ(s.size(), 4u);
  const double golden[4][2] = {{0.378738, 0.011024}, {0.147237, 0.004331}, {0.056282, 0.001773}, {0.019049, 0.000907}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(s[k].I, golden[k][0], 5e-7) << "I_" << k + 1;
    EXPECT_NEAR(s[k].V, golden[k][1], 5e-7) << "V_" << k + 1;
  }
}

// Between time steps the string holds the 2n + 2 rows; after the backward
// pass only their diagonals are left.
TEST(NotesCircuitSolver, StepsOfOneTimeStep) {
  Stepper run(model("circuit-solver"));
  EXPECT_EQ(count_named(run.modules(), "S"), 4);
  for (int step = 1; step <= 3; ++step) {
    run.step();
    std::vector<Module> s = run.modules();
    EXPECT_EQ(count_named(s, "M"), 10) << step;
    EXPECT_EQ(count_named(s, "S"), 0) << step;
    for (const Module& m : s) {
      const std::string& row = m.params.at(0);
      if (step >= 2) {  // after the forward pass
        EXPECT_EQ(field_of(row, "a1"), 0.0);
        EXPECT_EQ(field_of(row, "a2"), 0.0);
      }
      if (step == 3) {  // after the backward pass
        EXPECT_EQ(field_of(row, "a4"), 0.0);
        EXPECT_EQ(field_of(row, "a5"), 0.0);
      }
    }
  }
  run.step();
  EXPECT_EQ(names(run.modules()), (std::vector<std::string>{"S", "S", "S", "S"}));
}

TEST(NotesCircuitSolver, NotesCircuitMatchesDirectSolve) {
  cs::expect_matches_direct_solve(cs::uniform(4, 0.1), {}, {1, 2, 10});
}

// Different values in every segment, more segments, another time step.
TEST(NotesCircuitSolver, GradedCircuitMatchesDirectSolve) {
  cs::expect_matches_direct_solve(cs::graded(7, 0.05), {"GRADED", "SEGMENTS=7", "DT=0.05", "TIME_STEPS=100"},
                                  {1, 3, 20});
}

}  // namespace
}  // namespace sylva::test::examples
