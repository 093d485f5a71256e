// Continuous time for a differential L-system (docs/continuous-time.md):
// the state (the continuously changing parameters of the string's modules)
// is integrated between events; each event is located to a tolerance, its
// productions applied at that instant, and integration goes on from the new
// string. The times a caller asks for (samples at 0, dt, 2dt ...) are read
// off the integrator's dense output: they never change the integrator's
// steps, so the sequence of events does not depend on them.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "continuous/integrator.h"

namespace sylva::continuous {

// One event condition of one module at the state set last: whether it holds
// and its margin (>= 0 where it holds, crossing zero where it starts to).
struct EventReading {
  bool holds;
  double margin;
};

// What the scheduler needs of a model: a narrow interface, so that it can
// be tested with a system of its own (tests/continuous).
class ContinuousSystem {
 public:
  virtual ~ContinuousSystem() = default;
  // The state of the current string, in a fixed order until fire_events().
  virtual void gather(std::vector<double>& y) = 0;
  // Sets the time and the state that the calls below see.
  virtual void set_state(double t, std::span<const double> y) = 0;
  // The rates of change of the state set last.
  virtual void rates(std::span<double> dy) = 0;
  // The event conditions at the state set last, in a fixed order until fire_events().
  virtual void read_events(std::vector<EventReading>& readings) = 0;
  // Applies the productions of the events that hold at the state set last;
  // returns how many were applied. What they produce is the state set now.
  virtual std::size_t fire_events() = 0;
};

struct ContinuousSettings {
  IntegratorSettings integrator;
  // An event is placed within this much time after the instant its
  // condition becomes true.
  double event_tolerance = 1e-9;
  // Rounds of events at one instant (an event whose production leaves a
  // condition true fires another round) before the run is stopped as one
  // whose events never settle.
  int max_event_rounds = 1000;
  // The run's end: the integrator's steps go up to it, whatever the times
  // asked for in between (0: the first time asked for).
  double end_time = 0;
};

// A run that cannot go on: the integrator failed, or the events at an
// instant never settle. `time` is how far the run got.
class ContinuousRunError : public std::runtime_error {
 public:
  ContinuousRunError(double time, const std::string& what) : std::runtime_error(what), time_(time) {}
  double time() const { return time_; }

 private:
  double time_;
};

class ContinuousRun {
 public:
  ContinuousRun(ContinuousSystem& system, const ContinuousSettings& settings);
  ~ContinuousRun();

  // Starts at `t0`, firing the events whose conditions already hold.
  // `horizon` bounds the integrator's steps: the run's end, so that the
  // steps are those of the whole run whatever the samples asked for.
  void start(double t0, double horizon);
  // Advances to `t` (>= time()), firing every event on the way; the system
  // is left at the state at `t`, after any event at exactly `t`.
  void advance_to(double t);

  double time() const { return time_; }
  std::size_t events_fired() const { return events_fired_; }
  std::size_t integrator_steps() const { return steps_; }
  std::size_t evaluations() const { return integrator_ ? integrator_->evaluations() : 0; }
  std::size_t event_location_probes() const { return probes_; }

 private:
  // The system at `t` on the current step's dense output.
  void set_interpolated(double t);
  bool any_holds();
  // The instant in (t0, t1] where a condition first holds, within the tolerance.
  double locate_event(double t0, double t1);
  // Events at the current instant, round after round until none holds.
  void settle_events();
  // From the state of the string: the run's first start, or after events.
  void restart_integrator(bool first);

  ContinuousSystem& system_;
  ContinuousSettings settings_;
  std::unique_ptr<Integrator> integrator_;
  std::vector<double> y_, scratch_;
  std::vector<EventReading> readings_;
  double time_ = 0, horizon_ = 0;
  double valid_until_ = 0;      // the dense output holds up to here (no event before)
  bool event_pending_ = false;  // an event fires at valid_until_
  std::size_t events_fired_ = 0, steps_ = 0, probes_ = 0;
};

}  // namespace sylva::continuous
