#include "continuous/continuous_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace sylva::continuous {
namespace {

// The largest margin: it crosses zero where the first condition starts to hold.
double largest_margin(const std::vector<EventReading>& readings) {
  double m = -std::numeric_limits<double>::infinity();
  for (const EventReading& r : readings) m = std::max(m, r.margin);
  return m;
}

}  // namespace

ContinuousRun::ContinuousRun(ContinuousSystem& system, const ContinuousSettings& settings)
    : system_(system), settings_(settings) {
  integrator_ = make_integrator(settings_.integrator, [this](double t, std::span<const double> y, std::span<double> dy) {
    system_.set_state(t, y);
    system_.rates(dy);
  });
}

ContinuousRun::~ContinuousRun() = default;

void ContinuousRun::start(double t0, double horizon) {
  time_ = t0;
  horizon_ = std::max(horizon, t0);
  system_.gather(y_);
  system_.set_state(t0, y_);
  settle_events();
  restart_integrator(true);
}

void ContinuousRun::restart_integrator(bool first) {
  system_.gather(y_);
  if (first) integrator_->reset(time_, y_);
  else integrator_->restart(time_, y_);
  system_.set_state(time_, y_);  // the integrator's evaluations may have moved it
  valid_until_ = time_;
  event_pending_ = false;
}

void ContinuousRun::advance_to(double t) {
  if (t < time_) throw std::invalid_argument("a continuous run cannot go back in time");
  for (;;) {
    // An event at exactly `t` fires before the state at `t` is given.
    if (event_pending_ ? t < valid_until_ : t <= valid_until_) {
      if (t != time_) set_interpolated(t);
      time_ = t;
      return;
    }
    if (event_pending_) {
      time_ = valid_until_;
      set_interpolated(time_);
      settle_events();
      restart_integrator(false);
      continue;
    }
    if (valid_until_ >= horizon_) horizon_ = t;  // asked past the end given at start
    const double t0 = integrator_->time();
    double t1;
    try {
      t1 = integrator_->step(horizon_);
    } catch (const IntegrationFailed& failed) {
      throw ContinuousRunError(failed.time(), std::string(failed.what()));
    }
    ++steps_;
    system_.set_state(t1, integrator_->state());
    if (!any_holds()) {
      valid_until_ = t1;
      continue;
    }
    valid_until_ = locate_event(t0, t1);
    event_pending_ = true;
  }
}

void ContinuousRun::set_interpolated(double t) {
  scratch_.resize(y_.size());
  integrator_->interpolate(t, scratch_);
  system_.set_state(t, scratch_);
}

bool ContinuousRun::any_holds() {
  system_.read_events(readings_);
  return std::any_of(readings_.begin(), readings_.end(), [](const EventReading& r) { return r.holds; });
}

double ContinuousRun::locate_event(double t0, double t1) {
  // Regula falsi on the largest margin, with the Illinois change (a value kept
  // twice in a row is halved), bracketed by where some condition holds: a
  // condition whose margin says nothing (a plain boolean: +-1) is bisected.
  double a = t0, b = t1;
  double ga = -1, gb = largest_margin(readings_);
  set_interpolated(t0);
  ++probes_;
  if (!any_holds()) ga = largest_margin(readings_);
  int kept = 0;  // -1: a kept last time, +1: b kept
  const double tolerance = std::max(settings_.event_tolerance, 4 * std::numeric_limits<double>::epsilon() * std::abs(t1));
  while (b - a > tolerance) {
    double t = 0.5 * (a + b);
    if (ga < 0 && gb >= 0 && std::isfinite(ga) && std::isfinite(gb) && gb - ga > 0) {
      t = a + (b - a) * (-ga) / (gb - ga);
      // Keep the bracket shrinking: never within a tenth of the tolerance of an end.
      t = std::clamp(t, a + 0.1 * tolerance, b - 0.1 * tolerance);
    }
    set_interpolated(t);
    ++probes_;
    const bool holds = any_holds();
    const double g = largest_margin(readings_);
    if (holds) {
      b = t, gb = std::max(g, 0.0);
      if (kept == -1) ga *= 0.5;
      kept = -1;
    } else {
      a = t, ga = std::min(g, -std::numeric_limits<double>::min());
      if (kept == 1) gb *= 0.5;
      kept = 1;
    }
  }
  return b;
}

void ContinuousRun::settle_events() {
  for (int round = 0;; ++round) {
    system_.read_events(readings_);
    if (std::none_of(readings_.begin(), readings_.end(), [](const EventReading& r) { return r.holds; })) return;
    if (round == settings_.max_event_rounds)
      throw ContinuousRunError(time_, "events keep firing at t = " + time_text(time_) + ": after " +
                                          std::to_string(round) +
                                          " rounds an event's condition still holds; its production must "
                                          "take the module out of the condition (or remove it)");
    events_fired_ += system_.fire_events();  // the new state, which restart_integrator gathers
  }
}

}  // namespace sylva::continuous
