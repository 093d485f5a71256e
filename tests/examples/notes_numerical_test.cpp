// Tests of the course notes' numerical models in examples/ ("L-systems and
// Beyond", SIGGRAPH 2003): diffusion and decay, reaction-diffusion in a fixed
// and in a growing filament, the five-diagonal solver, the RC circuit solver
// and a branch bending under its own weight. Every expected value is worked
// out here: in closed form, by a linear stability analysis, by Eigen's dense
// solvers, or by a plain C++ loop; none is copied from the program's output.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

#include "examples/example_strings.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

// The parameters of every module named `name`, as numbers.
std::vector<std::vector<double>> params_of(const std::vector<Module>& s, const std::string& name) {
  std::vector<std::vector<double>> out;
  for (const Module& m : s) {
    if (m.name != name) continue;
    std::vector<double> p;
    for (const std::string& text : m.params) p.push_back(number(text));
    out.push_back(p);
  }
  return out;
}

double field_of(const std::string& text, const std::string& name) { return number(field(text, name)); }

// ---------------------------------------------------------------------------
// Diffusion and decay (diffusion-decay.l): u_t = -nu u + D u_xx on [0, L],
// u(0) = 64, u(L) = 256, a straight line at t = 0. The model's defaults.
namespace dd {
const int kCells = 40;
const double kDx = 1.0, kD = 1.0, kNu = 0.01, kLeft = 64.0, kRight = 256.0, kDt = 0.25;
const double kLength = kCells * kDx;

std::vector<double> values(const std::string& text) {
  std::vector<double> u;
  for (const std::vector<double>& p : params_of(parse_modules(text), "M")) u.push_back(p.at(0));
  return u;
}

// The continuous solution: the steady state
//   u_s(x) = (uL sinh(l (L - x)) + uR sinh(l x)) / sinh(l L),  l = sqrt(nu / D),
// plus the decaying sine series of the initial difference. The sine
// coefficients of the line and of u_s have closed forms (u_s'' = l^2 u_s
// integrates by parts twice); their difference is
//   b_n = 2/L (uL - uR (-1)^n) l^2 / (k_n (k_n^2 + l^2)),  k_n = n pi / L,
// and mode n decays as exp(-(D k_n^2 + nu) t).
double continuous(double x, double t) {
  const double l = std::sqrt(kNu / kD);
  double u = (kLeft * std::sinh(l * (kLength - x)) + kRight * std::sinh(l * x)) / std::sinh(l * kLength);
  for (int n = 1; n <= 4000; ++n) {
    const double k = n * M_PI / kLength, sign = n % 2 ? -1.0 : 1.0;
    const double b = 2 / kLength * (kLeft - kRight * sign) * l * l / (k * (k * k + l * l));
    u += b * std::sin(k * x) * std::exp(-(kD * k * k + kNu) * t);
  }
  return u;
}
}  // namespace dd

TEST(NotesDiffusionDecay, StartsOnTheStraightLineOfEquation2) {
  std::vector<double> u = dd::values(derive_string(model("diffusion-decay"), 0));
  ASSERT_EQ(u.size(), static_cast<std::size_t>(dd::kCells + 1));
  for (int i = 0; i <= dd::kCells; ++i) EXPECT_NEAR(u[i], 64.0 + 192.0 * i / dd::kCells, 1e-12) << i;
}

// One step is equation (5) at the interior points; the ends keep their values.
TEST(NotesDiffusionDecay, OneStepIsTheForwardEulerUpdate) {
  std::vector<double> u0 = dd::values(derive_string(model("diffusion-decay"), 0));
  std::vector<double> u1 = dd::values(derive_string(model("diffusion-decay"), 1));
  ASSERT_EQ(u1.size(), u0.size());
  EXPECT_EQ(u1.front(), dd::kLeft);
  EXPECT_EQ(u1.back(), dd::kRight);
  for (std::size_t i = 1; i + 1 < u0.size(); ++i) {
    double expected = u0[i] + (-dd::kNu * u0[i] + dd::kD * (u0[i - 1] - 2 * u0[i] + u0[i + 1]) / (dd::kDx * dd::kDx)) * dd::kDt;
    EXPECT_NEAR(u1[i], expected, 1e-12) << i;
  }
}

// At t = 100 (400 steps) the discrete solution follows the continuous one to
// within the O(dx^2 + dt) error of the scheme (about 0.05 here, on values
// between 40 and 256), while it is still far (25) from the steady state.
TEST(NotesDiffusionDecay, TransientFollowsTheContinuousSolution) {
  const int steps = 400;
  std::vector<double> u = dd::values(derive_string(model("diffusion-decay"), steps));
  ASSERT_EQ(u.size(), static_cast<std::size_t>(dd::kCells + 1));
  double far_from_steady = 0;
  for (int i = 0; i <= dd::kCells; ++i) {
    const double x = i * dd::kDx;
    EXPECT_NEAR(u[i], dd::continuous(x, steps * dd::kDt), 0.1) << "x = " << x;
    far_from_steady = std::max(far_from_steady, std::fabs(u[i] - dd::continuous(x, 1e9)));
  }
  EXPECT_GT(far_from_steady, 10.0);
}

// After the model's 8000 steps (t = 2000, slowest mode decayed by e^-32) the
// string is the steady state of the discrete equation
//   nu u_i = D (u_{i+1} - 2 u_i + u_{i-1}) / dx^2,
// u_i = (uL sinh(th (m - i)) + uR sinh(th i)) / sinh(th m), cosh th = 1 + nu dx^2 / (2 D).
TEST(NotesDiffusionDecay, SettlesToTheDiscreteSteadyState) {
  std::vector<double> u = dd::values(derive_string(model("diffusion-decay")));
  ASSERT_EQ(u.size(), static_cast<std::size_t>(dd::kCells + 1));
  const double th = std::acosh(1 + dd::kNu * dd::kDx * dd::kDx / (2 * dd::kD));
  const int m = dd::kCells;
  for (int i = 0; i <= m; ++i) {
    double expected = (dd::kLeft * std::sinh(th * (m - i)) + dd::kRight * std::sinh(th * i)) / std::sinh(th * m);
    EXPECT_NEAR(u[i], expected, 1e-9) << i;
  }
  // The decay makes it sag well below the straight line: 42.56 in the middle.
  EXPECT_LT(u[m / 2], 45.0);
}

// ---------------------------------------------------------------------------
// Reaction-diffusion (reaction-diffusion.l and expanding-reaction-diffusion.l):
// the activator-substrate system of the notes' equations (7), (8), nu = 0,
//   a_t = f(a, s) + DA a_xx,  s_t = g(a, s) + DS s_xx,
//   f = p - MU a,  g = SIGMA - p,  p = RHO s a^2 / (1 + KAPPA a^2) + RHO0.
namespace rd {
const double kRho = 1.0, kRho0 = 0.01, kKappa = 0.2, kMu = 1.0, kSigma = 1.0, kDa = 1.0, kDs = 20.0;

double production(double a, double s) { return kRho * s * a * a / (1 + kKappa * a * a) + kRho0; }
double f(double a, double s) { return production(a, s) - kMu * a; }
double g(double a, double s) { return kSigma - production(a, s); }

struct Analysis {
  double a, s;           // the uniform steady state
  double growth0;        // the largest growth rate of a uniform perturbation (k = 0)
  double k_max, growth;  // the fastest-growing wavenumber and its growth rate
};

// The uniform steady state by Newton's method on (f, g) = 0 from (1, 1), the
// Jacobian by central differences, and the growth rate of a perturbation
// exp(i k x) as the largest real part of the eigenvalues of
// J - k^2 diag(DA, DS), maximised over k on a fine grid.
Analysis analyse() {
  auto jacobian = [](double a, double s) {
    const double h = 1e-6;
    Eigen::Matrix2d J;
    J << (f(a + h, s) - f(a - h, s)) / (2 * h), (f(a, s + h) - f(a, s - h)) / (2 * h),
        (g(a + h, s) - g(a - h, s)) / (2 * h), (g(a, s + h) - g(a, s - h)) / (2 * h);
    return J;
  };
  Eigen::Vector2d x(1.0, 1.0);
  for (int i = 0; i < 100; ++i) x -= jacobian(x(0), x(1)).inverse() * Eigen::Vector2d(f(x(0), x(1)), g(x(0), x(1)));
  Analysis r{x(0), x(1), 0, 0, -1e9};
  const Eigen::Matrix2d J = jacobian(r.a, r.s);
  auto rate = [&](double k) {
    Eigen::Matrix2d A = J;
    A(0, 0) -= kDa * k * k;
    A(1, 1) -= kDs * k * k;
    Eigen::EigenSolver<Eigen::Matrix2d> eig(A);
    return std::max(eig.eigenvalues()(0).real(), eig.eigenvalues()(1).real());
  };
  r.growth0 = rate(0);
  for (double k = 1e-4; k < 3; k += 1e-4) {
    if (rate(k) > r.growth) r.growth = rate(k), r.k_max = k;
  }
  return r;
}

struct Cell {
  double len, a, s;
};

// Peaks of the activator: cells above 1.5 a* and above their neighbours
// (strictly on the left). A peak in an end cell counts one half, as the
// closed ends reflect the pattern: a cosine of n half-waves then has n/2.
double peaks(const std::vector<Cell>& c, double a_star) {
  double n = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    bool left = i == 0 || c[i].a > c[i - 1].a, right = i + 1 == c.size() || c[i].a >= c[i + 1].a;
    if (left && right && c[i].a > 1.5 * a_star) n += (i == 0 || i + 1 == c.size()) ? 0.5 : 1.0;
  }
  return n;
}

std::vector<Cell> fixed_cells(const std::string& text) {
  std::vector<Cell> out;
  for (const std::vector<double>& p : params_of(parse_modules(text), "M")) out.push_back({1.0, p.at(0), p.at(1)});
  return out;
}

std::vector<Cell> growing_cells(const std::string& text) {
  std::vector<Cell> out;
  for (const std::vector<double>& p : params_of(parse_modules(text), "M")) out.push_back({p.at(0), p.at(1), p.at(2)});
  return out;
}
}  // namespace rd

// The linear analysis itself: a stable uniform state that diffusion makes
// unstable (a Turing instability) with a wavelength of about 14 cells.
TEST(NotesReactionDiffusion, LinearAnalysisGivesATuringInstability) {
  rd::Analysis r = rd::analyse();
  EXPECT_NEAR(r.a, rd::kSigma / rd::kMu, 1e-9);  // a* = SIGMA / MU when nu = 0
  EXPECT_LT(r.growth0, 0);
  EXPECT_GT(r.growth, 0.1);
  EXPECT_GT(2 * M_PI / r.k_max, 10);
  EXPECT_LT(2 * M_PI / r.k_max, 20);
}

// The start: the uniform state, the activator perturbed by at most 0.5%.
TEST(NotesReactionDiffusion, StartsNearTheUniformState) {
  rd::Analysis r = rd::analyse();
  std::vector<rd::Cell> c = rd::fixed_cells(derive_string(model("reaction-diffusion"), 0));
  ASSERT_EQ(c.size(), 100u);
  double spread = 0;
  for (const rd::Cell& cell : c) {
    EXPECT_NEAR(cell.a, r.a, 0.005 * r.a + 1e-12);
    EXPECT_NEAR(cell.s, r.s, 1e-9);
    spread = std::max(spread, std::fabs(cell.a - r.a));
  }
  EXPECT_GT(spread, 0.001);
}

// After the model's 10000 steps (t = 100) the number of activator peaks is the
// number of wavelengths of the fastest-growing mode that fit in the filament,
// L k_max / (2 pi), within one: 7 for 7.3 with 100 cells, 11.5 for 11.7 with
// 160.
TEST(NotesReactionDiffusion, PeakCountIsTheFastestGrowingMode) {
  rd::Analysis r = rd::analyse();
  for (int cells : {100, 160}) {
    std::string text = cells == 100 ? derive_string(model("reaction-diffusion"))
                                    : derive_with(model("reaction-diffusion"), 10000, {"CELLS=160"});
    std::vector<rd::Cell> c = rd::fixed_cells(text);
    ASSERT_EQ(c.size(), static_cast<std::size_t>(cells));
    double expected = cells * r.k_max / (2 * M_PI);
    double found = rd::peaks(c, r.a);
    EXPECT_NEAR(found, expected, 1.0) << cells << " cells";
    // A real pattern: peaks well above the uniform state, troughs well below.
    double top = 0, bottom = 1e9;
    for (const rd::Cell& cell : c) top = std::max(top, cell.a), bottom = std::min(bottom, cell.a);
    EXPECT_GT(top, 1.5 * r.a);
    EXPECT_LT(bottom, 0.5 * r.a);
  }
}

// The growing filament: 40 cells of lengths 2^((37 i mod 29) / 29) grow by
// 1 + r dt per step and halve when they reach 2.
namespace erd {
const int kCells = 40;
const double kGrowth = 0.01, kDt = 0.01, kLmin = 1.0;

// Length and number of cells after `steps` steps: each initial cell's
// descendants all have the same length, so one length and a count per cell.
void lengths_after(int steps, double* total, int* cells) {
  *total = 0, *cells = 0;
  for (int i = 0; i < kCells; ++i) {
    double len = kLmin * std::pow(2.0, (i * 37 % 29) / 29.0);
    int count = 1;
    for (int n = 0; n < steps; ++n) {
      len = len * (1 + kGrowth * kDt);
      if (len >= 2 * kLmin) len /= 2, count *= 2;
    }
    *total += count * len, *cells += count;
  }
}
}  // namespace erd

// Cell divisions and lengths follow the growth law exactly.
TEST(NotesExpandingReactionDiffusion, CellsGrowAndDivide) {
  Stepper run(model("expanding-reaction-diffusion"));
  for (int steps : {0, 1000, 5000}) {
    run.step(steps - run.steps_done());
    std::vector<rd::Cell> c = rd::growing_cells(run.text());
    double total, length = 0;
    int cells;
    erd::lengths_after(steps, &total, &cells);
    for (const rd::Cell& cell : c) {
      EXPECT_GE(cell.len, erd::kLmin - 1e-12);
      EXPECT_LT(cell.len, 2 * erd::kLmin);
      length += cell.len;
    }
    EXPECT_EQ(static_cast<int>(c.size()), cells) << steps;
    EXPECT_NEAR(length, total, 1e-9 * total) << steps;
  }
}

// As the filament grows (from length 94 at t = 50 to 282 at t = 160) the
// pattern keeps up: every 1000 steps the peaks per unit length are within a
// band around the fastest-growing mode's k_max / (2 pi), and the number of
// peaks increases (10, 16, 20 at t = 60, 110, 160).
TEST(NotesExpandingReactionDiffusion, PeaksMultiplyAsTheFilamentGrows) {
  rd::Analysis r = rd::analyse();
  const double density = r.k_max / (2 * M_PI);
  Stepper run(model("expanding-reaction-diffusion"));
  std::vector<double> counts;
  for (int steps = 5000; steps <= 16000; steps += 1000) {
    run.step(steps - run.steps_done());
    std::vector<rd::Cell> c = rd::growing_cells(run.text());
    double length = 0;
    for (const rd::Cell& cell : c) length += cell.len;
    double found = rd::peaks(c, r.a);
    EXPECT_GT(found / length, 0.6 * density) << "t = " << steps * erd::kDt << ", length " << length;
    EXPECT_LT(found / length, 1.6 * density) << "t = " << steps * erd::kDt << ", length " << length;
    if (steps % 5000 == 1000) counts.push_back(found);  // t = 60, 110, 160
  }
  ASSERT_EQ(counts.size(), 3u);
  EXPECT_LT(counts[0], counts[1]);
  EXPECT_LT(counts[1], counts[2]);
  EXPECT_GE(counts[2], 1.8 * counts[0]);
}

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
