// `sylva experiment PLAN`: an experiment plan (experiment/plan.h) run on the
// cores of this machine and, under MPI, on the ranks of a cluster job; its
// measures written as one tidy table (docs/experiments.md).
#pragma once

#include <cstddef>

#include "api/provenance.h"
#include "api/simulation.h"
#include "experiment/plan.h"
#include "experiment/workers.h"

namespace sylva::experiment {

struct ExperimentOptions {
  SimulationOptions simulation;  // the build options every run starts from
  int jobs = 0;                  // runs at once on this machine; 0: one per core
  bool progress = false;         // a bar with the ETA on standard error
  Workers* remote = nullptr;     // other machines' workers (MPI ranks), beside this one's
};

struct ExperimentReport {
  std::size_t runs = 0, failed = 0;
  double seconds = 0;
};

// Checks the plan against its model before anything runs: every -D set
// compiles, every parameter is a name the model uses, every measure reads
// modules the model declares. ModelError at the plan's line otherwise.
// Returns what the table's provenance record says of the model.
RunRecord prepare_experiment(const Plan& plan, const ExperimentOptions& options);

// Prepares, runs every run, writes the table (and the plot the plan asks for).
ExperimentReport run_experiment(const Plan& plan, const ExperimentOptions& options);

// What a worker does with one run: its result as one line of text.
std::string run_to_text(const Plan& plan, const RunSpec& run, const SimulationOptions& base);

}  // namespace sylva::experiment
