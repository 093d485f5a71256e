// An experiment plan (docs/experiments.md): a model, the -D values to vary,
// the replicates, when and what to measure. Read from TOML by read_plan();
// every part keeps where it was written so that errors found later (a
// module the model lacks, a parameter it never uses) point into the plan.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "support/diagnostic.h"

namespace sylva::experiment {

// One -D name and the values it takes, as text (so `-D NAME=VALUE` gets what
// the plan wrote: 30 stays 30, not 30.000000).
struct Parameter {
  std::string name;
  std::vector<std::string> values;
  SourceLocation at;
};

// What is measured: a name (the table's column) and an expression over the
// string and its drawing (experiment/measure_expression.h).
struct MeasureSpec {
  std::string name;
  std::string expression;
  SourceLocation at;  // the expression's first character
};

// Which runs write their strings, meshes or images, and as what.
struct SavePlan {
  bool all_runs = false;
  std::vector<long> runs;             // run numbers, when not all
  std::vector<std::string> formats;   // extensions: str, png, obj, ply, glb, svg, pdf, ps, eps
  std::string directory;              // absolute
};

// A measure drawn against a parameter, one dot per run and time.
struct PlotPlan {
  std::string x, y;   // a parameter's name; a measure's name
  std::string file;   // absolute
};

struct Plan {
  std::string path;             // the plan file
  std::string model;            // absolute
  SourceLocation model_at;
  std::vector<std::string> inputs;  // absolute: view, animation, function ... files
  // The parameters, varied over their grid (every combination, the first
  // varying slowest) or zipped (the i-th value of each).
  std::vector<Parameter> parameters;
  bool zip = false;
  // Replicates: each with a seed made from `seed` and its number
  // (replicate_seed); none: one run per point, the model seeding itself.
  int replicates = 0;
  long seed = 1;
  // When to measure: derivation steps (0: the axiom; none given: the model's
  // derivation length), or times of a continuous model.
  std::vector<int> steps;
  std::vector<double> times;
  std::vector<MeasureSpec> measures;
  std::string output;            // the table, absolute
  double timeout_seconds = 0;    // per run; 0: none
  std::optional<SavePlan> save;
  std::optional<PlotPlan> plot;
};

// Reads and checks a plan: TOML syntax, known keys, types, non-empty value
// sets. Throws ModelError at the plan's line and column. Paths in the plan
// are relative to its directory.
Plan read_plan(const std::string& path);
Plan parse_plan(const std::string& text, const std::string& path);

}  // namespace sylva::experiment
