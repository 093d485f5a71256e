// Point-subdivision L-systems on the GPU (gpu/, sylva run --gpu) against the
// engine: Chaikin's corner cutting (examples/chaikin/chaikin.l, a ring of 4
// points) derived from its axiom for <steps> steps, 4·2^steps points at the
// end: 18 steps ≈ 1.05·10^6, 21 ≈ 8.4·10^6, 25 ≈ 1.34·10^8.
//
//   GpuChaikin/<steps>     the GL stencil deriver (libsylva_gl.so): context,
//                          shader, upload, one render pass per step, read back.
//                          OpenGL as SYLVA_GL chooses (unset: EGL, a GPU where
//                          there is one), named in the label; on llvmpipe (EGL
//                          surfaceless or OSMesa) this runs on the CPU's cores.
//   GpuChaikinOsmesa/<steps>  the same through OSMesa (SYLVA_GL=osmesa).
//   CpuStencilChaikin/<steps>  the CPU stencil deriver (doubles, one thread).
//   EngineChaikin/<steps>  the engine: Simulation::run(steps) of the model.
// The probe (which finds the stencil through the engine) is done once, untimed.
// Counter Mpts/s: final points per second, in millions.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "api/simulation.h"
#include "gpu/lsystem_glsl.h"
#include "gpu/stencil_deriver.h"
#include "gpu/stencil_probe.h"
#include "io/string_reader.h"

namespace {

sylva::build::BuildOptions gpu_bench_options() {
  sylva::build::BuildOptions options;
  const char* dir = std::getenv("SYLVA_BENCH_CACHE_DIR");
  options.cache_dir = dir && *dir ? dir : SYLVA_BENCH_CACHE_DIR;
  return options;
}

const std::string& chaikin() {
  static const std::string path = std::string(SYLVA_EXAMPLES_DIR) + "/chaikin/chaikin.l";
  return path;
}

const sylva::gpu::ProbeResult& chaikin_probe() {
  static const sylva::gpu::ProbeResult probe = [] {
    sylva::Simulation simulation(chaikin(), gpu_bench_options());
    return sylva::gpu::probe_stencil(simulation);
  }();
  return probe;
}

void stencil_bench(benchmark::State& state, sylva::gpu::StencilDeriver& deriver) {
  const auto& probe = chaikin_probe();
  if (!probe.in_class) {
    state.SkipWithError(probe.reason.c_str());
    return;
  }
  const int steps = static_cast<int>(state.range(0));
  std::size_t points = 0;
  for (auto _ : state) {
    auto derived = deriver.derive(probe.axiom.points, probe.axiom.dim, probe.stencil, steps);
    points = derived.size() / probe.axiom.dim;
    benchmark::DoNotOptimize(derived.data());
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["Mpts/s"] =
      benchmark::Counter(static_cast<double>(points) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(deriver.name());  // the GL derivers: which OpenGL
}

void GpuChaikin(benchmark::State& state) { stencil_bench(state, sylva::gpu::gl_stencil_deriver()); }

void GpuChaikinOsmesa(benchmark::State& state) {
  const char* chosen = std::getenv("SYLVA_GL");
  const std::string before = chosen ? chosen : "";
  setenv("SYLVA_GL", "osmesa", 1);
  stencil_bench(state, sylva::gpu::gl_stencil_deriver());
  chosen ? setenv("SYLVA_GL", before.c_str(), 1) : unsetenv("SYLVA_GL");
}

void CpuStencilChaikin(benchmark::State& state) {
  sylva::gpu::CpuStencilDeriver cpu;
  stencil_bench(state, cpu);
}

void EngineChaikin(benchmark::State& state) {
  const int steps = static_cast<int>(state.range(0));
  sylva::Simulation simulation(chaikin(), gpu_bench_options());
  std::size_t points = 0;
  for (auto _ : state) {
    simulation.rewind();
    simulation.run(steps);
    points = simulation.string().count_modules(simulation.types()) - 1;  // less Control
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["Mpts/s"] =
      benchmark::Counter(static_cast<double>(points) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// SYLVA_GPU_BENCH_HUGE=1 adds 25 steps (1.34·10^8 points, several GB).
void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(18)->Arg(21);
  if (const char* huge = std::getenv("SYLVA_GPU_BENCH_HUGE"); huge && *huge == '1') b->Arg(25);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(GpuChaikin)->Apply(sizes);
BENCHMARK(GpuChaikinOsmesa)->Apply(sizes);
BENCHMARK(CpuStencilChaikin)->Apply(sizes);
BENCHMARK(EngineChaikin)->Apply(sizes);

// ---- algorithm 2 (gpu/lsystem_glsl.h): adaptive subdivision ----------------
// examples/adaptive-subdivision (L-system 5, T = 0.05): <curves> copies of the
// example's open curve (E, 8 points, E) side by side in one string, 5 steps;
// each curve ends with 220 modules: 455 curves ≈ 10^5 modules, 4545 ≈ 10^6,
// 45454 ≈ 10^7.
//
//   GpuAdaptive/<curves>        the GL L-system deriver: per step fragment
//                               program 1 (productions), the scan-add (2
//                               values per pass), the total read back,
//                               fragment program 3 (successors by binary
//                               search); the final string read back.
//   GpuAdaptiveRadix8/<curves>  the same, the scan summing 8 values a pass.
//   CpuInterpreterAdaptive/<curves>  the translated productions interpreted
//                               on the CPU (the check, not a fast path).
//   EngineAdaptive/<curves>     the engine (compiled productions, one thread).
// Translation and the model's compile are done once, untimed.

const std::string& adaptive() {
  static const std::string path = std::string(SYLVA_EXAMPLES_DIR) + "/adaptive-subdivision/adaptive-subdivision.l";
  return path;
}

const sylva::gpu::LsystemTranslation& adaptive_translation() {
  static const sylva::gpu::LsystemTranslation translation = [] {
    sylva::Simulation simulation(adaptive(), gpu_bench_options());
    return sylva::gpu::translate_lsystem(simulation, gpu_bench_options());
  }();
  return translation;
}

sylva::gpu::GpuString adaptive_curves(long curves) {
  const auto& one = adaptive_translation().axiom;
  sylva::gpu::GpuString many;
  for (long c = 0; c < curves; ++c) {
    many.types.insert(many.types.end(), one.types.begin(), one.types.end());
    many.params.insert(many.params.end(), one.params.begin(), one.params.end());
  }
  return many;
}

constexpr int kAdaptiveSteps = 5;

void adaptive_bench(benchmark::State& state, sylva::gpu::LsystemDeriver& deriver) {
  const auto& t = adaptive_translation();
  if (!t.in_class) {
    state.SkipWithError(t.reason.c_str());
    return;
  }
  const auto string = adaptive_curves(state.range(0));
  std::size_t modules = 0;
  for (auto _ : state) {
    auto derived = deriver.derive(t.program, string, kAdaptiveSteps);
    modules = derived.size();
    benchmark::DoNotOptimize(derived.types.data());
  }
  state.counters["modules"] = static_cast<double>(modules);
  state.counters["Mmod/s"] =
      benchmark::Counter(static_cast<double>(modules) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(deriver.name());
}

void GpuAdaptive(benchmark::State& state) {
  auto& gl = sylva::gpu::gl_lsystem_deriver();
  gl.set_layout(0, 2);
  adaptive_bench(state, gl);
}

void GpuAdaptiveRadix8(benchmark::State& state) {
  auto& gl = sylva::gpu::gl_lsystem_deriver();
  gl.set_layout(0, 8);
  adaptive_bench(state, gl);
  gl.set_layout(0, 2);
}

void CpuInterpreterAdaptive(benchmark::State& state) {
  sylva::gpu::CpuLsystemDeriver cpu;
  adaptive_bench(state, cpu);
}

void EngineAdaptive(benchmark::State& state) {
  const auto& t = adaptive_translation();
  sylva::Simulation simulation(adaptive(), gpu_bench_options());
  const std::string text = sylva::gpu::format_gpu_string(t.program, adaptive_curves(state.range(0)), false);
  const sylva::ModuleString start = sylva::io::parse_string(text, simulation.types(), "<curves>");
  std::size_t modules = 0;
  for (auto _ : state) {
    state.PauseTiming();
    simulation.rewind();
    simulation.start_from(start);
    state.ResumeTiming();
    simulation.run(kAdaptiveSteps);
    modules = simulation.string().count_modules(simulation.types());
  }
  state.counters["modules"] = static_cast<double>(modules);
  state.counters["Mmod/s"] =
      benchmark::Counter(static_cast<double>(modules) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

void curve_counts(benchmark::internal::Benchmark* b) {
  b->Arg(455)->Arg(4545)->Arg(45454)->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(GpuAdaptive)->Apply(curve_counts);
BENCHMARK(GpuAdaptiveRadix8)->Apply(curve_counts);
BENCHMARK(CpuInterpreterAdaptive)->Apply(curve_counts);
BENCHMARK(EngineAdaptive)->Apply(curve_counts);

}  // namespace
