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

// What every run of a plan starts from: the build options and the plan's
// inputs, one thread per run.
SimulationOptions run_options(const Plan& plan, const ExperimentOptions& options);

// A plan checked against its model, ready to run.
struct PreparedExperiment {
  std::vector<RunSpec> runs;
  SimulationOptions base;  // run_options()
  RunRecord model;         // what the table's provenance record says of the model
};

// Checks the plan against its model before anything runs: every -D set
// compiles, every parameter is a name the model uses, every measure reads
// modules the model declares. ModelError at the plan's line otherwise.
PreparedExperiment prepare_experiment(const Plan& plan, const ExperimentOptions& options);

// Runs every run, writes the table (and the plot the plan asks for).
ExperimentReport run_experiment(const Plan& plan, const PreparedExperiment& prepared, const ExperimentOptions& options);
// Prepares, then runs.
ExperimentReport run_experiment(const Plan& plan, const ExperimentOptions& options);

// What a worker does with one run: runs it in a process forked for it (a
// crash, or the plan's timeout, ends only that process).
RunResult run_in_own_process(const Plan& plan, const RunSpec& run, const SimulationOptions& base);

}  // namespace sylva::experiment
