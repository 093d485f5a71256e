#include "experiment/run_one.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "api/outputs.h"
#include "api/provenance.h"
#include "experiment/measures.h"

namespace sylva::experiment {
namespace {

bool saved(const Plan& plan, const RunSpec& run) {
  if (!plan.save) return false;
  return plan.save->all_runs ||
         std::find(plan.save->runs.begin(), plan.save->runs.end(), run.number) != plan.save->runs.end();
}

// runs/run-0003/step-0006.png
void save_outputs(const Plan& plan, const RunSpec& run, Simulation& simulation, int step) {
  char name[64];
  std::snprintf(name, sizeof name, "run-%04ld", run.number);
  const std::filesystem::path dir = std::filesystem::path(plan.save->directory) / name;
  std::filesystem::create_directories(dir);
  std::snprintf(name, sizeof name, "step-%04d.", step);
  const std::string stem = (dir / name).string();
  std::optional<geometry::Scene> scene;
  for (const std::string& format : plan.save->formats) {
    if (format == kStringFrame) {
      write_recorded_string(stem + format, simulation);  // and its record (api/provenance.h)
      continue;
    }
    if (!scene) scene = simulation.scene();
    write_output(stem + format, *scene, simulation, OutputOptions{});
  }
}

RunRow measure(const Measures& measures, Simulation& simulation) {
  RunRow row;
  row.step = simulation.step_number();
  row.time = simulation.continuous() ? simulation.time() : 0;
  if (measures.needs_scene()) {
    const geometry::Scene scene = simulation.scene();
    row.values = measures.evaluate(simulation.string(), simulation.types(), &scene);
  } else {
    row.values = measures.evaluate(simulation.string(), simulation.types(), nullptr);
  }
  return row;
}

}  // namespace

SimulationOptions with_defines(SimulationOptions options, const RunSpec& run) {
  for (const std::string& define : run.defines()) options.build.defines.push_back(define);
  return options;
}

RunResult execute_run(const Plan& plan, const RunSpec& run, const SimulationOptions& base) {
  RunResult result;
  result.number = run.number;
  try {
    SimulationOptions options = with_defines(base, run);
    options.seed = run.seed;
    Simulation simulation(plan.model, options, [](const std::string&) {});
    // Saved outputs record the run (api/provenance.h): `sylva run --reproduce` re-runs one alone.
    const bool keep = saved(plan, run);
    std::optional<ProvenanceScope> provenance;
    if (keep) provenance.emplace(simulation, make_run_record(simulation, options));
    const Measures measures(plan.measures, simulation.types());
    simulation.begin();
    if (!plan.times.empty()) {
      for (double t : plan.times) {
        simulation.advance_to(t);
        result.rows.push_back(measure(measures, simulation));
        result.rows.back().time = t;
        if (keep) save_outputs(plan, run, simulation, simulation.step_number());
      }
    } else {
      std::vector<int> steps = plan.steps;
      if (steps.empty()) steps.push_back(simulation.derivation_length());
      for (int target : steps) {
        while (simulation.step_number() < target && simulation.step()) {
        }
        if (simulation.step_number() < target) {
          RunRow row;
          row.step = target;
          row.values.assign(plan.measures.size(), std::nan(""));
          row.note = "the run ended at step " + std::to_string(simulation.step_number());
          result.rows.push_back(std::move(row));
          continue;
        }
        result.rows.push_back(measure(measures, simulation));
        if (keep) save_outputs(plan, run, simulation, target);
      }
    }
    simulation.finish();
    result.ok = true;
  } catch (const std::exception& error) {
    result.error = error.what();
  }
  return result;
}

std::string encode_result(const RunResult& result) {
  nlohmann::json rows = nlohmann::json::array();
  for (const RunRow& row : result.rows) {
    nlohmann::json values = nlohmann::json::array();
    // JSON has no NaN or infinities: they travel as null, "inf" and "-inf".
    for (double v : row.values) {
      if (std::isnan(v)) values.push_back(nullptr);
      else if (std::isinf(v)) values.push_back(v > 0 ? "inf" : "-inf");
      else values.push_back(v);
    }
    rows.push_back({{"step", row.step}, {"time", row.time}, {"values", values}, {"note", row.note}});
  }
  return nlohmann::json{{"number", result.number}, {"ok", result.ok}, {"error", result.error}, {"rows", rows}}.dump();
}

RunResult decode_result(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  RunResult result;
  result.number = j.at("number").get<long>();
  result.ok = j.at("ok").get<bool>();
  result.error = j.at("error").get<std::string>();
  for (const nlohmann::json& r : j.at("rows")) {
    RunRow row;
    row.step = r.at("step").get<int>();
    row.time = r.at("time").get<double>();
    row.note = r.at("note").get<std::string>();
    for (const nlohmann::json& v : r.at("values")) {
      if (v.is_null()) row.values.push_back(std::nan(""));
      else if (v.is_string()) row.values.push_back(v.get<std::string>() == "inf" ? HUGE_VAL : -HUGE_VAL);
      else row.values.push_back(v.get<double>());
    }
    result.rows.push_back(std::move(row));
  }
  return result;
}

}  // namespace sylva::experiment
