// The C++ a cpfg model needs for its random numbers: the choice among
// stochastic productions and the streams of ran() and its kin. Internal to
// the cpfg front end.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sylva::lang::cpfg {

struct LsystemRandomness {
  int label = 0;
  bool stochastic = false;        // it has a seed: (its productions are chosen at random)
  std::string production_seed;    // C++ of that seed:
  std::string homomorphism_seed;  // C++ of its homomorphism's seed:; empty without one
};

struct RandomCode {
  std::string declarations;  // at namespace scope, before the rules
  std::string start;         // statements for the start of a run
  // Defines sylva_cpfg_before_module (kModelProbeProductions).
  bool chooses = false;
  // Defines int sylva_cpfg_restart_streams(), to be called at the start of
  // every interpretation pass.
  bool restarts_streams = false;
};

// `lsystems` in the model's order (the first is the main one); `rule_count`
// bounds the productions that can apply to one module.
RandomCode random_code(const std::vector<LsystemRandomness>& lsystems, std::size_t rule_count);

}  // namespace sylva::lang::cpfg
