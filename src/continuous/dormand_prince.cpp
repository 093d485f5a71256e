// Dormand-Prince RK5(4): seven stages, the fifth-order solution carried on,
// the embedded fourth-order one used only to estimate the error. The last
// stage is f at the new point, so it is the next step's first (FSAL).
//
// Dense output is the fourth-order continuous extension: a cubic Hermite
// interpolant on the step's ends plus theta^2 (1 - theta)^2 h sum d_i k_i.
// The order-4 conditions on the weights b_i(theta) leave a one-parameter
// family of d; d7 is the member that minimises the sum of the squared
// fifth-order error coefficients (each divided by its tree's symmetry) at the
// midpoint, Shampine's criterion. Solved exactly in rationals, which gives the
// values published by Hairer, Norsett and Wanner.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "continuous/integrator.h"
#include "continuous/methods.h"

namespace sylva::continuous {
namespace {

constexpr int kStages = 7;
constexpr std::array<double, kStages> c = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
constexpr double a[kStages][kStages - 1] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
// The fifth-order weights are the last row of a; these are fifth minus fourth order.
constexpr std::array<double, kStages> e = {71.0 / 57600,      0, -71.0 / 16695, 71.0 / 1920,
                                           -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
constexpr std::array<double, kStages> d = {
    -12715105075.0 / 11282082432.0,  0, 87487479700.0 / 32700410799.0, -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0, -1453857185.0 / 822651844.0, 69997945.0 / 29380423.0};

constexpr double kSafety = 0.9, kMinFactor = 0.2, kMaxFactor = 5;

class DormandPrince final : public Integrator {
 public:
  DormandPrince(const IntegratorSettings& settings, RightHandSide f)
      : first_step_(settings.step),
        max_step_(settings.max_step),
        rtol_(settings.relative_tolerance),
        atol_(settings.absolute_tolerance),
        f_(std::move(f)) {}

  void reset(double t, std::span<const double> y) override {
    const std::size_t n = y.size();
    t_ = t_prev_ = t;
    y_.assign(y.begin(), y.end());
    for (auto& k : k_) k.assign(n, 0.0);
    for (auto* v : {&y_new_, &r2_, &r3_, &r4_, &r5_}) v->assign(n, 0.0);
    y_prev_ = y_;
    have_k1_ = false;
    h_ = first_step_;
  }

  void restart(double t, std::span<const double> y) override {
    const double h = h_;
    reset(t, y);
    if (h > 0) h_ = h;
  }

  double step(double t_limit) override {
    check_limit(t_, t_limit);
    const std::size_t n = y_.size();
    if (n == 0) {
      t_prev_ = t_;
      t_ = t_limit;
      return t_;
    }
    if (!have_k1_) evaluate(t_, y_, k_[0]);
    have_k1_ = true;

    double h = max_step_ > 0 ? std::min(h_, max_step_) : h_;
    bool rejected = false, not_finite = false;
    for (;;) {
      // The controller's step, before the limit clips it: only this one
      // can underflow, as a caller may well ask for a tiny last step.
      const double h_wanted = h;
      if (h_wanted < 1e-14 * std::max(1.0, std::abs(t_))) underflow(h_wanted, not_finite);
      // Within 1% of the limit, stretch to it instead of leaving a sliver.
      const bool last = t_ + 1.01 * h >= t_limit && (max_step_ <= 0 || t_limit - t_ <= max_step_);
      if (last) h = t_limit - t_;

      const double err = attempt(h);
      if (std::isfinite(err) && all_finite(y_new_) && all_finite(k_[6])) {
        double factor = err == 0 ? kMaxFactor : std::clamp(kSafety * std::pow(err, -0.2), kMinFactor, kMaxFactor);
        if (err <= 1) {
          // Right after a rejection, growing again invites another one.
          if (rejected) factor = std::min(factor, 1.0);
          // A step cut short by the limit says little about the step the
          // solution allows: keep the size that was wanted when that was fine.
          h_ = last && factor >= 1 ? std::max(h_wanted, h * factor) : h * factor;
          accept(h, last ? t_limit : t_ + h);
          return t_;
        }
        h *= factor;
        not_finite = false;
      } else {
        // Values beyond range are an error too large to measure: shrink as
        // hard as the controller allows and try again.
        h *= kMinFactor;
        not_finite = true;
      }
      rejected = true;
    }
  }

  double time() const override { return t_; }
  std::span<const double> state() const override { return y_; }

  void interpolate(double t, std::span<double> y) const override {
    t = within_step(t, t_prev_, t_);
    const double h = t_ - t_prev_;
    const double s = h == 0 ? 1 : (t - t_prev_) / h;
    const double r = 1 - s;
    for (std::size_t i = 0; i < y_.size(); ++i)
      y[i] = y_prev_[i] + s * (r2_[i] + r * (r3_[i] + s * (r4_[i] + r * r5_[i])));
  }

  std::size_t evaluations() const override { return evaluations_; }

 private:
  void evaluate(double t, std::span<const double> y, std::span<double> dy) {
    ++evaluations_;
    f_(t, y, dy);
  }

  // Computes stages 2..7 and y_new_ for a step h; returns the RMS error norm.
  double attempt(double h) {
    const std::size_t n = y_.size();
    for (int s = 1; s < kStages; ++s) {
      for (std::size_t i = 0; i < n; ++i) {
        double sum = 0;
        for (int j = 0; j < s; ++j) sum += a[s][j] * k_[j][i];
        y_new_[i] = y_[i] + h * sum;
      }
      evaluate(t_ + c[s] * h, y_new_, k_[s]);
    }
    // The seventh stage was taken at y_new_ itself (the row a[6] is b).
    double sum_sq = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double err = 0;
      for (int j = 0; j < kStages; ++j) err += e[j] * k_[j][i];
      const double scale = atol_ + rtol_ * std::max(std::abs(y_[i]), std::abs(y_new_[i]));
      const double ratio = h * err / scale;
      sum_sq += ratio * ratio;
    }
    return std::sqrt(sum_sq / static_cast<double>(n));
  }

  void accept(double h, double t_new) {
    const std::size_t n = y_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double dy = y_new_[i] - y_[i];
      const double k1h = h * k_[0][i];
      double dense = 0;
      for (int j = 0; j < kStages; ++j) dense += d[j] * k_[j][i];
      r2_[i] = dy;
      r3_[i] = k1h - dy;
      r4_[i] = dy - h * k_[6][i] - r3_[i];
      r5_[i] = h * dense;
    }
    std::swap(y_prev_, y_);
    std::swap(y_, y_new_);
    std::swap(k_[0], k_[6]);
    t_prev_ = t_;
    t_ = t_new;
  }

  [[noreturn]] void underflow(double h, bool not_finite) const {
    if (not_finite) throw_not_finite(t_);
    throw IntegrationFailed(t_, "step size underflow at t = " + time_text(t_) + ": the step fell to " +
                                    time_text(h) + " without meeting the tolerances");
  }

  double first_step_, max_step_, rtol_, atol_;
  RightHandSide f_;
  double t_ = 0, t_prev_ = 0;
  double h_ = 0;  // the next step to try
  std::vector<double> y_, y_prev_, y_new_;
  std::array<std::vector<double>, kStages> k_;
  bool have_k1_ = false;
  // Dense output of the last step: y_prev_ + s (r2 + (1-s) (r3 + s (r4 + (1-s) r5))).
  std::vector<double> r2_, r3_, r4_, r5_;
  std::size_t evaluations_ = 0;
};

}  // namespace

std::unique_ptr<Integrator> make_dormand_prince(const IntegratorSettings& settings, RightHandSide f) {
  return std::make_unique<DormandPrince>(settings, std::move(f));
}

}  // namespace sylva::continuous
