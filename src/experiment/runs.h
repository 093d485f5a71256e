// The runs of a plan: every point of its parameter grid (or zip) times its
// replicates, numbered in a fixed order so that a run's number, its -D
// values and its seed depend on the plan alone.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiment/plan.h"

namespace sylva::experiment {

struct RunSpec {
  long number = 0;     // point · replicates + replicate
  long point = 0;      // which parameter combination
  int replicate = 0;
  std::optional<long> seed;  // replicate_seed(plan.seed, replicate), when the plan has replicates
  std::vector<std::pair<std::string, std::string>> values;  // (parameter, value) in the plan's order
  // "NAME=VALUE" as build options take them.
  std::vector<std::string> defines() const;
};

// All runs, by number. The grid varies the first parameter slowest.
std::vector<RunSpec> plan_runs(const Plan& plan);

// The first run of each distinct -D set among `runs` (a model is compiled
// once per set).
std::vector<RunSpec> one_run_per_define_set(const std::vector<RunSpec>& runs);

}  // namespace sylva::experiment
