// The scheduler of continuous time on systems of its own, whose event times
// are known in closed form.
#include "continuous/continuous_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sylva::continuous {
namespace {

// Cells that grow as dx/dt = rate and split in two halves when x reaches 1:
// a cell starting at x0 first splits at (1 - x0) / rate, then every 0.5 / rate.
class SplittingCells : public ContinuousSystem {
 public:
  explicit SplittingCells(std::vector<double> x, double rate = 1) : cells_(std::move(x)), rate_(rate) {}
  void gather(std::vector<double>& y) override { y = cells_; }
  void set_state(double t, std::span<const double> y) override {
    time_ = t;
    cells_.assign(y.begin(), y.end());
  }
  void rates(std::span<double> dy) override {
    for (double& d : dy) d = rate_;
  }
  void read_events(std::vector<EventReading>& readings) override {
    readings.clear();
    for (double x : cells_) readings.push_back({x >= 1.0, x - 1.0});
  }
  std::size_t fire_events() override {
    std::vector<double> next;
    const std::size_t before = fired_at_.size();
    for (double x : cells_) {
      if (x >= 1.0) {
        next.push_back(x / 2);
        next.push_back(x / 2);
        fired_at_.push_back(time_);
      } else {
        next.push_back(x);
      }
    }
    cells_ = next;
    return fired_at_.size() - before;
  }
  std::vector<double> cells_;
  std::vector<double> fired_at_;
  double time_ = 0;
  double rate_;
};

ContinuousSettings settings(Method method, double event_tolerance = 1e-10) {
  ContinuousSettings s;
  s.integrator.method = method;
  s.integrator.step = 0.1;
  s.event_tolerance = event_tolerance;
  return s;
}

TEST(ContinuousRunTest, EventsFireAtTheInstantTheBoundaryIsReached) {
  for (Method method : {Method::kRungeKutta4, Method::kDormandPrince, Method::kCvode}) {
    SplittingCells cells({0.3});
    ContinuousRun run(cells, settings(method));
    run.start(0, 2.0);
    run.advance_to(2.0);
    // Splits at 0.7, then both halves at 1.2, then all four at 1.7.
    ASSERT_EQ(cells.fired_at_.size(), 1u + 2u + 4u);
    EXPECT_NEAR(cells.fired_at_[0], 0.7, 1e-9);
    for (int k = 1; k < 3; ++k) EXPECT_NEAR(cells.fired_at_[k], 1.2, 1e-9);
    for (int k = 3; k < 7; ++k) EXPECT_NEAR(cells.fired_at_[k], 1.7, 1e-9);
    EXPECT_EQ(cells.cells_.size(), 8u);
    // At t = 2 each cell has grown 0.3 since 1.7, from 0.5.
    for (double x : cells.cells_) EXPECT_NEAR(x, 0.8, 1e-8);
    EXPECT_EQ(run.events_fired(), 7u);
  }
}

TEST(ContinuousRunTest, ConditionsHoldingAtTheStartFireAtOnce) {
  SplittingCells cells({1.0, 0.25});
  ContinuousRun run(cells, settings(Method::kDormandPrince));
  run.start(0, 1);
  ASSERT_EQ(cells.fired_at_.size(), 1u);
  EXPECT_EQ(cells.fired_at_[0], 0.0);
  EXPECT_EQ(cells.cells_, (std::vector<double>{0.5, 0.5, 0.25}));
}

TEST(ContinuousRunTest, SamplesDoNotChangeTheEvents) {
  // The same run sampled every 0.1 and every 0.05: the events are the same
  // to the last bit, and the samples they share are equal.
  auto run_sampled = [](double dt, std::vector<std::vector<double>>* samples) {
    SplittingCells cells({0.3, 0.55});
    ContinuousRun run(cells, settings(Method::kDormandPrince));
    run.start(0, 3);
    for (int k = 0; k * dt <= 3 + 1e-12; ++k) {
      run.advance_to(k * dt);
      samples->push_back(cells.cells_);
    }
    return cells.fired_at_;
  };
  std::vector<std::vector<double>> coarse, fine;
  const std::vector<double> events_coarse = run_sampled(0.1, &coarse);
  const std::vector<double> events_fine = run_sampled(0.05, &fine);
  EXPECT_EQ(events_coarse, events_fine);
  for (std::size_t k = 0; k < coarse.size(); ++k) EXPECT_EQ(coarse[k], fine[2 * k]) << "sample " << k;
}

TEST(ContinuousRunTest, AnEventAtASampleTimeFiresBeforeTheSample) {
  SplittingCells cells({0.5});
  ContinuousRun run(cells, settings(Method::kRungeKutta4, 1e-12));
  run.start(0, 1);
  run.advance_to(0.5);  // the cell reaches 1 at 0.5 (to the tolerance)
  run.advance_to(0.5 + 1e-9);
  EXPECT_EQ(cells.cells_.size(), 2u);
}

TEST(ContinuousRunTest, EventsThatNeverSettleStopTheRun) {
  // A "split" that leaves the cell at the boundary fires for ever.
  class Stuck : public SplittingCells {
   public:
    Stuck() : SplittingCells({1.0}) {}
    std::size_t fire_events() override { return 0; }
  } stuck;
  ContinuousSettings s = settings(Method::kDormandPrince);
  s.max_event_rounds = 50;
  ContinuousRun run(stuck, s);
  try {
    run.start(0, 1);
    FAIL() << "no error";
  } catch (const ContinuousRunError& e) {
    EXPECT_NE(std::string(e.what()).find("events keep firing at t = 0"), std::string::npos) << e.what();
  }
}

TEST(ContinuousRunTest, ABlowUpIsReportedWithTheTimeReached) {
  // dx/dt = x^2 from x = 1 reaches infinity at t = 1.
  class BlowUp : public SplittingCells {
   public:
    BlowUp() : SplittingCells({1.0}) {}
    void rates(std::span<double> dy) override { dy[0] = cells_[0] * cells_[0]; }
    void read_events(std::vector<EventReading>& r) override { r.clear(); }
  } blow_up;
  ContinuousRun run(blow_up, settings(Method::kRungeKutta4));
  try {
    run.start(0, 2);
    run.advance_to(2);
    FAIL() << "no error";
  } catch (const ContinuousRunError& e) {
    EXPECT_LT(e.time(), 1.5);  // RK4 may step a little past the singularity before it overflows
    EXPECT_GT(e.time(), 0.5);
  }
}

TEST(ContinuousRunTest, GoingBackInTimeIsAnError) {
  SplittingCells cells({0.1});
  ContinuousRun run(cells, settings(Method::kDormandPrince));
  run.start(0, 1);
  run.advance_to(0.5);
  EXPECT_THROW(run.advance_to(0.25), std::invalid_argument);
}

}  // namespace
}  // namespace sylva::continuous
