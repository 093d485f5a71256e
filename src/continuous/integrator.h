// Integrators of a system of ordinary differential equations y' = f(t, y),
// stepped one step at a time so that a caller can look inside each step
// (dense output) for the instants it cares about: sample times and the
// events of a differential L-system (docs/continuous-time.md).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

namespace sylva::continuous {

// dy = f(t, y); both spans have the system's size.
using RightHandSide = std::function<void(double t, std::span<const double> y, std::span<double> dy)>;

enum class Method {
  kRungeKutta4,    // classical RK4, fixed step `step`
  kDormandPrince,  // adaptive RK5(4), error per step within the tolerances
  kCvode,          // SUNDIALS CVODE, variable-order BDF: stiff systems
};

struct IntegratorSettings {
  Method method = Method::kDormandPrince;
  double step = 0.01;             // RK4's step; the first step tried by the adaptive methods
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-9;
  double max_step = 0;            // 0: no limit below the distance asked for
};

// A step that cannot be taken: the solution grew without bound (a stiff
// system under an explicit method, a model whose equations blow up), or the
// step size fell below what double precision resolves.
class IntegrationFailed : public std::runtime_error {
 public:
  IntegrationFailed(double time, const std::string& what) : std::runtime_error(what), time_(time) {}
  double time() const { return time_; }  // how far the solution was computed

 private:
  double time_;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Starts again at (t, y); the system's size may differ from before.
  virtual void reset(double t, std::span<const double> y) = 0;
  // The same after a jump of the state (an event): an adaptive method starts
  // with the step it had come to rather than the first step of the settings,
  // which the size of a model's steps rarely has anything to do with.
  virtual void restart(double t, std::span<const double> y) { reset(t, y); }
  // Advances one step, not past `t_limit` (> time()); returns the new time.
  // Throws IntegrationFailed when no step can be taken or the state stops
  // being finite.
  virtual double step(double t_limit) = 0;
  // The time and state after the last step (or the reset).
  virtual double time() const = 0;
  virtual std::span<const double> state() const = 0;
  // The solution at t within the last step [previous time, time()], from the
  // method's own interpolant (accurate to about the method's order).
  virtual void interpolate(double t, std::span<double> y) const = 0;
  // Evaluations of the right-hand side so far.
  virtual std::size_t evaluations() const = 0;
};

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings, RightHandSide f);

// "rk4", "rk45" or "cvode"; throws std::invalid_argument naming the choices.
Method method_named(const std::string& name);

// A time as it reads in messages: short, but enough digits to tell close
// instants apart.
std::string time_text(double t);

}  // namespace sylva::continuous
