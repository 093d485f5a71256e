// Turtle interpretation and the whole picture of a large plant.
//
//   Interpret/plant_1m/<scene|query>
//       bench/models/plant_1m.l derived (untimed) to 1,310,717 modules, then
//       interpreted into a Scene (scene) or only for the turtle's state, as
//       the query-module pass does (query). Counter Mmod/s: modules per second.
//   Picture/plant_1m/1920x1080
//       Scene + render + PNG of the same plant with plant_1m.v (perspective,
//       shaded cylinders, z buffer), timed together: what `sylva run
//       plant_1m.l plant_1m.v -o plant.png --width 1920 --height 1080` spends
//       after deriving.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <memory>
#include <string>

#include "api/outputs.h"
#include "api/simulation.h"
#include "turtle/interpreter.h"

namespace {

std::unique_ptr<sylva::Simulation> derived_plant() {
  sylva::SimulationOptions options;
  options.build.cache_dir = SYLVA_BENCH_CACHE_DIR;
  options.input_files = {std::string(SYLVA_BENCH_MODELS_DIR) + "/plant_1m.v"};
  auto simulation =
      std::make_unique<sylva::Simulation>(std::string(SYLVA_BENCH_MODELS_DIR) + "/plant_1m.l", options);
  simulation->run();
  return simulation;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void interpret(benchmark::State& state, bool scene) {
  auto simulation = derived_plant();
  const double modules = static_cast<double>(simulation->string().count_modules(simulation->types()));
  // The query pass's walk: the string as it stands, no scene kept.
  const sylva::ModuleString interpreted = simulation->interpreted(0);
  for (auto _ : state) {
    if (scene) {
      benchmark::DoNotOptimize(simulation->scene());
    } else {
      sylva::derive::ParameterWrites answers;
      sylva::turtle::walk_string(interpreted, simulation->types(), simulation->turtle_settings(), nullptr, nullptr,
                                 &answers);
      benchmark::DoNotOptimize(answers);
    }
  }
  state.counters["Mmod/s"] = benchmark::Counter(modules / 1e6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["modules"] = modules;
  state.counters["peak_RSS_MB"] = peak_rss_mb();
}

void picture(benchmark::State& state) {
  auto simulation = derived_plant();
  sylva::OutputOptions output;
  output.width = 1920;
  output.height = 1080;
  const std::string path = std::string(SYLVA_BENCH_CACHE_DIR) + "/plant_1m.png";
  for (auto _ : state) sylva::write_output(path, simulation->scene(), *simulation, output);
  state.counters["peak_RSS_MB"] = peak_rss_mb();
}

BENCHMARK_CAPTURE(interpret, plant_1m_scene, true)->Name("Interpret/plant_1m/scene")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(interpret, plant_1m_query, false)->Name("Interpret/plant_1m/query")->Unit(benchmark::kMillisecond);
BENCHMARK(picture)->Name("Picture/plant_1m/1920x1080")->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
