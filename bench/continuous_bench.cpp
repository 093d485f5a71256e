// Differential L-systems (docs/continuous-time.md), run by hand:
//
//   Continuous/anabaena/<T>/<event tolerance exponent>
//       examples/anabaena-continuous run from t = 0 to T with Dormand-Prince
//       (tolerance 1e-6) and events located to 10^-<exponent>.
//   FixedDt/anabaena/<T>
//       The same model written with a fixed dt = 0.1 inside its productions,
//       as lpfg users do (bench/models/anabaena_fixed_dt.l): T / dt steps.
//
// Counters: cells (modules at T), events, events/s, steps (integrator
// steps), evals (right-hand-side evaluations: passes of the derivative rules
// over the string), probes (passes of the event conditions while locating
// events) and probes/event.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>

#include "api/simulation.h"

namespace {

using Clock = std::chrono::steady_clock;

sylva::build::BuildOptions options() {
  sylva::build::BuildOptions o;
  const char* dir = std::getenv("SYLVA_BENCH_CACHE_DIR");
  o.cache_dir = dir && *dir ? dir : SYLVA_BENCH_CACHE_DIR;
  return o;
}

void continuous_anabaena(benchmark::State& state) {
  const double end = static_cast<double>(state.range(0));
  sylva::Simulation simulation(std::string(SYLVA_EXAMPLES_DIR) + "/anabaena-continuous/anabaena-continuous.l",
                               options());
  sylva::continuous::ContinuousSettings settings;
  settings.event_tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  settings.end_time = end;
  simulation.set_continuous_settings(settings);
  double seconds = 0;
  for (auto _ : state) {
    simulation.rewind();
    const auto start = Clock::now();
    simulation.advance_to(end);
    const double s = std::chrono::duration<double>(Clock::now() - start).count();
    seconds += s;
    state.SetIterationTime(s);
  }
  const auto counts = simulation.continuous_counts();
  state.counters["cells"] = static_cast<double>(simulation.string().count_modules(simulation.types()) - 1);
  state.counters["events"] = static_cast<double>(counts.events);
  state.counters["events/s"] = static_cast<double>(counts.events) * static_cast<double>(state.iterations()) / seconds;
  state.counters["steps"] = static_cast<double>(counts.steps);
  state.counters["evals"] = static_cast<double>(counts.evaluations);
  state.counters["probes"] = static_cast<double>(counts.location_probes);
  state.counters["probes/event"] =
      static_cast<double>(counts.location_probes) / std::max<double>(1, static_cast<double>(counts.events));
}

void fixed_dt_anabaena(benchmark::State& state) {
  const int steps = static_cast<int>(state.range(0) * 10);  // dt = 0.1
  sylva::Simulation simulation(std::string(SYLVA_BENCH_MODELS_DIR) + "/anabaena_fixed_dt.l", options());
  for (auto _ : state) {
    simulation.rewind();
    const auto start = Clock::now();
    simulation.begin();
    for (int k = 0; k < steps; ++k) simulation.step();
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - start).count());
  }
  state.counters["cells"] = static_cast<double>(simulation.string().count_modules(simulation.types()));
}

}  // namespace

BENCHMARK(continuous_anabaena)
    ->Name("Continuous/anabaena")
    ->ArgsProduct({{575, 800, 1000}, {9, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(fixed_dt_anabaena)
    ->Name("FixedDt/anabaena")
    ->Args({575})
    ->Args({800})
    ->Args({1000})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
