// Gillespie groups (LPFG manual 7.2): the immigration-death example and small
// models checked against what Gillespie's direct method implies — exact
// distributions worked out on paper, compared with many seeded runs.
//
// Tolerances: a mean over R independent runs has standard error sd/sqrt(R);
// a correct engine lands within 4 standard errors with probability 0.99994
// per check, and every run is seeded, so each check gives the same numbers
// on every machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "examples/example_strings.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test::examples {
namespace {

struct Sample {
  double mean = 0, variance = 0;  // the sample mean and the unbiased sample variance
};

Sample sample(const std::vector<double>& xs) {
  Sample s;
  for (double x : xs) s.mean += x;
  s.mean /= static_cast<double>(xs.size());
  for (double x : xs) s.variance += (x - s.mean) * (x - s.mean);
  s.variance /= static_cast<double>(xs.size() - 1);
  return s;
}

// A model loaded once and run many times; its Printf output collects in `messages`.
class Runs {
 public:
  explicit Runs(const std::string& model, std::vector<std::string> defines = {}) {
    build::BuildOptions options;
    options.cache_dir = SYLVA_TEST_CACHE_DIR;
    options.defines = std::move(defines);
    simulation_ = std::make_unique<Simulation>(model, options, [this](const std::string& m) { messages += m; });
  }
  Simulation& simulation() { return *simulation_; }
  std::string text() {
    std::string s = simulation_->string_text();
    if (!s.empty() && s.back() == '\n') s.pop_back();
    return s;
  }
  // One run of `steps` steps from a fresh Start.
  std::string run(int steps) {
    messages.clear();
    simulation_->rewind();
    simulation_->begin();
    for (int k = 0; k < steps; ++k) simulation_->step();
    return text();
  }

  std::string messages;

 private:
  std::unique_ptr<Simulation> simulation_;
};

std::string write_model(const std::string& name, const std::string& text) {
  return write_temp_file("gillespie-" + name, name + ".l", text);
}

// ---------------------------------------------------------------------------
// The example: immigration at rate 10, decay at rate 1 per molecule, from no
// molecules. The number N at time t is Poisson with mean
// m = 10 (1 - exp(-t)), so mean and variance are both m; at t = 2,
// m = 8.6466. The model stops with the first reaction after t = 2, so the
// state at t = 2 is the string before the last step.
TEST(ExampleImmigrationDeath, CountAtTheEndTimeIsPoissonWithTheAnalyticMean) {
  Runs runs(example_path("immigration-death/immigration-death.l"));
  Simulation& d = runs.simulation();
  const int kRuns = 2000;
  std::vector<double> counts;
  std::set<std::string> finals;
  for (int r = 0; r < kRuns; ++r) {
    d.rewind();
    d.begin();
    std::size_t molecules = 0;  // the Source is the other module
    int steps = 0;
    while (!d.stopped()) {
      molecules = d.string().count_modules(d.types()) - 1;
      d.step();
      ASSERT_LT(++steps, 1000) << "run " << r << " does not reach the end time";
    }
    counts.push_back(static_cast<double>(molecules));
    finals.insert(runs.text());
  }
  const double m = 10.0 * (1.0 - std::exp(-2.0));
  const Sample s = sample(counts);
  // Standard error of the mean: sqrt(m / R) = 0.066. Of the sample variance
  // of a Poisson variable: sqrt((mu4 - m^2) / R) with mu4 = m + 3m^2, i.e.
  // sqrt((m + 2m^2) / R) = 0.28.
  EXPECT_NEAR(s.mean, m, 4 * std::sqrt(m / kRuns));
  EXPECT_NEAR(s.variance, m, 4 * std::sqrt((m + 2 * m * m) / kRuns));
  // Each run is seeded differently (seed 1, 2, ...): the runs differ.
  EXPECT_GT(finals.size(), 10u);
}

// ---------------------------------------------------------------------------
// Competing decay: 20 modules A, each becoming B at rate 1 or C at rate 3.
// Each step fires one reaction: the successor records the step it fired in.
// Every step prints "step t" (t = GillespieTime(), lpfg's clock: the sum of
// the times to each reaction so far).
const char* kCompetingDecay = R"(#include <lpfgall.h>
#ifndef SEED_STEP
#define SEED_STEP 1
#endif
#ifdef CALL_RAN
#define DRAW() ran(1.0f)
#else
#define DRAW()
#endif
module A;
module B(int);
module C(int);
long seed = 1;
derivation length: 20;
Start: { SeedGillespie(seed); seed += SEED_STEP; UseGroup(1); }
StartEach: { DRAW(); }
EndEach: { Printf("%d %.17g\n", StepNo(), GillespieTime()); }
axiom: A A A A A A A A A A A A A A A A A A A A;
ggroup 1:
A : {
  propensity 1 produce B(StepNo());
  propensity 3 produce C(StepNo());
}
endgroup
)";

struct Clock {
  std::vector<double> taus;
  std::vector<double> times;
};

// The clock after each step, and the time each step took (from `start`).
Clock read_clock(const std::string& messages, double start = 0) {
  Clock c;
  std::istringstream in(messages);
  std::string line;
  while (std::getline(in, line)) {
    char* at = nullptr;
    std::strtol(line.c_str(), &at, 10);
    const double t = std::strtod(at, nullptr);
    c.taus.push_back(t - (c.times.empty() ? start : c.times.back()));
    c.times.push_back(t);
  }
  return c;
}

// Which step each module fired in, in string order (-1 for an A).
std::vector<int> firing_steps(const std::string& text) {
  std::vector<int> steps;
  for (const Module& m : parse_modules(text)) steps.push_back(m.name == "A" ? -1 : static_cast<int>(number(m.params[0])));
  return steps;
}

TEST(Gillespie, ReactionsAreChosenByPropensityAndTimesAreExponential) {
  Runs runs(write_model("competing-decay", kCompetingDecay));
  const int kRuns = 2000, kModules = 20;
  std::vector<double> b_counts, end_times;
  for (int r = 0; r < kRuns; ++r) {
    const std::vector<Module> s = parse_modules(runs.run(kModules));
    ASSERT_EQ(s.size(), static_cast<std::size_t>(kModules));
    // One reaction per step: the steps recorded are 1..20, each once.
    std::vector<int> fired = firing_steps(runs.text());
    std::sort(fired.begin(), fired.end());
    for (int k = 0; k < kModules; ++k) ASSERT_EQ(fired[k], k + 1) << runs.text();
    b_counts.push_back(count_named(s, "B"));
    const Clock clock = read_clock(runs.messages);
    ASSERT_EQ(clock.times.size(), static_cast<std::size_t>(kModules)) << runs.messages;
    for (std::size_t k = 0; k < clock.taus.size(); ++k) {
      ASSERT_GT(clock.taus[k], 0) << "step " << k + 1;
      ASSERT_TRUE(std::isfinite(clock.taus[k]));
      if (k > 0) {
        ASSERT_GT(clock.times[k], clock.times[k - 1]);
      }
    }
    end_times.push_back(clock.times.back());
  }
  // Every A ends as B with probability 1/(1+3): the number of B's is
  // Binomial(20, 1/4), mean 5, variance 3.75; standard error sqrt(3.75/R).
  const Sample b = sample(b_counts);
  EXPECT_NEAR(b.mean, 5.0, 4 * std::sqrt(3.75 / kRuns));
  // The sample variance has variance (mu4 - sigma^4) / R, with
  // mu4 = 3 sigma^4 + sigma^2 (1 - 6pq) for a binomial.
  EXPECT_NEAR(b.variance, 3.75, 4 * std::sqrt((2 * 3.75 * 3.75 + 3.75 * (1 - 6 * 0.25 * 0.75)) / kRuns));
  // With n A's left the total propensity is 4n, so the time to convert all
  // is a sum of independent exponentials of rates 4n, n = 20..1: mean
  // sum 1/(4n), variance sum 1/(4n)^2.
  // Cumulants add: k2 = sum 1/rate^2 (the variance), k4 = sum 6/rate^4, and
  // the sample variance has variance (mu4 - k2^2) / R = (k4 + 2 k2^2) / R.
  double mean = 0, variance = 0, k4 = 0;
  for (int n = 1; n <= kModules; ++n) {
    const double rate = 4.0 * n;
    mean += 1 / rate;
    variance += 1 / (rate * rate);
    k4 += 6 / (rate * rate * rate * rate);
  }
  const Sample t = sample(end_times);
  EXPECT_NEAR(t.mean, mean, 4 * std::sqrt(variance / kRuns));
  EXPECT_NEAR(t.variance, variance, 4 * std::sqrt((k4 + 2 * variance * variance) / kRuns));
}

TEST(Gillespie, TheSameSeedGivesTheSameRunAndOthersDiffer) {
  const std::string model = write_model("competing-decay", kCompetingDecay);
  // Runs in one process take the next seed each.
  Runs by_seed(model);
  const std::string run1 = by_seed.run(20), run2 = by_seed.run(20), run3 = by_seed.run(20);
  EXPECT_NE(run1, run2);
  EXPECT_NE(run2, run3);
  EXPECT_NE(run1, run3);
  // Seed 1 every time: the same string and the same times, run after run.
  Runs fixed(model, {"SEED_STEP=0"});
  const std::string first = fixed.run(20);
  const std::string first_times = fixed.messages;
  EXPECT_EQ(fixed.run(20), first);
  EXPECT_EQ(fixed.messages, first_times);
  // ran() draws its numbers from another generator: calling it in every
  // StartEach changes nothing.
  Runs with_ran(model, {"SEED_STEP=0", "CALL_RAN"});
  EXPECT_EQ(with_ran.run(20), first);
  EXPECT_EQ(with_ran.messages, first_times);
}

// With no reaction left nothing changes, and lpfg's clock stands still.
TEST(Gillespie, NoReactionLeftMeansNothingChangesAndTheClockStands) {
  Runs runs(write_model("competing-decay", kCompetingDecay));
  const std::string converted = runs.run(20);
  const double end = read_clock(runs.messages).times.back();
  runs.messages.clear();
  for (int k = 0; k < 3; ++k) runs.simulation().step();
  EXPECT_EQ(runs.text(), converted);
  const Clock clock = read_clock(runs.messages, end);
  ASSERT_EQ(clock.taus.size(), 3u) << runs.messages;
  for (double tau : clock.taus) EXPECT_EQ(tau, 0) << runs.messages;
}

// lpfg's generator and order. After SeedGillespie(7) erand48's state is 7;
// each step draws one number u to choose the reaction (r = u P, less each
// propensity in string order until r <= 0) and one, u', for the time to it,
// -ln(1 - u') / P, which GillespieTime() adds up. The string and the clock
// are lpfg's (lpfg -b on this model, Printf with %.17g): step 1 fires the
// first A, step 2 the last.
TEST(Gillespie, LpfgsGeneratorAndOrder) {
  const std::string model = write_model("lpfg-order", R"(#include <lpfgall.h>
module A(int);
module B(int);
derivation length: 2;
Start: { SeedGillespie(7); UseGroup(1); }
EndEach: { Printf("%d %.17g\n", StepNo(), GillespieTime()); }
axiom: A(1) A(2) A(3) A(4);
ggroup 1:
A(n) : { propensity 1 produce B(n); }
endgroup
)");
  Runs runs(model);
  EXPECT_EQ(runs.run(2), "B(1) A(2) A(3) B(4)");
  EXPECT_EQ(runs.messages, "1 0.03132275146026426\n2 0.31185679042490339\n");
}

// Which reactions a string offers, as lpfg gathers them (lpfg -b on this
// model; its clock and the string's last modules printed): group 0's
// productions take no part in a Gillespie step (X stays until step 4); of
// A's productions each one that matches offers its reactions, until one that
// matches offers none: A(0) offers nothing (the first production matches
// and offers nothing), A(200) offers 1 + 2 + 1; a zero propensity never
// fires. Seeded with 3, step 1 fires A(200) -> A(-1); after it nothing can
// fire and the clock stands; UseGroup(0) returns to ordinary steps.
TEST(Gillespie, EachMatchingProductionOffersUntilOneOffersNone) {
  const std::string model = write_model("group-rules", R"(#include <lpfgall.h>
module A(int);
module X;
module Y;
module Z;
derivation length: 4;
Start: { UseGroup(1); SeedGillespie(3); }
StartEach: { if (StepNo() == 4) UseGroup(0); }
EndEach: { Printf("%d %.17g\n", StepNo(), GillespieTime()); }
axiom: X Z A(0) A(200);
X : { produce Y; }
ggroup 1:
A(n) : { if (n > 100) propensity 1 produce A(-1); }
A(n) : { propensity 2 produce A(n + 1); propensity 1 produce A(n + 10); }
Z : { propensity 0 produce Y; }
endgroup
)");
  Runs runs(model);
  EXPECT_EQ(runs.run(4), "Y Z A(0) A(-1)");
  EXPECT_EQ(runs.messages,
            "1 0.05388337720033564\n2 0.05388337720033564\n3 0.05388337720033564\n4 0.05388337720033564\n");
}

}  // namespace
}  // namespace sylva::test::examples
