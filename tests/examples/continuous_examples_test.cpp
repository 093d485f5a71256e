// The differential L-systems of examples/ (docs/continuous-time.md), checked
// against what is known without the program: closed-form event times, the
// geometry the paper's productions preserve, and the paper's description
// of the Anabaena filament.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "api/timed_run.h"
#include "examples/continuous_examples.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

std::string model(const std::string& name) { return example_path(name + "/" + name + ".l"); }

// ---- logistic threshold ------------------------------------------------------

TEST(ContinuousExamplesTest, TheLogisticCellMaturesWhenTheCurveReachesTheThreshold) {
  const double x0 = 0.05, r = 1.2, xmax = 1.0, xstar = 0.9;
  const double t_star = std::log(xstar * (xmax - x0) / (x0 * (xmax - xstar))) / r;  // 4.2847...
  for (continuous::Method method :
       {continuous::Method::kRungeKutta4, continuous::Method::kDormandPrince, continuous::Method::kCvode}) {
    auto s = timed("logistic-threshold", 6, method, 1e-10);
    s->advance_to(t_star - 0.01);
    EXPECT_EQ(names(modules_of(*s)), std::vector<std::string>{"A"});
    s->advance_to(6);
    const std::vector<Module> m = modules_of(*s);
    ASSERT_EQ(names(m), std::vector<std::string>{"M"});
    EXPECT_NEAR(number(m[0].params[1]), t_star, 1e-6) << "method " << static_cast<int>(method);
    // The size keeps following the logistic curve after the event.
    const double x6 = xmax / (1 + (xmax / x0 - 1) * std::exp(-r * 6));
    EXPECT_NEAR(number(m[0].params[0]), x6, 1e-6);
  }
}

// ---- the dragon curve --------------------------------------------------------

// Where the turtle ends after the string: Right/Left turn by their angle, the
// three segments move by their length x.
std::pair<double, double> endpoint(const std::vector<Module>& string) {
  const double pi = std::acos(-1.0);
  double heading = 90, x = 0, y = 0;  // the turtle starts heading up
  for (const Module& m : string) {
    if (m.name == "Right") heading -= number(m.params[0]);
    else if (m.name == "Left") heading += number(m.params[0]);
    else if (m.name == "Fr" || m.name == "Fl" || m.name == "Fh") {
      const double length = number(m.params[0]);
      x += length * std::cos(heading * pi / 180), y += length * std::sin(heading * pi / 180);
    }
  }
  return {x, y};
}

TEST(ContinuousExamplesTest, TheDragonCurvesEndpointsStayFixedAtEverySample) {
  auto s = timed("dragon-curve-continuous", 4.5, continuous::Method::kDormandPrince);
  const double end_x = std::cos(45 * std::acos(-1.0) / 180);  // the initial segment, turned 45 degrees right
  int samples = 0;
  for (double t : sample_times(4.5, 0.125)) {
    s->advance_to(t);
    const auto [x, y] = endpoint(modules_of(*s));
    EXPECT_NEAR(x, end_x, 1e-9) << "t = " << t;
    EXPECT_NEAR(y, end_x, 1e-9) << "t = " << t;
    ++samples;
  }
  EXPECT_EQ(samples, 37);
  // Every T each leg is replaced by two and each hypotenuse vanishes: after
  // the replacement at 0 and those at 1, 2, 3 and 4 there are 2^5 legs.
  const std::vector<Module> m = modules_of(*s);
  EXPECT_EQ(count_named(m, "Fr") + count_named(m, "Fl"), 32);
  EXPECT_EQ(count_named(m, "Fh"), 16);
}

// ---- Anabaena ----------------------------------------------------------------

struct Cell {
  double x, c;
  bool heterocyst;
};
std::vector<Cell> cells(const Simulation& s) {
  std::vector<Cell> out;
  for (const Module& m : modules_of(s))
    if (m.name == "Cell") out.push_back({number(m.params[0]), number(m.params[1]), m.params[2] == "1"});
  return out;
}

TEST(ContinuousExamplesTest, AnabaenaKeepsItsCellsInsideTheDomainAndSpacesItsHeterocysts) {
  const double xmax = 1, cmin = 5;
  auto s = timed("anabaena-continuous", 575, continuous::Method::kDormandPrince, 1e-8);
  std::size_t previous_cells = 0;
  for (double t : sample_times(575, 25)) {
    s->advance_to(t);
    const std::vector<Cell> filament = cells(*s);
    // Events fire at the domain's boundary: no vegetative cell is ever past it.
    for (const Cell& cell : filament) {
      if (cell.heterocyst) continue;
      EXPECT_LT(cell.x, xmax + 1e-9) << "t = " << t;
      EXPECT_GT(cell.c, cmin - 1e-9) << "t = " << t;
    }
    EXPECT_GE(filament.size(), previous_cells) << "cells only divide";
    previous_cells = filament.size();
  }
  // The paper: heterocysts at approximately equal spacing maintained as the
  // filament grows. Vegetative runs between heterocysts stay within a band
  // around the diffusion's reach (about ln(cmax/cmin) sqrt(D/mu) ~ 4 cells a side).
  const std::vector<Cell> filament = cells(*s);
  ASSERT_GT(filament.size(), 200u);
  EXPECT_TRUE(filament.front().heterocyst && filament.back().heterocyst);
  std::vector<int> runs;
  int run = 0, heterocysts = 0;
  for (const Cell& cell : filament) {
    if (cell.heterocyst) {
      ++heterocysts;
      if (run > 0) runs.push_back(run);
      run = 0;
    } else {
      ++run;
    }
  }
  EXPECT_GT(heterocysts, 15);
  for (int r : runs) {
    EXPECT_GE(r, 3);
    EXPECT_LE(r, 20);
  }
}

TEST(ContinuousExamplesTest, HalvingDtChangesNeitherTheEventsNorTheSharedSamples) {
  auto sampled = [](double dt) {
    auto s = timed("anabaena-continuous", 300, continuous::Method::kDormandPrince, 1e-7);
    std::vector<std::string> strings;
    for (double t : sample_times(300, dt)) {
      s->advance_to(t);
      strings.push_back(io::format_string(s->string(), s->types()));
    }
    return strings;
  };
  const std::vector<std::string> coarse = sampled(10), fine = sampled(5);
  ASSERT_EQ(fine.size(), 2 * coarse.size() - 1);
  for (std::size_t k = 0; k < coarse.size(); ++k) EXPECT_EQ(coarse[k], fine[2 * k]) << "t = " << 10 * k;
}

TEST(ContinuousExamplesTest, ADiscreteModelCannotRunInTime) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation s(model("koch"), options, [](const std::string&) {});
  EXPECT_FALSE(s.continuous());
  TimedRunOptions run;
  run.end_time = 1;
  EXPECT_THROW(run_in_time(s, run, OutputOptions{}), ModelError);
}

}  // namespace
}  // namespace sylva::test::examples
