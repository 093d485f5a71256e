// The plants of Prusinkiewicz, Hammel and Mjolsness, "Animation of plant
// development" (SIGGRAPH 1993), section 7, as differential L-systems in
// examples/: pinnate-leaf, campanula, lychnis and hieracium. Each is checked
// against what is known without the program: the logistic and cubic growth
// functions in closed form, event times from the apex's arithmetic, the
// apices and flowers of Lychnis by a discrete simulation of apex ages, and
// the order in which Hieracium's apices flower.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <memory>
#include <queue>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "api/timed_run.h"
#include "examples/continuous_examples.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {


// Run with Dormand-Prince at tight tolerances: the checks below are to 1e-6.
std::unique_ptr<Simulation> precisely(const std::string& name, double end) {
  return timed(name, end, continuous::Method::kDormandPrince, 1e-10);
}

std::vector<Module> named(const std::vector<Module>& string, const std::string& name) {
  std::vector<Module> out;
  for (const Module& m : string)
    if (m.name == name) out.push_back(m);
  return out;
}

double logistic(double t, double x0, double r, double xmax) {
  return xmax / (1 + (xmax / x0 - 1) * std::exp(-r * t));
}

// The paper's cubic G integrated: 0 at t = 0, dx at T, zero slopes at both.
double cubic(double t, double dx, double T) {
  if (t <= 0) return 0;
  if (t >= T) return dx;
  const double s = t / T;
  return dx * (3 * s * s - 2 * s * s * s);
}

// ---- 7.1 pinnate leaf --------------------------------------------------------

TEST(DlPlantsTest, PinnateLeafMakesALeafletPairEachTimeTheApexReachesTheThreshold) {
  // Figure 9's values.
  const int n0 = 4;
  const double x0 = 1.0, xth = 2.0, k = 0.5, ra = 2.0, xamax = 3.0, ri = 1.0, ximax = 3.0;
  const double s0 = 0.05, rs = 2.0, smax = 6.0, alpha0 = 2.0, ralpha = 1.0, alphamax = 60.0;
  // The logistic apex reaches xth at t1; it restarts at (1 - k) xth = x0, so
  // every later division is t1 after the one before.
  const double t1 = std::log(xth * (xamax - x0) / (x0 * (xamax - xth))) / ra;  // ln(4)/2 = 0.693
  ASSERT_NEAR((1 - k) * xth, x0, 1e-15);
  const double end = 9;  // Figure 9's last frame, 900 x 0.01
  auto s = precisely("pinnate-leaf", end);
  const double eps = 1e-3;
  for (int j = 1; j <= n0; ++j) {
    s->advance_to(j * t1 - eps);
    std::vector<Module> m = modules_of(*s);
    EXPECT_EQ(count_named(m, "L"), 2 * (j - 1)) << "before division " << j;
    ASSERT_EQ(count_named(m, "Fa"), 1);
    EXPECT_EQ(number(named(m, "Fa")[0].params[1]), n0 - (j - 1));
    // Just before: the apex is eps short of the threshold on its logistic curve.
    EXPECT_NEAR(number(named(m, "Fa")[0].params[0]), logistic(t1 - eps, x0, ra, xamax), 1e-7);
    s->advance_to(j * t1 + eps);
    m = modules_of(*s);
    EXPECT_EQ(count_named(m, "L"), 2 * j) << "after division " << j;
    EXPECT_EQ(count_named(m, "Fi"), j);
    EXPECT_EQ(count_named(m, "Plus") + count_named(m, "Minus"), 2 * j);
    EXPECT_NEAR(number(named(m, "Fa")[0].params[0]), logistic(eps, x0, ra, xamax), 1e-7);
  }
  // With n = 0 the apex turns into an internode and the terminal leaflet.
  s->advance_to((n0 + 1) * t1 - eps);
  EXPECT_EQ(count_named(modules_of(*s), "Fa"), 1);
  EXPECT_EQ(count_named(modules_of(*s), "L"), 2 * n0);
  s->advance_to((n0 + 1) * t1 + eps);
  std::vector<Module> m = modules_of(*s);
  EXPECT_EQ(count_named(m, "Fa"), 0);
  EXPECT_EQ(count_named(m, "L"), 2 * n0 + 1);
  EXPECT_EQ(count_named(m, "Fi"), n0 + 1);
  EXPECT_EQ(names(m).back(), "L") << "the terminal leaflet ends the leaf";

  // At a sample time every organ is on its logistic curve from its creation:
  // internode j (from the base) and leaflet pair j at j t1, the terminal
  // internode (length xth) and leaflet at (n0 + 1) t1.
  const double t = 3.6;
  s->advance_to(t);
  m = modules_of(*s);
  const std::vector<Module> fi = named(m, "Fi"), leaflets = named(m, "L"), plus = named(m, "Plus");
  ASSERT_EQ(fi.size(), 5u);
  ASSERT_EQ(leaflets.size(), 9u);
  ASSERT_EQ(plus.size(), 4u);
  for (int j = 1; j <= n0 + 1; ++j) {
    const double age = t - j * t1;
    const double start = j <= n0 ? k * xth : xth;
    EXPECT_NEAR(number(fi[j - 1].params[0]), logistic(age, start, ri, ximax), 1e-6) << "internode " << j;
    EXPECT_NEAR(number(leaflets[j <= n0 ? 2 * (j - 1) : 2 * n0].params[0]), logistic(age, s0, rs, smax), 1e-6)
        << "leaflet " << j;
    if (j <= n0) {
      EXPECT_NEAR(number(leaflets[2 * (j - 1) + 1].params[0]), logistic(age, s0, rs, smax), 1e-6);
      EXPECT_NEAR(number(plus[j - 1].params[0]), logistic(age, alpha0, ralpha, alphamax), 1e-6)
          << "angle " << j;
    }
  }
  // At the figure's last frame the leaflets are near their full size.
  s->advance_to(end);
  const double first_leaflet = number(named(modules_of(*s), "L")[0].params[0]);
  EXPECT_NEAR(first_leaflet, logistic(end - t1, s0, rs, smax), 1e-6);
  EXPECT_GT(first_leaflet, 0.999 * smax);
}

// ---- 7.2 Campanula -----------------------------------------------------------

TEST(DlPlantsTest, CampanulaFlowersAtTheApexsArithmeticTimesAndItsInternodesFollowTheCubic) {
  // The example's values.
  const int n0 = 8;
  const double v = 1.0, x0 = 0.2, xth = 1.0, k = 0.5, dx = 1.0, T1 = 4.0, alpha0 = 5.0, dalpha = 55.0, T2 = 3.0;
  // The apex grows at v: it reaches xth after (xth - x0)/v, then every k xth / v.
  std::vector<double> event;
  for (int j = 0; j <= n0; ++j) event.push_back((xth - x0) / v + j * k * xth / v);  // 0.8, 1.3, ..., 4.8
  auto s = precisely("campanula", 9);
  const double eps = 1e-3;
  for (int j = 0; j <= n0; ++j) {
    s->advance_to(event[j] - eps);
    std::vector<Module> m = modules_of(*s);
    EXPECT_EQ(count_named(m, "K"), j) << "before event " << j;
    ASSERT_EQ(count_named(m, "Fa"), 1);
    EXPECT_NEAR(number(named(m, "Fa")[0].params[0]), xth - v * eps, 1e-9);
    s->advance_to(event[j] + eps);
    m = modules_of(*s);
    EXPECT_EQ(count_named(m, "K"), j + 1) << "after event " << j;
    EXPECT_EQ(count_named(m, "Fi"), j + 1);
  }
  EXPECT_EQ(count_named(modules_of(*s), "Fa"), 0) << "the apex became the terminal flower";

  // Internode j is G(dx, T1) at its age past its initial length, k xth (the
  // terminal one: xth); the angles likewise from alpha0. A second run, from 0.
  s = precisely("campanula", 9);
  for (double t : {2.0, 3.7, 6.1, 9.0}) {
    s->advance_to(t);
    const std::vector<Module> m = modules_of(*s);
    const std::vector<Module> fi = named(m, "Fi"), angles = named(m, "Angle");
    int created = 0;
    for (double e : event) created += e < t;
    ASSERT_EQ(static_cast<int>(fi.size()), created) << "t = " << t;
    ASSERT_EQ(static_cast<int>(angles.size()), std::min(created, n0));
    for (int j = 0; j < created; ++j) {
      const double age = t - event[j];
      EXPECT_NEAR(number(fi[j].params[1]), age, 1e-9) << "t = " << t << ", internode " << j;
      const double start = j < n0 ? k * xth : xth;
      EXPECT_NEAR(number(fi[j].params[0]), start + cubic(age, dx, T1), 1e-6) << "t = " << t << ", internode " << j;
      if (j < n0) {
        EXPECT_NEAR(number(angles[j].params[0]), alpha0 + cubic(age, dalpha, T2), 1e-5);
      }
    }
  }
  // By t = 9 every internode has its final length and the plant its height.
  double height = 0;
  for (const Module& m : named(modules_of(*s), "Fi")) height += number(m.params[0]);
  EXPECT_NEAR(height, n0 * (k * xth + dx) + xth + dx, 1e-5);
}

// ---- 7.3 Lychnis -------------------------------------------------------------

// Apices and flowers at time t, by a discrete simulation of apex ages: an
// apex that reaches taumax at time e becomes a flower and two apices of
// ages 0 and taumax/2, which reach taumax at e + taumax and e + taumax/2.
struct Counts {
  int apices, flowers;
};
Counts lychnis_counts(double taumax, double t) {
  std::priority_queue<double, std::vector<double>, std::greater<double>> due;  // when each apex fires
  due.push(0);  // the initial apex has age taumax
  int flowers = 0;
  while (!due.empty() && due.top() < t) {
    const double e = due.top();
    due.pop();
    ++flowers;
    due.push(e + taumax);
    due.push(e + taumax / 2);
  }
  return {static_cast<int>(due.size()), flowers};
}

TEST(DlPlantsTest, LychnisApicesAndFlowersFollowTheFibonacciRecurrence) {
  const double taumax = 2.0, dx = 1.0, T = 3.0;
  auto s = precisely("lychnis", 10.5);
  std::vector<int> opened;  // flowers opening at k taumax/2, from the simulation of ages
  for (int k = 0; k <= 9; ++k) {
    const double t = (k + 0.5) * taumax / 2;
    s->advance_to(t);
    const std::vector<Module> m = modules_of(*s);
    const Counts expected = lychnis_counts(taumax, t);
    EXPECT_EQ(count_named(m, "K"), expected.flowers) << "t = " << t;
    EXPECT_EQ(count_named(m, "A"), expected.apices) << "t = " << t;
    EXPECT_EQ(count_named(m, "I"), 2 * expected.flowers);
    EXPECT_EQ(count_named(m, "A"), count_named(m, "K") + 1);
    opened.push_back(expected.flowers - (k == 0 ? 0 : lychnis_counts(taumax, t - taumax / 2).flowers));
    // Every internode is the cubic of its age: it started at 0, at an event.
    for (const Module& i : named(m, "I")) {
      const double age = number(i.params[1]);
      EXPECT_NEAR(number(i.params[0]), cubic(age, dx, T), 1e-6) << "t = " << t;
      const double born = t - age;  // a multiple of taumax/2
      EXPECT_NEAR(born / (taumax / 2), std::round(born / (taumax / 2)), 1e-6);
    }
  }
  // The paper's recurrence: a_k = a_{k-1} + a_{k-2} with a_0 = a_1 = 1.
  EXPECT_EQ(opened, (std::vector<int>{1, 1, 2, 3, 5, 8, 13, 21, 34, 55}));
  EXPECT_EQ(count_named(modules_of(*s), "K"), 143);  // 1 + 1 + 2 + ... + 55
}

// ---- 7.4 Hieracium -----------------------------------------------------------

struct Head {
  int order;           // 0: the main axis, 1: a lateral
  double flowered_at;  // when the apex reached F_a2
};
std::vector<Head> heads(const std::vector<Module>& string) {
  std::vector<Head> out;
  for (const Module& m : named(string, "Fa2"))
    out.push_back({static_cast<int>(number(m.params[1])), number(m.params[2])});
  return out;
}

TEST(DlPlantsTest, HieraciumFlowersBasipetallyFromTheMainApexDown) {
  const double t_hormone = 5.0, v_main = 4.0;
  auto s = precisely("hieracium", 14);
  // No hormone before it is generated at the base; then its front climbs the
  // basal internode at the main axis' speed.
  s->advance_to(t_hormone - 1e-3);
  for (const Module& m : named(modules_of(*s), "Fi")) EXPECT_EQ(m.params[3], "0");
  const double delta = 0.1;
  s->advance_to(t_hormone + delta);
  const std::vector<Module> fi = named(modules_of(*s), "Fi");
  ASSERT_FALSE(fi.empty());
  EXPECT_EQ(fi[0].params[3], "1");
  EXPECT_NEAR(number(fi[0].params[1]), v_main * delta, 1e-9);
  for (std::size_t j = 1; j < fi.size(); ++j) EXPECT_EQ(fi[j].params[3], "0");

  s->advance_to(14);
  const std::vector<Module> m = modules_of(*s);
  EXPECT_EQ(count_named(m, "Fa0") + count_named(m, "Fa1"), 0) << "every apex has flowered or is dormant";
  const std::vector<Head> h = heads(m);
  // String order: the laterals from the base up, the main apex last.
  ASSERT_GE(h.size(), 11u);
  ASSERT_EQ(h.back().order, 0);
  for (std::size_t j = 0; j + 1 < h.size(); ++j) EXPECT_EQ(h[j].order, 1);
  const double main_time = h.back().flowered_at;
  EXPECT_GT(main_time, t_hormone);
  // The main apex first; each lateral after the one above it.
  for (std::size_t j = 0; j + 1 < h.size(); ++j) {
    EXPECT_GT(h[j].flowered_at, main_time) << "lateral " << j;
    if (j + 2 < h.size()) {
      EXPECT_GT(h[j].flowered_at, h[j + 1].flowered_at) << "lateral " << j << " and the one above";
    }
  }
  // A flowering apex no longer grows.
  const double main_length = number(named(m, "Fa2").back().params[0]);
  s->advance_to(14.5);
  EXPECT_EQ(number(named(modules_of(*s), "Fa2").back().params[0]), main_length);
}

}  // namespace
}  // namespace sylva::test::examples
