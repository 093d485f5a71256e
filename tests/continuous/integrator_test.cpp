// The integrators against problems whose solutions are known in closed form:
// decay, the logistic curve, the harmonic oscillator, and a stiff linear
// equation. Expected values come from the analytic solutions, never from
// another run of the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "continuous/integrator.h"

namespace sylva::test {
namespace {

using continuous::IntegrationFailed;
using continuous::Integrator;
using continuous::IntegratorSettings;
using continuous::Method;
using continuous::RightHandSide;

IntegratorSettings settings_for(Method method, double rtol = 1e-8, double atol = 1e-10, double step = 0.01) {
  IntegratorSettings settings;
  settings.method = method;
  settings.relative_tolerance = rtol;
  settings.absolute_tolerance = atol;
  settings.step = step;
  return settings;
}

// Steps to `t_end`, checking that no step passes the limit; returns the steps taken.
int run_to(Integrator& integrator, double t_end) {
  int steps = 0;
  while (integrator.time() < t_end) {
    const double before = integrator.time();
    const double t = integrator.step(t_end);
    EXPECT_EQ(t, integrator.time());
    EXPECT_LE(t, t_end);
    if (!(t > before)) {
      ADD_FAILURE() << "no progress from t = " << before;
      break;
    }
    ++steps;
  }
  EXPECT_EQ(integrator.time(), t_end);
  return steps;
}

const RightHandSide kDecay = [](double, std::span<const double> y, std::span<double> dy) { dy[0] = -y[0]; };

constexpr double kRate = 1.5, kCapacity = 10, kStart = 0.5;
const RightHandSide kLogistic = [](double, std::span<const double> y, std::span<double> dy) {
  dy[0] = kRate * y[0] * (1 - y[0] / kCapacity);
};
double logistic(double t) { return kCapacity / (1 + (kCapacity / kStart - 1) * std::exp(-kRate * t)); }

class EachMethod : public ::testing::TestWithParam<Method> {};

INSTANTIATE_TEST_SUITE_P(Integrators, EachMethod,
                         ::testing::Values(Method::kRungeKutta4, Method::kDormandPrince, Method::kCvode),
                         [](const auto& info) {
                           switch (info.param) {
                             case Method::kRungeKutta4: return std::string("rk4");
                             case Method::kDormandPrince: return std::string("rk45");
                             case Method::kCvode: return std::string("cvode");
                           }
                           return std::string("unknown");
                         });

TEST_P(EachMethod, DecayReachesExpMinusOne) {
  auto integrator = continuous::make_integrator(settings_for(GetParam()), kDecay);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  run_to(*integrator, 1);
  const double bound = GetParam() == Method::kRungeKutta4 ? 1e-9 : GetParam() == Method::kDormandPrince ? 1e-7 : 1e-6;
  EXPECT_NEAR(integrator->state()[0], std::exp(-1.0), bound);
}

TEST_P(EachMethod, LogisticMatchesClosedFormAtSamplesAndInsideSteps) {
  auto integrator = continuous::make_integrator(settings_for(GetParam()), kLogistic);
  const std::vector<double> y0 = {kStart};
  integrator->reset(0, y0);
  double worst_inside = 0;
  std::vector<double> inside(1);
  for (double sample : {0.25, 0.5, 1.0, 2.0, 3.7, 5.0, 8.0}) {
    while (integrator->time() < sample) {
      const double t0 = integrator->time();
      const double t1 = integrator->step(sample);
      for (double s : {0.25, 0.5, 0.75}) {
        const double t = t0 + s * (t1 - t0);
        integrator->interpolate(t, inside);
        worst_inside = std::max(worst_inside, std::abs(inside[0] - logistic(t)));
      }
    }
    EXPECT_EQ(integrator->time(), sample);
    EXPECT_NEAR(integrator->state()[0], logistic(sample), 1e-6) << "t = " << sample;
  }
  EXPECT_LT(worst_inside, 1e-6);
}

TEST_P(EachMethod, InterpolantMeetsTheStepsEnds) {
  auto integrator = continuous::make_integrator(settings_for(GetParam()), kLogistic);
  const std::vector<double> y0 = {kStart};
  integrator->reset(0, y0);
  std::vector<double> y(1);
  integrator->interpolate(0, y);  // before any step: the state of the reset
  EXPECT_EQ(y[0], kStart);
  integrator->step(1);
  const double before = integrator->state()[0], t0 = integrator->time();
  integrator->step(2);
  integrator->interpolate(integrator->time(), y);
  EXPECT_NEAR(y[0], integrator->state()[0], 1e-12);
  integrator->interpolate(t0, y);
  EXPECT_NEAR(y[0], before, 1e-9);
  EXPECT_THROW(integrator->interpolate(integrator->time() + 1, y), std::out_of_range);
}

TEST_P(EachMethod, StepsNeverPassTheLimit) {
  auto integrator = continuous::make_integrator(settings_for(GetParam()), kDecay);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  // Limits that fall between RK4's steps, just after a step, and very close.
  for (double limit : {0.123, 0.5, 0.5000000001, 0.51, 0.7, 0.7 + 1e-13, 1.0}) run_to(*integrator, limit);
  EXPECT_NEAR(integrator->state()[0], std::exp(-1.0), 1e-6);
  EXPECT_THROW(integrator->step(integrator->time()), std::invalid_argument);
  EXPECT_THROW(integrator->step(0.5), std::invalid_argument);
}

TEST_P(EachMethod, MaxStepCapsEachStep) {
  auto settings = settings_for(GetParam(), 1e-4, 1e-6, 0.01);
  settings.max_step = 0.05;
  auto integrator = continuous::make_integrator(settings, kDecay);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  while (integrator->time() < 2) {
    const double t0 = integrator->time();
    EXPECT_LE(integrator->step(2) - t0, 0.05 * (1 + 1e-12));
  }
}

TEST_P(EachMethod, ResetChangesTheSystemsSize) {
  int calls = 0;
  // Each component decays at its own rate, k+1, whatever the size.
  const RightHandSide f = [&](double, std::span<const double> y, std::span<double> dy) {
    ++calls;
    for (std::size_t k = 0; k < y.size(); ++k) dy[k] = -static_cast<double>(k + 1) * y[k];
  };
  auto integrator = continuous::make_integrator(settings_for(GetParam()), f);
  const std::vector<double> one = {1}, three = {1, 2, 3}, none = {};
  integrator->reset(0, one);
  run_to(*integrator, 1);
  ASSERT_EQ(integrator->state().size(), 1u);
  EXPECT_NEAR(integrator->state()[0], std::exp(-1.0), 1e-6);

  integrator->reset(1, three);
  run_to(*integrator, 2);
  ASSERT_EQ(integrator->state().size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(integrator->state()[k], (k + 1) * std::exp(-(k + 1.0)), 1e-6);

  const std::size_t evaluations = integrator->evaluations();
  integrator->reset(2, none);
  EXPECT_EQ(integrator->step(7.5), 7.5);
  EXPECT_EQ(integrator->time(), 7.5);
  EXPECT_TRUE(integrator->state().empty());
  integrator->interpolate(5, std::span<double>());
  EXPECT_EQ(integrator->evaluations(), evaluations);

  integrator->reset(0, three);
  run_to(*integrator, 1);
  EXPECT_NEAR(integrator->state()[2], 3 * std::exp(-3.0), 1e-6);
  EXPECT_EQ(integrator->evaluations(), static_cast<std::size_t>(calls));
}

TEST_P(EachMethod, NonFiniteRightHandSideFails) {
  const RightHandSide f = [](double t, std::span<const double> y, std::span<double> dy) {
    dy[0] = t > 0.3 ? std::numeric_limits<double>::quiet_NaN() : -y[0];
  };
  auto integrator = continuous::make_integrator(settings_for(GetParam()), f);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  try {
    run_to(*integrator, 1);
    FAIL() << "no failure";
  } catch (const IntegrationFailed& failure) {
    EXPECT_GE(failure.time(), 0);
    EXPECT_LE(failure.time(), 0.3 + 1e-9);
    EXPECT_EQ(integrator->time(), failure.time());
    EXPECT_TRUE(std::isfinite(integrator->state()[0]));
    EXPECT_NE(std::string(failure.what()).find("finite"), std::string::npos) << failure.what();
  }
}

TEST_P(EachMethod, NaNFromTheStartFailsAtTheStart) {
  const RightHandSide f = [](double, std::span<const double>, std::span<double> dy) {
    dy[0] = std::numeric_limits<double>::quiet_NaN();
  };
  auto integrator = continuous::make_integrator(settings_for(GetParam()), f);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  try {
    integrator->step(1);
    FAIL() << "no failure";
  } catch (const IntegrationFailed& failure) {
    EXPECT_EQ(failure.time(), 0);
    EXPECT_EQ(integrator->time(), 0);
  }
}

TEST_P(EachMethod, ExceptionFromTheRightHandSidePropagates) {
  const RightHandSide f = [](double t, std::span<const double> y, std::span<double> dy) {
    if (t > 0.2) throw std::domain_error("model fault");
    dy[0] = -y[0];
  };
  auto integrator = continuous::make_integrator(settings_for(GetParam()), f);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  EXPECT_THROW(run_to(*integrator, 1), std::domain_error);
}

TEST(RungeKutta4, HalvingTheStepDividesTheErrorBySixteen) {
  auto error_with = [](double step) {
    auto integrator = continuous::make_integrator(settings_for(Method::kRungeKutta4, 1e-6, 1e-9, step), kLogistic);
    const std::vector<double> y0 = {kStart};
    integrator->reset(0, y0);
    run_to(*integrator, 4);
    return std::abs(integrator->state()[0] - logistic(4));
  };
  const double coarse = error_with(0.2), fine = error_with(0.1);
  EXPECT_GT(coarse / fine, 12);
  EXPECT_LT(coarse / fine, 20);
}

TEST(RungeKutta4, StiffDecayBlowsUp) {
  // With h = 0.01 and rate 1000 each step multiplies y by 1-10+50-166.7+416.7 = 291.
  const RightHandSide f = [](double, std::span<const double> y, std::span<double> dy) { dy[0] = -1000 * y[0]; };
  auto integrator = continuous::make_integrator(settings_for(Method::kRungeKutta4), f);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  try {
    run_to(*integrator, 10);
    FAIL() << "no failure";
  } catch (const IntegrationFailed& failure) {
    // 291^n passes the largest double after about 125 steps.
    EXPECT_GT(failure.time(), 1);
    EXPECT_LT(failure.time(), 1.5);
    EXPECT_NE(std::string(failure.what()).find("--integrator cvode"), std::string::npos);
  }
}

TEST(DormandPrince, HarmonicOscillatorKeepsItsEnergy) {
  constexpr double omega = 2 * std::numbers::pi;
  const RightHandSide f = [](double, std::span<const double> y, std::span<double> dy) {
    dy[0] = y[1];
    dy[1] = -omega * omega * y[0];
  };
  auto integrator = continuous::make_integrator(settings_for(Method::kDormandPrince), f);
  const std::vector<double> y0 = {1, 0};
  integrator->reset(0, y0);
  auto energy = [&](std::span<const double> y) { return 0.5 * (y[1] * y[1] + omega * omega * y[0] * y[0]); };
  const double e0 = energy(y0);
  for (int period = 1; period <= 10; ++period) {
    run_to(*integrator, period);
    EXPECT_NEAR(energy(integrator->state()) / e0, 1, 1e-6) << "period " << period;
  }
  EXPECT_NEAR(integrator->state()[0], 1, 1e-6);
  EXPECT_NEAR(integrator->state()[1], 0, 1e-5);
}

TEST(DormandPrince, ReusesTheLastStageAndAdaptsItsStep) {
  int calls = 0;
  const RightHandSide f = [&](double, std::span<const double> y, std::span<double> dy) {
    ++calls;
    dy[0] = -y[0];
  };
  auto integrator = continuous::make_integrator(settings_for(Method::kDormandPrince, 1e-6, 1e-9), f);
  const std::vector<double> y0 = {1};
  integrator->reset(0, y0);
  const int steps = run_to(*integrator, 10);
  // FSAL: six new evaluations per attempt, one more at the start.
  EXPECT_EQ((integrator->evaluations() - 1) % 6, 0u);
  EXPECT_LT(steps, 100);  // far fewer than the first step, 0.01, would need
  EXPECT_EQ(integrator->evaluations(), static_cast<std::size_t>(calls));
}

TEST(Cvode, StiffEquationTakesFewEvaluations) {
  // y' = -1000 (y - cos t), y(0) = 0: a fast transient onto a slow curve.
  const RightHandSide f = [](double t, std::span<const double> y, std::span<double> dy) {
    dy[0] = -1000 * (y[0] - std::cos(t));
  };
  auto integrator = continuous::make_integrator(settings_for(Method::kCvode, 1e-6, 1e-9), f);
  const std::vector<double> y0 = {0};
  integrator->reset(0, y0);
  run_to(*integrator, 1);
  const double a = 1e6 / (1e6 + 1), b = 1e3 / (1e6 + 1);
  EXPECT_NEAR(integrator->state()[0], a * std::cos(1.0) + b * std::sin(1.0) - a * std::exp(-1000.0), 1e-5);
  EXPECT_LT(integrator->evaluations(), 2000u);
}

TEST(Cvode, RobertsonKineticsStayBalanced) {
  const RightHandSide f = [](double, std::span<const double> y, std::span<double> dy) {
    dy[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
    dy[2] = 3e7 * y[1] * y[1];
    dy[1] = -dy[0] - dy[2];
  };
  auto integrator = continuous::make_integrator(settings_for(Method::kCvode, 1e-6, 1e-10), f);
  const std::vector<double> y0 = {1, 0, 0};
  integrator->reset(0, y0);
  run_to(*integrator, 40);
  const auto y = integrator->state();
  EXPECT_NEAR(y[0] + y[1] + y[2], 1, 1e-6);  // the reactions conserve mass
  EXPECT_NEAR(y[0], 0.7158, 1e-3);          // the well-known value at t = 40
  EXPECT_LT(integrator->evaluations(), 2000u);
}

// A system too large for a dense Jacobian (Newton's equations solved by
// GMRES instead): 2000 cells of a stiff diffusion-decay filament whose
// exact solution decays as one mode, y_i(t) = sin(pi i / (n + 1)) e^(-lambda t).
TEST(Cvode, LargeStiffSystemsNeedNoDenseJacobian) {
  const std::size_t n = 2000;
  const double pi = std::acos(-1.0), d = 1e3;
  const RightHandSide f = [&](double, std::span<const double> y, std::span<double> dy) {
    for (std::size_t i = 0; i < n; ++i) {
      const double left = i > 0 ? y[i - 1] : 0, right = i + 1 < n ? y[i + 1] : 0;
      dy[i] = d * (left + right - 2 * y[i]);
    }
  };
  std::vector<double> y0(n);
  for (std::size_t i = 0; i < n; ++i) y0[i] = std::sin(pi * static_cast<double>(i + 1) / (n + 1));
  const double lambda = 2 * d * (1 - std::cos(pi / (n + 1)));  // the mode's eigenvalue
  auto integrator = continuous::make_integrator(settings_for(Method::kCvode, 1e-8, 1e-12), f);
  integrator->reset(0, y0);
  run_to(*integrator, 10);
  const auto y = integrator->state();
  for (std::size_t i : {std::size_t{0}, n / 3, n / 2}) EXPECT_NEAR(y[i], y0[i] * std::exp(-lambda * 10), 1e-5);
}

TEST(MethodNamed, NamesAndErrors) {
  EXPECT_EQ(continuous::method_named("rk4"), Method::kRungeKutta4);
  EXPECT_EQ(continuous::method_named("rk45"), Method::kDormandPrince);
  EXPECT_EQ(continuous::method_named("cvode"), Method::kCvode);
  try {
    continuous::method_named("euler");
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "unknown integrator 'euler': choose rk4, rk45 or cvode");
  }
  EXPECT_THROW(continuous::method_named("RK4"), std::invalid_argument);
}

}  // namespace
}  // namespace sylva::test
