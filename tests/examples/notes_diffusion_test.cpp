// The course notes' diffusion models in examples/: diffusion and decay,
// reaction-diffusion in a fixed and in a growing filament (see
// notes_numerical.h for where the expected values come from).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "examples/notes_numerical.h"

namespace sylva::test::examples {
namespace {

using notes::field_of;
using notes::model;
using notes::params_of;

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

}  // namespace
}  // namespace sylva::test::examples
