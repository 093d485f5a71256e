// The integrators behind make_integrator, one per source file, and what they
// share: the check that a state is still finite and the failure it raises.
#pragma once

#include <memory>
#include <span>
#include <string>

#include "continuous/integrator.h"

namespace sylva::continuous {

std::unique_ptr<Integrator> make_runge_kutta4(const IntegratorSettings& settings, RightHandSide f);
std::unique_ptr<Integrator> make_dormand_prince(const IntegratorSettings& settings, RightHandSide f);
std::unique_ptr<Integrator> make_cvode(const IntegratorSettings& settings, RightHandSide f);

bool all_finite(std::span<const double> values);

// `time` is how far the solution is known to be finite: the start of the
// step that produced the bad values.
[[noreturn]] void throw_not_finite(double time);

// Throws std::invalid_argument unless `t_limit` lies ahead of `time`.
void check_limit(double time, double t_limit);

// Throws std::out_of_range unless `t` lies in the last step [t0, t1], give or
// take rounding; returns t pulled into the step.
double within_step(double t, double t0, double t1);

}  // namespace sylva::continuous
