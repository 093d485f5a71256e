#include "experiment/experiment.h"

#include <unistd.h>

#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "api/provenance.h"
#include "api/series_plot.h"
#include "experiment/local_processes.h"
#include "experiment/measures.h"
#include "experiment/progress.h"
#include "experiment/run_one.h"
#include "experiment/table.h"
#include "io/output_file.h"

namespace sylva::experiment {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every identifier in the model and in the files it includes with quotes:
// a -D name the plan varies must be one of them.
void collect_identifiers(const fs::path& file, std::set<std::string>& names, std::set<fs::path>& seen) {
  if (!seen.insert(fs::weakly_canonical(file)).second) return;
  const std::string text = read_text(file);
  for (std::size_t i = 0; i < text.size();) {
    if (std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_') {
      const std::size_t start = i;
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
      names.insert(text.substr(start, i - start));
    } else if (std::isdigit(static_cast<unsigned char>(text[i]))) {
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_' || text[i] == '.')) ++i;
    } else {
      ++i;
    }
  }
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string::npos || line[hash] != '#' || line.find("include", hash) == std::string::npos) continue;
    const std::size_t open = line.find('"'), close = line.rfind('"');
    if (open == std::string::npos || close <= open) continue;
    const fs::path included = file.parent_path() / line.substr(open + 1, close - open - 1);
    if (fs::exists(included)) collect_identifiers(included, names, seen);
  }
}

void check_parameters(const Plan& plan) {
  std::set<std::string> names;
  std::set<fs::path> seen;
  collect_identifiers(plan.model, names, seen);
  for (const Parameter& p : plan.parameters)
    if (!names.count(p.name))
      throw ModelError(p.at, "the model " + fs::path(plan.model).filename().string() + " never uses '" + p.name +
                                 "': -D " + p.name + " would change nothing");
}

int local_jobs(const ExperimentOptions& options) {
  return options.jobs > 0 ? options.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

std::string defines_text(const std::vector<std::string>& defines) {
  std::string out;
  for (const std::string& d : defines) out += " -D " + d;
  return out.empty() ? " (no -D)" : out;
}

void write_plot(const Plan& plan, const std::vector<RunSpec>& runs, const std::vector<RunResult>& results) {
  const PlotPlan& plot = *plan.plot;
  std::size_t x_index = 0, y_index = 0;
  while (plan.parameters[x_index].name != plot.x) ++x_index;
  while (plan.measures[y_index].name != plot.y) ++y_index;
  // At the last measurement: one dot per run.
  PlotSeries series{plot.y, {}, {}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::size_t last = plan.times.empty() ? std::max<std::size_t>(plan.steps.size(), 1) - 1 : plan.times.size() - 1;
    if (results[i].rows.size() <= last || !results[i].rows[last].note.empty()) continue;
    series.t.push_back(std::strtod(runs[i].values[x_index].second.c_str(), nullptr));
    series.value.push_back(results[i].rows[last].values[y_index]);
  }
  const std::string when = plan.times.empty() ? (plan.steps.empty() ? std::string("the last step")
                                                                    : "step " + std::to_string(plan.steps.back()))
                                              : "time " + std::to_string(plan.times.back());
  write_series_plot(plot.file, {series},
                    plot.y + " against " + plot.x + " at " + when + " (" + fs::path(plan.path).filename().string() + ")",
                    900, 600, plot.x);
}

// TABLE.provenance.json: what made the table. The rows carry each run's
// -D values, seed and step; this says the rest (api/provenance.h).
std::string table_record(const Plan& plan, const RunRecord& model) {
  nlohmann::json record = model;
  for (const char* per_run : {"defines", "seed", "step", "time", "finished", "string_sha256", "axiom_from"})
    record.erase(per_run);
  record["plan"] = {{"path", fs::absolute(plan.path).string()}, {"sha256", file_sha256(plan.path).value_or("")}};
  record["table"] = fs::path(plan.output).filename().string();
  return record.dump(2) + "\n";
}

}  // namespace

SimulationOptions run_options(const Plan& plan, const ExperimentOptions& options) {
  SimulationOptions base = options.simulation;
  for (const std::string& input : plan.inputs) base.input_files.emplace_back(input);
  base.threads = 1;  // runs go side by side; each keeps to one core
  return base;
}

PreparedExperiment prepare_experiment(const Plan& plan, const ExperimentOptions& options) {
  check_parameters(plan);
  PreparedExperiment prepared{plan_runs(plan), run_options(plan, options), {}};
  // Each -D set compiled once, side by side, before any run: a model that
  // does not compile stops the experiment here with the compiler's message.
  std::vector<RunSpec> builds = one_run_per_define_set(prepared.runs);
  for (std::size_t k = 0; k < builds.size(); ++k) builds[k].number = static_cast<long>(k);
  LocalProcesses compilers(local_jobs(options), [&](const RunSpec& spec) {
    RunResult result;
    result.number = spec.number;
    try {
      Simulation simulation(plan.model, with_defines(prepared.base, spec), [](const std::string&) {});
      result.ok = true;
    } catch (const std::exception& error) {
      result.error = error.what();
    }
    return encode_result(result);
  });
  for (const RunResult& built : schedule(builds, {&compilers}))
    if (!built.ok)
      throw ModelError(plan.model_at, "the model does not build with" + defines_text(builds[built.number].defines()) +
                                          ":\n" + built.error);
  // The measures against the model's modules (the same in every -D set).
  const SimulationOptions first = with_defines(prepared.base, prepared.runs.front());
  Simulation simulation(plan.model, first, [](const std::string&) {});
  const Measures measures(plan.measures, simulation.types());
  prepared.model = make_run_record(simulation, first);
  return prepared;
}

RunResult run_in_own_process(const Plan& plan, const RunSpec& run, const SimulationOptions& base) {
  LocalProcesses process(1, [&](const RunSpec& r) { return encode_result(execute_run(plan, r, base)); },
                         plan.timeout_seconds);
  process.start(run);
  for (;;) {
    std::vector<RunResult> done = process.collect(1000);
    if (!done.empty()) return std::move(done.front());
  }
}

ExperimentReport run_experiment(const Plan& plan, const ExperimentOptions& options) {
  return run_experiment(plan, prepare_experiment(plan, options), options);
}

ExperimentReport run_experiment(const Plan& plan, const PreparedExperiment& prepared, const ExperimentOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const std::vector<RunSpec>& runs = prepared.runs;
  if (plan.save) fs::create_directories(plan.save->directory);

  LocalProcesses local(local_jobs(options),
                       [&](const RunSpec& run) { return encode_result(execute_run(plan, run, prepared.base)); },
                       plan.timeout_seconds);
  std::vector<Workers*> workers = {&local};
  if (options.remote) workers.push_back(options.remote);

  ExperimentReport report;
  report.runs = runs.size();
  Progress progress(runs.size(), options.progress);
  std::size_t done = 0;
  const std::vector<RunResult> results = schedule(runs, workers, [&](const RunResult& result) {
    ++done;
    if (!result.ok) ++report.failed;
    progress.update(done, report.failed);
  });
  progress.finish();

  io::write_output_file(plan.output, table_text(plan, runs, results));
  io::write_output_file(plan.output + kProvenanceSidecarSuffix, table_record(plan, prepared.model));
  if (plan.plot) write_plot(plan, runs, results);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return report;
}

}  // namespace sylva::experiment
