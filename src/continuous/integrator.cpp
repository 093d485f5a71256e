#include "continuous/integrator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "continuous/methods.h"

namespace sylva::continuous {

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings, RightHandSide f) {
  if (!f) throw std::invalid_argument("an integrator needs a right-hand side");
  // NaN fails every comparison, so each check is written to let only good values pass.
  if (!(settings.relative_tolerance >= 0) || !(settings.absolute_tolerance >= 0) ||
      !std::isfinite(settings.relative_tolerance) || !std::isfinite(settings.absolute_tolerance) ||
      settings.relative_tolerance + settings.absolute_tolerance == 0)
    throw std::invalid_argument("integrator tolerances must be finite, not negative, and not both zero");
  if (!(settings.max_step >= 0)) throw std::invalid_argument("the integrator's max step must not be negative");
  if (!(settings.step > 0) || !std::isfinite(settings.step))
    throw std::invalid_argument("the integrator's step must be positive and finite");
  switch (settings.method) {
    case Method::kRungeKutta4: return make_runge_kutta4(settings, std::move(f));
    case Method::kDormandPrince: return make_dormand_prince(settings, std::move(f));
    case Method::kCvode: return make_cvode(settings, std::move(f));
  }
  throw std::invalid_argument("unknown integration method");
}

Method method_named(const std::string& name) {
  if (name == "rk4") return Method::kRungeKutta4;
  if (name == "rk45") return Method::kDormandPrince;
  if (name == "cvode") return Method::kCvode;
  throw std::invalid_argument("unknown integrator '" + name + "': choose rk4, rk45 or cvode");
}

bool all_finite(std::span<const double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

void throw_not_finite(double time) {
  throw IntegrationFailed(time, "the solution stopped being finite at t = " + time_text(time) +
                                    "; the system may be stiff: try --integrator cvode or a smaller step");
}

std::string time_text(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", t);
  return text;
}

void check_limit(double time, double t_limit) {
  if (!(t_limit > time))
    throw std::invalid_argument("an integrator step must end ahead of t = " + time_text(time) + ", not at " +
                                time_text(t_limit));
}

double within_step(double t, double t0, double t1) {
  // Callers compute the instants they ask for (sample times, event roots) in
  // floating point, so an end of the step may come back a few ulps outside it.
  const double slack = 64 * std::numeric_limits<double>::epsilon() * std::max({std::abs(t0), std::abs(t1), t1 - t0});
  if (!(t >= t0 - slack && t <= t1 + slack))
    throw std::out_of_range("cannot interpolate at t = " + time_text(t) + ": outside the last step [" +
                            time_text(t0) + ", " + time_text(t1) + "]");
  return std::clamp(t, t0, t1);
}

}  // namespace sylva::continuous
