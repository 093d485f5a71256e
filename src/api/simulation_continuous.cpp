// Continuous time of a Simulation: a differential L-system's state
// integrated between events (continuous/continuous_run.h).
#include <string>

#include "api/derivation_system.h"
#include "api/simulation.h"
#include "support/diagnostic.h"

namespace sylva {
bool Simulation::continuous() const { return derivation_->has_continuous_rules(); }

double Simulation::time() const { return continuous_run_ ? continuous_run_->time() : 0.0; }

Simulation::ContinuousCounts Simulation::continuous_counts() const {
  if (!continuous_run_) return {};
  return {continuous_run_->events_fired(), continuous_run_->integrator_steps(), continuous_run_->evaluations(),
          continuous_run_->event_location_probes()};
}

void Simulation::advance_to(double t) {
  begin();
  RunBudget::Scope bounded(budget_);
  try {
    if (!continuous_run_) {
      continuous_system_ = std::make_unique<DerivationSystem>(*derivation_);
      continuous_run_ = std::make_unique<continuous::ContinuousRun>(*continuous_system_, continuous_settings_);
      continuous_run_->start(0.0, continuous_settings_.end_time > 0 ? continuous_settings_.end_time : t);
      check_string_limits();
    }
    continuous_run_->advance_to(t);
  } catch (const continuous::ContinuousRunError& e) {
    throw ModelError(SourceLocation{model_path_, 0, 0},
                     std::string(e.what()) + " (the run reached t = " + continuous::time_text(e.time()) + ")");
  }
  check_string_limits();
  act_on_requests(RequestSource::Rules);
}

}  // namespace sylva
