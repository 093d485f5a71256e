#include "app/experiment_command.h"

#include <unistd.h>

#include <cstdio>

#include "experiment/experiment.h"
#include "experiment/mpi_session.h"

namespace sylva::app {
namespace {

using namespace sylva::experiment;

void print_report(const Plan& plan, const ExperimentReport& report) {
  std::fprintf(stderr, "sylva: %zu runs in %.1f s (%.2f runs/s)%s; table: %s\n", report.runs, report.seconds,
               report.seconds > 0 ? report.runs / report.seconds : 0.0,
               report.failed ? (", " + std::to_string(report.failed) + " failed (their rows say why)").c_str() : "",
               plan.output.c_str());
}

// Under MPI: rank 0 runs the experiment with the other ranks as workers;
// they run, each in a process of its own, the runs it sends.
int run_under_mpi(const Plan& plan, ExperimentOptions options) {
  std::unique_ptr<MpiSession> mpi = open_mpi_session();
  if (mpi->rank() != 0) {
    if (!mpi->agree(true)) return 1;
    const std::vector<RunSpec> runs = plan_runs(plan);
    const SimulationOptions base = run_options(plan, options);
    mpi->serve([&](long number) {
      return encode_result(run_in_own_process(plan, runs.at(static_cast<std::size_t>(number)), base));
    });
    return 0;
  }
  PreparedExperiment prepared;
  try {
    prepared = prepare_experiment(plan, options);
  } catch (...) {
    mpi->agree(false);
    throw;
  }
  mpi->agree(true);
  std::unique_ptr<Workers> others = other_ranks(*mpi);
  options.remote = others.get();
  if (options.jobs == 0) options.jobs = 1;  // under MPI a rank is one worker unless told otherwise
  const ExperimentReport report = run_experiment(plan, prepared, options);
  others.reset();  // tells the other ranks to stop
  print_report(plan, report);
  return 0;
}

}  // namespace

CLI::App* add_experiment_command(CLI::App& app, ExperimentCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "experiment", "Run a plan of parameter sweeps and replicates, measured into one table (docs/experiments.md); "
                    "under mpirun or srun the runs go to every rank");
  command->add_option("plan", options.plan, "The experiment plan (TOML)")->required()->type_name("PLAN.toml");
  command->add_option("-j,--jobs", options.jobs,
                      "Runs at once on this machine (default: one per core; under MPI: one per rank)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("N");
  command->add_flag("--no-progress", options.no_progress, "No progress bar (there is none when standard error is not a terminal)");
  return command;
}

int run_experiment_command(const ExperimentCommandOptions& command, const build::BuildOptions& build) {
  const Plan plan = read_plan(command.plan);
  ExperimentOptions options;
  options.simulation.build = build;
  options.jobs = command.jobs;
  options.progress = !command.no_progress && ::isatty(STDERR_FILENO);
  if (launched_by_mpi()) return run_under_mpi(plan, options);
  const ExperimentReport report = run_experiment(plan, options);
  print_report(plan, report);
  return 0;
}

}  // namespace sylva::app
