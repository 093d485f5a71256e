// SUNDIALS CVODE: variable-order BDF with Newton iterations on a dense
// finite-difference Jacobian, for the stiff systems the explicit methods
// cannot step. CVODE runs one internal step per call (CV_ONE_STEP) with the
// caller's limit as its stop time, so it never steps past the limit, and its
// Nordsieck history interpolates inside the last step.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "continuous/integrator.h"
#include "continuous/methods.h"

namespace sylva::continuous {
namespace {

struct FreeContext {
  void operator()(SUNContext context) const { SUNContext_Free(&context); }
};
struct FreeVector {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct FreeMatrix {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct FreeSolver {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
struct FreeCvode {
  void operator()(void* memory) const { CVodeFree(&memory); }
};
using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, FreeContext>;
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, FreeVector>;
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, FreeMatrix>;
using SolverPtr = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, FreeSolver>;
using CvodePtr = std::unique_ptr<void, FreeCvode>;

std::string flag_name(long flag) {
  // CVODE allocates the name and leaves it to the caller to free.
  std::unique_ptr<char, decltype(&std::free)> name(CVodeGetReturnFlagName(flag), &std::free);
  return name ? name.get() : "flag " + std::to_string(flag);
}

class Cvode final : public Integrator {
 public:
  Cvode(const IntegratorSettings& settings, RightHandSide f) : settings_(settings), f_(std::move(f)) {
    SUNContext context = nullptr;
    if (SUNContext_Create(nullptr, &context) != 0) throw std::runtime_error("cannot create a SUNDIALS context");
    context_.reset(context);
  }

  void reset(double t, std::span<const double> y) override {
    t_ = t_prev_ = t;
    n_ = y.size();
    if (n_ == 0) return;  // nothing to integrate; SUNDIALS is not asked to handle empty vectors
    if (!memory_ || N_VGetLength_Serial(y_.get()) != static_cast<sunindextype>(n_)) {
      // Release in the reverse of the order CVODE's memory refers to them.
      memory_.reset();
      solver_.reset();
      matrix_.reset();
      y_.reset();
      const auto n = static_cast<sunindextype>(n_);
      y_.reset(N_VNew_Serial(n, context_.get()));
      if (!y_) throw std::runtime_error("cannot allocate CVODE's state vector");
      std::copy(y.begin(), y.end(), N_VGetArrayPointer(y_.get()));
      create(t);
    } else {
      std::copy(y.begin(), y.end(), N_VGetArrayPointer(y_.get()));
      check(CVodeReInit(memory_.get(), t, y_.get()), "CVodeReInit");
    }
  }

  void restart(double t, std::span<const double> y) override {
    double last = 0;
    const bool stepped = memory_ && n_ == y.size() && CVodeGetLastStep(memory_.get(), &last) == CV_SUCCESS;
    reset(t, y);
    if (stepped && last > 0) check(CVodeSetInitStep(memory_.get(), last), "CVodeSetInitStep");
  }

  double step(double t_limit) override {
    check_limit(t_, t_limit);
    if (n_ == 0) {
      t_prev_ = t_;
      t_ = t_limit;
      return t_;
    }
    check(CVodeSetStopTime(memory_.get(), t_limit), "CVodeSetStopTime");
    rhs_failure_ = nullptr;
    message_.clear();
    double t_reached = t_;
    const int flag = CVode(memory_.get(), t_limit, y_.get(), &t_reached, CV_ONE_STEP);
    // An exception from f could not cross CVODE's C frames; it was kept for here.
    if (rhs_failure_) std::rethrow_exception(std::exchange(rhs_failure_, nullptr));
    if (flag < 0) {
      if (rhs_not_finite_) throw_not_finite(t_);
      std::string what = "CVODE could not take a step at t = " + time_text(t_) + ": " + flag_name(flag);
      if (!message_.empty()) what += " (" + message_ + ")";
      throw IntegrationFailed(t_, what);
    }
    if (!all_finite(state())) throw_not_finite(t_);
    t_prev_ = t_;
    // The stop time is reached by interpolation within rounding of it: report it exactly.
    t_ = flag == CV_TSTOP_RETURN ? t_limit : std::min(t_reached, t_limit);
    // Closing in on a point past which f is not finite, CVODE shrinks its
    // step until t + h == t and then goes on "succeeding" without moving.
    // The state is that of t_, so the failure is reported from there.
    if (flag != CV_TSTOP_RETURN && t_ - t_prev_ < 1e-14 * std::max(1.0, std::abs(t_prev_))) {
      if (rhs_not_finite_) throw_not_finite(t_);
      throw IntegrationFailed(t_, "step size underflow at t = " + time_text(t_) + ": CVODE's step fell to " +
                                      time_text(t_ - t_prev_));
    }
    rhs_not_finite_ = false;
    return t_;
  }

  double time() const override { return t_; }
  std::span<const double> state() const override {
    if (n_ == 0) return {};
    return {N_VGetArrayPointer(y_.get()), n_};
  }

  void interpolate(double t, std::span<double> y) const override {
    if (n_ == 0) return;
    t = within_step(t, t_prev_, t_);
    if (t == t_) {
      std::copy_n(N_VGetArrayPointer(y_.get()), n_, y.begin());
      return;
    }
    // A vector that wraps the caller's span: CVODE writes straight into it.
    VectorPtr out(N_VMake_Serial(static_cast<sunindextype>(n_), y.data(), context_.get()));
    if (!out) throw std::runtime_error("cannot allocate a CVODE vector");
    const int flag = CVodeGetDky(memory_.get(), t, 0, out.get());
    if (flag < 0) throw std::out_of_range("CVODE cannot interpolate at t = " + time_text(t) + ": " + flag_name(flag));
  }

  std::size_t evaluations() const override { return evaluations_; }

 private:
  // Systems up to this size use a dense Jacobian (at most 1.9 MB).
  static constexpr sunindextype kLargestDenseSystem = 500;

  void create(double t) {
    const auto n = static_cast<sunindextype>(n_);
    memory_.reset(CVodeCreate(CV_BDF, context_.get()));
    if (!memory_) throw std::runtime_error("cannot create CVODE's memory");
    void* memory = memory_.get();
    check(CVodeSetErrHandlerFn(memory, &Cvode::on_error, this), "CVodeSetErrHandlerFn");
    check(CVodeInit(memory, &Cvode::rhs, t, y_.get()), "CVodeInit");
    check(CVodeSetUserData(memory, this), "CVodeSetUserData");
    check(CVodeSStolerances(memory, settings_.relative_tolerance, settings_.absolute_tolerance), "CVodeSStolerances");
    check(CVodeSetInitStep(memory, settings_.step), "CVodeSetInitStep");
    if (settings_.max_step > 0) check(CVodeSetMaxStep(memory, settings_.max_step), "CVodeSetMaxStep");
    if (n > kLargestDenseSystem) {
      // A dense Jacobian grows as n^2 (80 GB for a filament of 10^5 cells):
      // large systems solve Newton's equations by GMRES on Jacobian-vector
      // products, which CVODE approximates by differences of f.
      solver_.reset(SUNLinSol_SPGMR(y_.get(), SUN_PREC_NONE, 0, context_.get()));
      if (!solver_) throw std::runtime_error("cannot create CVODE's linear solver");
      check(CVodeSetLinearSolver(memory, solver_.get(), nullptr), "CVodeSetLinearSolver");
      return;
    }
    matrix_.reset(SUNDenseMatrix(n, n, context_.get()));
    if (!matrix_) throw std::runtime_error("cannot allocate CVODE's Jacobian matrix");
    solver_.reset(SUNLinSol_Dense(y_.get(), matrix_.get(), context_.get()));
    if (!solver_) throw std::runtime_error("cannot create CVODE's linear solver");
    // No Jacobian function: CVODE approximates it by finite differences.
    check(CVodeSetLinearSolver(memory, solver_.get(), matrix_.get()), "CVodeSetLinearSolver");
  }

  void check(int flag, const char* call) const {
    if (flag < 0)
      throw std::runtime_error(std::string(call) + " failed: " + flag_name(flag) +
                               (message_.empty() ? "" : " (" + message_ + ")"));
  }

  static int rhs(double t, N_Vector y, N_Vector ydot, void* user_data) {
    auto& self = *static_cast<Cvode*>(user_data);
    ++self.evaluations_;
    const std::span<double> dy(N_VGetArrayPointer(ydot), self.n_);
    try {
      self.f_(t, std::span<const double>(N_VGetArrayPointer(y), self.n_), dy);
    } catch (...) {
      self.rhs_failure_ = std::current_exception();
      return -1;  // unrecoverable: CVODE returns at once
    }
    // A positive value asks CVODE to retry with a smaller step, which is
    // what a state driven out of the region where f is finite needs.
    if (!all_finite(dy) || !all_finite(std::span<const double>(N_VGetArrayPointer(y), self.n_))) {
      self.rhs_not_finite_ = true;
      return 1;
    }
    return 0;
  }

  static void on_error(int, const char*, const char*, char* message, void* user_data) {
    static_cast<Cvode*>(user_data)->message_ = message ? message : "";
  }

  IntegratorSettings settings_;
  RightHandSide f_;
  std::size_t n_ = 0;
  double t_ = 0, t_prev_ = 0;
  std::size_t evaluations_ = 0;
  std::exception_ptr rhs_failure_;
  bool rhs_not_finite_ = false;  // since the last step of a reasonable size
  std::string message_;  // CVODE's own account of its last error
  // Declared in the order they are made, so they are released in reverse.
  ContextPtr context_;
  VectorPtr y_;
  MatrixPtr matrix_;
  SolverPtr solver_;
  CvodePtr memory_;
};

}  // namespace

std::unique_ptr<Integrator> make_cvode(const IntegratorSettings& settings, RightHandSide f) {
  return std::make_unique<Cvode>(settings, std::move(f));
}

}  // namespace sylva::continuous
