// `sylva experiment PLAN.toml`: parameter sweeps and replicates of a model,
// measured into one table (docs/experiments.md); the same command under
// mpirun or srun spreads the runs over the job's ranks.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "build/model_builder.h"

namespace sylva::app {

struct ExperimentCommandOptions {
  std::string plan;
  int jobs = 0;
  bool no_progress = false;
};

CLI::App* add_experiment_command(CLI::App& app, ExperimentCommandOptions& options);
int run_experiment_command(const ExperimentCommandOptions& options, const build::BuildOptions& build);

}  // namespace sylva::app
