// Point-subdivision L-systems on the GPU (gpu/, sylva run --gpu) against the
// engine: Chaikin's corner cutting (examples/chaikin/chaikin.l, a ring of 4
// points) derived from its axiom for <steps> steps, 4·2^steps points at the
// end: 18 steps ≈ 1.05·10^6, 21 ≈ 8.4·10^6, 25 ≈ 1.34·10^8.
//
//   GpuChaikin/<steps>     the GL stencil deriver (libsylva_gl.so): context,
//                          shader, upload, one render pass per step, read back.
//                          With OSMesa (Mesa's software rasteriser, llvmpipe)
//                          this runs on the CPU's cores; a real GPU differs.
//   CpuStencilChaikin/<steps>  the CPU stencil deriver (doubles, one thread).
//   EngineChaikin/<steps>  the engine: Simulation::run(steps) of the model.
// The probe (which finds the stencil through the engine) is done once, untimed.
// Counter Mpts/s: final points per second, in millions.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "api/simulation.h"
#include "gpu/stencil_deriver.h"
#include "gpu/stencil_probe.h"

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
}

void GpuChaikin(benchmark::State& state) { stencil_bench(state, sylva::gpu::gl_stencil_deriver()); }

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
BENCHMARK(CpuStencilChaikin)->Apply(sizes);
BENCHMARK(EngineChaikin)->Apply(sizes);

}  // namespace
