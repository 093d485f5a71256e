// One run of an experiment, from its RunSpec to its table rows: the model
// opened with the run's -D values and seed, derived (or integrated) to each
// measurement step (or time), measured there, and the chosen runs' strings,
// meshes and images saved. What a worker does, wherever it runs.
#pragma once

#include <string>
#include <vector>

#include "api/simulation.h"
#include "experiment/plan.h"
#include "experiment/runs.h"

namespace sylva::experiment {

// The measures at one step or time.
struct RunRow {
  int step = 0;
  double time = 0;
  std::vector<double> values;
  std::string note;  // empty: measured; else why not (the run ended earlier)
};

struct RunResult {
  long number = 0;
  bool ok = false;
  std::string error;  // when !ok: what stopped the run (a model error, a crash, a timeout)
  std::vector<RunRow> rows;
};

// Runs `run` of `plan` in this process, from `base` (run_options() of the
// plan, experiment/experiment.h) with the run's -D values and seed. Errors of
// the model become the result's error; the rows measured before them are kept.
RunResult execute_run(const Plan& plan, const RunSpec& run, const SimulationOptions& base);

// `options` with the run's -D values added.
SimulationOptions with_defines(SimulationOptions options, const RunSpec& run);

// The text that carries a result between processes (one line of JSON), and back.
std::string encode_result(const RunResult& result);
RunResult decode_result(const std::string& text);

}  // namespace sylva::experiment
