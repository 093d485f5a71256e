// Sylva benchmarks (Google Benchmark). Run by hand; see bench/README.md.
//
//   Derive/<model>/<steps>/<fresh|reused>
//       Derives <model> from its axiom for <steps> steps and times the steps
//       only (StartEach, the productions, decomposition, EndEach). `fresh`
//       builds a new Simulation for every iteration, as a user's run does, so
//       the strings' memory is allocated and faulted in while deriving;
//       `reused` derives again in the same Simulation, whose string buffers
//       are already large enough.
//   Threads/<model>/<steps>/<threads>
//       As Derive/.../fresh, on that many threads (1, 2, 4 ... up to the
//       machine's cores): the derivation's own speed-up, without the start
//       and end of a process.
//   Threads/<model>/<steps>/<threads>/reused
//       As Derive/.../reused, on that many threads: the speed-up once the
//       pages are faulted in.
//   SimulationsAtOnce/koch/<n>
//       n Simulations deriving koch at once, each on a thread of its own (and
//       one thread each), in one process; the slowest one's steps are timed.
//       Against n = 1: what sharing a process costs them (its memory map).
//   Pass/<threads>
//       The cost of a parallel pass itself: four empty tasks per thread
//       handed to that many threads (1, 2, 4 ... up to 16), and their end
//       awaited.
//   DiffusionStep
//       diffusion.l grown to 2^21 cells (untimed), then one timed diffusion
//       step per iteration.
//   BytesPerModule/<one_float|no_params>
//       ModuleString::size_bytes() / count_modules() for a string whose
//       modules all carry one float (koch.l) or none (koch_noparam.l).
//   FirstRun/<model>/<steps>
//       Translate + compile + load + derive with an empty cache directory.
//       Counters: build_ms (Simulation constructed: translate, compile,
//       load), derive_ms, cpu_ms (CPU time of this thread and of the
//       preprocessor and compiler processes: the figure to trust on a loaded
//       machine, where the wall clock counts waiting for a core).
//   CachedStart/<model>
//       Constructing a Simulation for a model already in the cache (hash the
//       model, check the manifest, dlopen, build the engine's tables).
//
// Counters:
//   Mmod/s       output modules per second of derivation-step time, in
//                millions: the modules of the string after each timed step,
//                summed, over the summed step time.
//   Mmod/s_last  the same for the last step alone.
//   Mmod/s_cpu   as Mmod/s, over the thread's CPU time (user + system) instead
//                of the wall clock: the figure to trust on a loaded machine.
//   modules      modules in the final string.
//   B/module     bytes per module of the final string (size, not capacity).
//   peak_RSS_MB  getrusage's ru_maxrss so far, for the whole process: run one
//                benchmark per process (bench/run.sh does) to read it per model.
//
// SYLVA_BENCH_STEPS=1 in the environment prints every timed step of Derive/*
// (modules, time, rate) on stderr.
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>
#include <unistd.h>

#include "api/simulation.h"
#include "derive/worker_threads.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string model_path(const std::string& name) { return std::string(SYLVA_BENCH_MODELS_DIR) + "/" + name + ".l"; }

// The benchmarks' own cache, shared between runs (compiled once).
sylva::build::BuildOptions warm_options() {
  sylva::build::BuildOptions options;
  const char* dir = std::getenv("SYLVA_BENCH_CACHE_DIR");
  options.cache_dir = dir && *dir ? dir : SYLVA_BENCH_CACHE_DIR;
  return options;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of this thread (user and system, so page faults count): unlike the
// wall clock, not inflated when other processes share the cores.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// CPU time (user + system) of this process's waited-for children: the
// preprocessor and compiler runs of a build.
double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

std::size_t count_modules(const sylva::Simulation& d) { return d.string().count_modules(d.types()); }

void set_string_counters(benchmark::State& state, const sylva::Simulation& d) {
  const std::size_t modules = count_modules(d);
  state.counters["modules"] = static_cast<double>(modules);
  state.counters["B/module"] = static_cast<double>(d.string().size_bytes()) / static_cast<double>(modules);
  state.counters["peak_RSS_MB"] = peak_rss_mb();
}

// ---- derivation throughput ---------------------------------------------------

// threads: 0 for one per core, as a run's default.
std::unique_ptr<sylva::Simulation> new_simulation(const std::string& model, int threads) {
  sylva::SimulationOptions options;
  options.build = warm_options();
  options.threads = threads;
  return std::make_unique<sylva::Simulation>(model_path(model), options);
}

void derive(benchmark::State& state, const std::string& model, int steps, bool fresh, int threads) {
  std::unique_ptr<sylva::Simulation> simulation = new_simulation(model, threads);
  double total_seconds = 0, last_seconds = 0, total_cpu = 0, last_cpu = 0;
  double total_modules = 0, last_modules = 0;
  const bool print_steps = std::getenv("SYLVA_BENCH_STEPS") != nullptr;
  for (auto _ : state) {
    if (fresh) {
      simulation.reset();
      simulation = new_simulation(model, threads);
    }
    sylva::Simulation& d = *simulation;
    d.rewind();
    d.begin();
    double iteration_seconds = 0;
    for (int k = 0; k < steps; ++k) {
      const double cpu_start = thread_cpu_seconds();
      const Clock::time_point start = Clock::now();
      d.step();
      last_seconds = seconds_since(start);
      last_cpu = thread_cpu_seconds() - cpu_start;
      total_cpu += last_cpu;
      iteration_seconds += last_seconds;
      last_modules = static_cast<double>(count_modules(d));  // untimed
      total_modules += last_modules;
      if (print_steps)
        std::fprintf(stderr, "%s step %d: %.0f modules, %.3f ms (%.3f ms CPU), %.1f Mmod/s (%.1f per CPU second)\n",
                     model.c_str(), k + 1, last_modules, last_seconds * 1e3, last_cpu * 1e3,
                     last_modules / last_seconds / 1e6, last_modules / last_cpu / 1e6);
    }
    total_seconds += iteration_seconds;
    state.SetIterationTime(iteration_seconds);
  }
  const sylva::Simulation& d = *simulation;
  state.counters["Mmod/s"] = total_modules / total_seconds / 1e6;
  state.counters["Mmod/s_last"] = last_modules / last_seconds / 1e6;
  state.counters["Mmod/s_cpu"] = total_modules / total_cpu / 1e6;
  set_string_counters(state, d);
}

// `simulations` derivations of koch at once, each on a thread of its own and
// on one thread, in one process; the time of the slowest.
void simulations_at_once(benchmark::State& state, int simulations) {
  for (auto _ : state) {
    std::vector<double> seconds(static_cast<std::size_t>(simulations));
    std::vector<std::thread> running;
    for (int k = 0; k < simulations; ++k)
      running.emplace_back([&, k] {
        std::unique_ptr<sylva::Simulation> simulation = new_simulation("koch", 1);
        simulation->begin();
        const Clock::time_point start = Clock::now();
        for (int step = 0; step < 12; ++step) simulation->step();
        seconds[static_cast<std::size_t>(k)] = seconds_since(start);
      });
    for (std::thread& thread : running) thread.join();
    state.SetIterationTime(*std::max_element(seconds.begin(), seconds.end()));
  }
}

void pass_overhead(benchmark::State& state, int threads) {
  const std::size_t tasks = static_cast<std::size_t>(threads) * 4;
  for (auto _ : state) sylva::derive::run_tasks(threads, tasks, [](std::size_t k) { benchmark::DoNotOptimize(k); });
}

void busy_for(std::chrono::microseconds time) {
  const Clock::time_point end = Clock::now() + time;
  while (Clock::now() < end) {
  }
}

// A pass of four 20 us tasks per thread after 100 us of serial work, as the
// passes of a step follow each other: on `threads` threads it takes 80 us
// once every thread has woken.
void pass_after_serial_work(benchmark::State& state, int threads) {
  const std::size_t tasks = static_cast<std::size_t>(threads) * 4;
  for (auto _ : state) {
    busy_for(std::chrono::microseconds(100));
    const Clock::time_point start = Clock::now();
    sylva::derive::run_tasks(threads, tasks, [](std::size_t) { busy_for(std::chrono::microseconds(20)); });
    state.SetIterationTime(seconds_since(start));
  }
}

// ---- diffusion ---------------------------------------------------------------

constexpr int kDiffusionGrowthSteps = 21;  // GROWTH_STEPS in diffusion.l

void diffusion_step(benchmark::State& state) {
  sylva::Simulation d(model_path("diffusion"), warm_options());
  d.begin();
  for (int k = 0; k < kDiffusionGrowthSteps; ++k) d.step();
  const double modules = static_cast<double>(count_modules(d));
  double total_seconds = 0, total_cpu = 0, total_modules = 0;
  for (auto _ : state) {
    const double cpu_start = thread_cpu_seconds();
    const Clock::time_point start = Clock::now();
    d.step();
    const double seconds = seconds_since(start);
    total_cpu += thread_cpu_seconds() - cpu_start;
    state.SetIterationTime(seconds);
    total_seconds += seconds;
    total_modules += modules;
  }
  if (static_cast<double>(count_modules(d)) != modules) state.SkipWithError("the diffusion step changed the size");
  state.counters["Mmod/s"] = total_modules / total_seconds / 1e6;
  state.counters["Mmod/s_cpu"] = total_modules / total_cpu / 1e6;
  set_string_counters(state, d);
}

// ---- string size ---------------------------------------------------------------

void bytes_per_module(benchmark::State& state, const std::string& model) {
  sylva::Simulation d(model_path(model), warm_options());
  for (auto _ : state) {
    d.rewind();
    d.run(8);
    benchmark::DoNotOptimize(d.string().data());
  }
  set_string_counters(state, d);
}

// ---- start-up ----------------------------------------------------------------

void first_run(benchmark::State& state, const std::string& model, int steps) {
  double build_seconds = 0, derive_seconds = 0, cpu_seconds = 0;
  for (auto _ : state) {
    char pattern[] = "/tmp/sylva-bench-cache-XXXXXX";
    if (!mkdtemp(pattern)) {
      state.SkipWithError("mkdtemp failed");
      return;
    }
    sylva::build::BuildOptions options;
    options.cache_dir = pattern;
    const double cpu_start = thread_cpu_seconds() + children_cpu_seconds();
    const Clock::time_point start = Clock::now();
    sylva::Simulation simulation(model_path(model), options);
    const double built = seconds_since(start);
    simulation.run(steps);
    const double total = seconds_since(start);
    cpu_seconds += thread_cpu_seconds() + children_cpu_seconds() - cpu_start;
    state.SetIterationTime(total);
    build_seconds += built;
    derive_seconds += total - built;
    if (!simulation.compiled_now()) state.SkipWithError("the model was not compiled");
    std::error_code ec;
    fs::remove_all(pattern, ec);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["build_ms"] = build_seconds / n * 1e3;
  state.counters["derive_ms"] = derive_seconds / n * 1e3;
  state.counters["cpu_ms"] = cpu_seconds / n * 1e3;
}

void cached_start(benchmark::State& state, const std::string& model) {
  { sylva::Simulation warm(model_path(model), warm_options()); }  // make sure it is in the cache
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    auto simulation = std::make_unique<sylva::Simulation>(model_path(model), warm_options());
    state.SetIterationTime(seconds_since(start));
    if (simulation->compiled_now()) state.SkipWithError("the model was compiled, not taken from the cache");
    simulation.reset();  // unloads the library: every iteration loads it again
  }
}

void register_all() {
  struct Derived {
    const char* model;
    int steps;
    int iterations;
  };
  // koch_noparam is not among the targets; it shows what parameters cost.
  const Derived derived[] = {
      {"koch", 12, 3},
      {"koch_noparam", 12, 3},
      {"branching_nocontext", 21, 3},
      {"branching_context", 21, 3},
      {"branching_newleft", 21, 3},
      {"branching_newright", 20, 3},
  };
  for (const Derived& m : derived) {
    for (bool fresh : {true, false}) {
      const std::string name = std::string("Derive/") + m.model + "/" + std::to_string(m.steps) +
                               (fresh ? "/fresh" : "/reused");
      benchmark::RegisterBenchmark(name.c_str(), derive, std::string(m.model), m.steps, fresh, 0)
          ->UseManualTime()
          ->Iterations(m.iterations)
          ->Unit(benchmark::kMillisecond);
    }
  }
  // Speed-up with threads: the context-free models (one float a module,
  // none, and branches) and the ordinary-context one, not those whose new
  // context keeps them serial;
  // `reused`, with the buffers of the last iteration: the speed-up without
  // faulting in fresh pages, which on virtual machines scales worse than the
  // rewriting does.
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (bool fresh : {true, false})
    for (const Derived& m : {derived[0], derived[1], derived[2], derived[3]})
      for (int threads = 1; threads <= cores; threads *= 2)
        benchmark::RegisterBenchmark(("Threads/" + std::string(m.model) + "/" + std::to_string(m.steps) + "/" +
                                      std::to_string(threads) + (fresh ? "" : "/reused"))
                                         .c_str(),
                                     derive, std::string(m.model), m.steps, fresh, threads)
            ->UseManualTime()
            ->Iterations(m.iterations)
            ->Unit(benchmark::kMillisecond);
  for (int simulations : {1, 2})
    benchmark::RegisterBenchmark(("SimulationsAtOnce/koch/" + std::to_string(simulations)).c_str(),
                                 simulations_at_once, simulations)
        ->UseManualTime()
        ->Iterations(3)
        ->Unit(benchmark::kMillisecond);
  for (int threads = 1; threads <= 16; threads *= 2) {
    benchmark::RegisterBenchmark(("Pass/" + std::to_string(threads)).c_str(), pass_overhead, threads)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("PassAfterSerialWork/" + std::to_string(threads)).c_str(), pass_after_serial_work,
                                 threads)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("DiffusionStep", diffusion_step)
      ->UseManualTime()
      ->Iterations(20)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BytesPerModule/one_float", bytes_per_module, std::string("koch"))->Iterations(1);
  benchmark::RegisterBenchmark("BytesPerModule/no_params", bytes_per_module, std::string("koch_noparam"))
      ->Iterations(1);
  benchmark::RegisterBenchmark("FirstRun/borchert_honda/36", first_run, std::string("borchert_honda"), 36)
      ->UseManualTime()
      ->Iterations(5)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("FirstRun/koch/4", first_run, std::string("koch"), 4)
      ->UseManualTime()
      ->Iterations(5)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("CachedStart/borchert_honda", cached_start, std::string("borchert_honda"))
      ->UseManualTime()
      ->Iterations(200)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("CachedStart/koch", cached_start, std::string("koch"))
      ->UseManualTime()
      ->Iterations(200)
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
