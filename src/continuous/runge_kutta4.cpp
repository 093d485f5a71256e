// Classical fourth-order Runge-Kutta with a fixed step. It keeps f at the end
// of each step: that is the next step's first stage, and with f at the start
// it gives a cubic Hermite interpolant inside the step at no extra cost.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "continuous/integrator.h"
#include "continuous/methods.h"

namespace sylva::continuous {
namespace {

class RungeKutta4 final : public Integrator {
 public:
  RungeKutta4(const IntegratorSettings& settings, RightHandSide f) : step_(settings.step), f_(std::move(f)) {}

  void reset(double t, std::span<const double> y) override {
    const std::size_t n = y.size();
    t_ = t_prev_ = t;
    y_.assign(y.begin(), y.end());
    y_prev_ = y_;
    for (auto* v : {&f_end_, &f_prev_, &k2_, &k3_, &k4_, &scratch_}) v->assign(n, 0.0);
    have_f_end_ = false;
  }

  double step(double t_limit) override {
    check_limit(t_, t_limit);
    const std::size_t n = y_.size();
    if (n == 0) {
      t_prev_ = t_;
      t_ = t_limit;
      return t_;
    }
    // The last step is stretched by rounding's worth rather than leaving a
    // sliver of a step, whose Hermite interpolant would be ill-conditioned.
    const bool last = t_limit - t_ <= step_ * (1 + 1e-9);
    const double h = last ? t_limit - t_ : step_;
    const double t_next = last ? t_limit : t_ + h;
    if (!have_f_end_) evaluate(t_, y_, f_end_);

    const std::span<const double> k1 = f_end_;
    stage(h / 2, k1);
    evaluate(t_ + h / 2, scratch_, k2_);
    stage(h / 2, k2_);
    evaluate(t_ + h / 2, scratch_, k3_);
    stage(h, k3_);
    evaluate(t_ + h, scratch_, k4_);
    for (std::size_t i = 0; i < n; ++i) scratch_[i] = y_[i] + h / 6 * (k1[i] + 2 * (k2_[i] + k3_[i]) + k4_[i]);
    // An explicit method that has blown up does not recover by going on; the
    // state is left at the last finite step.
    if (!all_finite(scratch_)) throw_not_finite(t_);

    std::swap(y_prev_, y_);
    std::swap(y_, scratch_);
    std::swap(f_prev_, f_end_);
    t_prev_ = t_;
    t_ = t_next;
    evaluate(t_, y_, f_end_);
    have_f_end_ = true;
    return t_;
  }

  double time() const override { return t_; }
  std::span<const double> state() const override { return y_; }

  void interpolate(double t, std::span<double> y) const override {
    t = within_step(t, t_prev_, t_);
    const double h = t_ - t_prev_;
    if (h == 0) {
      std::copy(y_.begin(), y_.end(), y.begin());
      return;
    }
    const double s = (t - t_prev_) / h;
    const double r = 1 - s;
    const double h00 = (1 + 2 * s) * r * r, h10 = s * r * r, h01 = s * s * (3 - 2 * s), h11 = -s * s * r;
    for (std::size_t i = 0; i < y_.size(); ++i)
      y[i] = h00 * y_prev_[i] + h01 * y_[i] + h * (h10 * f_prev_[i] + h11 * f_end_[i]);
  }

  std::size_t evaluations() const override { return evaluations_; }

 private:
  void evaluate(double t, std::span<const double> y, std::span<double> dy) {
    ++evaluations_;
    f_(t, y, dy);
  }
  // scratch = y + a k: the argument of the next stage.
  void stage(double a, std::span<const double> k) {
    for (std::size_t i = 0; i < y_.size(); ++i) scratch_[i] = y_[i] + a * k[i];
  }

  double step_;
  RightHandSide f_;
  double t_ = 0, t_prev_ = 0;
  std::vector<double> y_, y_prev_;
  std::vector<double> f_end_, f_prev_;  // f at the ends of the last step
  bool have_f_end_ = false;
  std::vector<double> k2_, k3_, k4_, scratch_;
  std::size_t evaluations_ = 0;
};

}  // namespace

std::unique_ptr<Integrator> make_runge_kutta4(const IntegratorSettings& settings, RightHandSide f) {
  return std::make_unique<RungeKutta4>(settings, std::move(f));
}

}  // namespace sylva::continuous
