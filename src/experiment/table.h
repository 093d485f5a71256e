// The experiment's table: one row per run and measurement step (or time),
// columns run, point, replicate, seed, the parameters, step (or time), the
// measures, status and error. CSV as pandas and R read it: numbers in the
// shortest form that reads back exactly, NA where there is no value.
#pragma once

#include <string>
#include <vector>

#include "experiment/plan.h"
#include "experiment/run_one.h"
#include "experiment/runs.h"

namespace sylva::experiment {

std::string table_text(const Plan& plan, const std::vector<RunSpec>& runs, const std::vector<RunResult>& results);

// A number as the table writes it.
std::string number_cell(double value);

}  // namespace sylva::experiment
