// Provenance at the command line (api/provenance.h, docs/provenance.md): the
// record `sylva run` puts in its outputs, and `sylva run --reproduce FILE`,
// which runs the recorded run again and checks its string.
#pragma once

#include <string>

#include "api/provenance.h"
#include "api/simulation.h"
#include "build/model_builder.h"

namespace sylva::app {

// What every output of a `sylva run` records: `options` as the Simulation
// was made with, the saved string it started from (--axiom-from, "" for
// none) and, for a run in continuous time, its settings.
RunRecord run_record(const Simulation& simulation, const SimulationOptions& options, const std::string& axiom_from,
                     const continuous::ContinuousSettings* in_time);

// Exit statuses of --reproduce.
inline constexpr int kReproduced = 0;
inline constexpr int kNotReproduced = 1;  // a file changed, or the string differs
inline constexpr int kNoRecord = 2;       // FILE carries no record

// Reads the record in `file`, checks that the model, the input files and a
// saved axiom still hash as recorded, runs the model again with the recorded
// definitions, seed and steps (or time), and compares the string's SHA-256
// with the recorded one. `build` gives the cache, verbosity and compile time
// limit; its compiler, when set, replaces the recorded one. Prints
// "reproduced: FILE (string sha256 ...)" on standard output, or what
// differs on standard error.
int run_reproduce(const std::string& file, const build::BuildOptions& build);

}  // namespace sylva::app
