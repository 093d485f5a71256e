// The derivation as the continuous scheduler sees it: the narrow interface
// of continuous/continuous_run.h over a Derivation.
#pragma once

#include "api/simulation.h"
#include "continuous/continuous_run.h"
#include "derive/derivation.h"

namespace sylva {

class Simulation::DerivationSystem : public continuous::ContinuousSystem {
 public:
  explicit DerivationSystem(derive::Derivation& derivation) : derivation_(derivation) {}
  void gather(std::vector<double>& y) override { derivation_.gather_state(y); }
  void set_state(double t, std::span<const double> y) override { derivation_.scatter_state(t, y); }
  void rates(std::span<double> dy) override { derivation_.evaluate_rates(dy); }
  void read_events(std::vector<continuous::EventReading>& readings) override { derivation_.read_events(readings); }
  std::size_t fire_events() override { return derivation_.fire_events(); }

 private:
  derive::Derivation& derivation_;
};

}  // namespace sylva
