// What the equations and events of a differential L-system use
// (docs/continuous-time.md): the time, the rates the translator writes for
// `d(x) = ...;`, and the growth functions of Prusinkiewicz, Hammel and
// Mjolsness, "Animation of plant development" (SIGGRAPH 1993).
#pragma once

#include <sylva/abi.h>
#include <sylva/runtime/functions.h>
#include <sylva/runtime/modules.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

// The time of a continuous run: where the equations are evaluated, or the
// instant an event fires (0 in a run of steps).
inline double CurrentTime() { return sylva::rt::control.time; }

// x(t) of the logistic equation dx/dt = r x (1 - x/xmax) with x(0) = x0.
inline double LogisticGrowth(double t, double x0, double r, double xmax) {
  return xmax / (1.0 + (xmax / x0 - 1.0) * std::exp(-r * t));
}
// The logistic equation's right-hand side, for `d(x) = LogisticRate(x, r, xmax);`.
inline double LogisticRate(double x, double r, double xmax) { return r * x * (1.0 - x / xmax); }

// The paper's cubic growth function G(dx, T): from 0 at t = 0 to dx at
// t = T with zero slope at both ends, extended to dx beyond T (and 0 before 0).
inline double CubicGrowth(double t, double dx, double T) {
  if (t <= 0) return 0;
  if (t >= T) return dx;
  const double s = t / T;
  return dx * s * s * (3.0 - 2.0 * s);
}
// Its derivative in t, for `d(x) = CubicGrowthRate(age, dx, T);`.
inline double CubicGrowthRate(double t, double dx, double T) {
  if (t <= 0 || t >= T) return 0;
  const double s = t / T;
  return dx * 6.0 * s * (1.0 - s) / T;
}

namespace sylva::rt {
// `d(x) = value;` in a derivative rule: the rate of the I-th parameter of the
// module the rule is for. Only a floating-point parameter changes continuously.
template <int I, class... T>
inline void set_rate(abi::RuleCall* call, double value) {
  static_assert(std::is_floating_point_v<typename ParamAt<I, T...>::type>,
                "d(p): only a float or double parameter can change continuously");
  call->rates[I] = value;
}
}  // namespace sylva::rt
