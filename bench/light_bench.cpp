// Benchmarks of the light environments (EnviroManual 3.2): one environmental
// pass of 100,000 queries, as a dense forest canopy would send each step.
//
//   Light/chiba/<sky128|sky128_area|sources9>/100000
//       100 tree crowns on a 10 x 10 grid 40 apart, each a ball of radius 15
//       holding 1,000 leaf-cluster spheres of radius 1 (4 parameters, so
//       the brightest direction is computed too). sky128: the light sphere of
//       128 samples (CIE sky); sky128_area: the same with "estimate
//       intersection area: on"; sources9: 9 explicit sources. Grid 64^3.
//   Light/takenaka/sources9/100000
//       The same canopy as clusters of area pi (spheres of radius 1.5), 9
//       sources, beam radius 1.
//   Light/clover/100000
//       A 2000 x 2000 grid over a 1000 x 1000 field; 50,000 leaves entered
//       and 100,000 light queries per pass, leaves removed after each pass.
//
// The reported time is wall-clock seconds per pass (per step); counter
// `cpu_s/step` is the CPU time of all threads per pass (the figure to trust
// on a loaded machine) and `threads` how many threads the programs used.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <thread>
#include <unistd.h>

#include "env/field.h"
#include "env/program.h"
#include "env/programs/programs.h"

namespace {

namespace fs = std::filesystem;
using sylva::env::Answer;
using sylva::env::Field;
using sylva::env::ProgramInvocation;
using sylva::env::Query;

constexpr int kQueries = 100'000;

ProgramInvocation write_parameters(const std::string& program, const std::string& text) {
  fs::path dir = fs::temp_directory_path() / ("sylva-bench-light-" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / (program + ".par")) << text;
  return ProgramInvocation{program, {program + ".par"}, dir, (dir / "field.e").string(), 1};
}

Query query(float x, float y, float z, std::vector<float> parameters) {
  Query q;
  q.module.symbol = "?E";
  q.module.parameters = std::move(parameters);
  q.turtle.position = {x, y, z};
  q.turtle.position_count = 3;
  return q;
}

// Leaf clusters in 100 crowns: uniform in balls of radius 15, centred 25 up.
std::vector<Query> canopy(std::vector<float> parameters) {
  std::mt19937 random(1);
  std::uniform_real_distribution<float> unit(-1, 1);
  std::vector<Query> queries;
  queries.reserve(kQueries);
  for (int i = 0; i < kQueries; ++i) {
    int tree = i % 100;
    float x, y, z;
    do {
      x = unit(random), y = unit(random), z = unit(random);
    } while (x * x + y * y + z * z > 1);
    queries.push_back(query(40.0f * (tree % 10) + 15 * x, 25 + 15 * y, 40.0f * (tree / 10) + 15 * z, parameters));
    queries.back().id = static_cast<std::uint64_t>(i);
  }
  return queries;
}

// Nine sources over the sky: the zenith and two rings of four.
std::string nine_sources(const std::string& keyword) {
  std::string text = keyword + ": 0 1 0 1\n";
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < 4; ++k) {
      double azimuth = (k + 0.5 * ring) * std::numbers::pi / 2, elevation = ring == 0 ? 0.9 : 0.45;
      text += keyword + ": " + std::to_string(std::cos(elevation) * std::cos(azimuth)) + " " +
              std::to_string(std::sin(elevation)) + " " + std::to_string(std::cos(elevation) * std::sin(azimuth)) +
              (ring == 0 ? " 0.8\n" : " 0.5\n");
    }
  return text;
}

// CPU seconds of the whole process (all threads), user + system.
double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](timeval t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void run_passes(benchmark::State& state, Field& field, const std::vector<Query>& queries) {
  std::vector<Answer> answers(queries.size());
  int step = 0;
  double cpu = 0;
  for (auto _ : state) {
    std::fill(answers.begin(), answers.end(), Answer{});
    double start = process_cpu_seconds();
    field.answer(queries, answers, step++);
    cpu += process_cpu_seconds() - start;
    benchmark::DoNotOptimize(answers.data());
  }
  state.counters["cpu_s/step"] = cpu / static_cast<double>(state.iterations());
  state.counters["queries"] = static_cast<double>(queries.size());
  state.counters["threads"] = std::max(1u, std::thread::hardware_concurrency());
}

void chiba(benchmark::State& state, const std::string& parameters) {
  auto field = sylva::env::make_chiba(write_parameters("chiba", parameters));
  run_passes(state, *field, canopy({1.0f, 0, 0, 0}));
}

void BM_ChibaSky(benchmark::State& state) {
  chiba(state, "grid size: 64 64 64\nnumber of samples: 128\nuse CIE formula: yes\ntransmittance: 0.6\n");
}
void BM_ChibaSkyArea(benchmark::State& state) {
  chiba(state, "grid size: 64 64 64\nnumber of samples: 128\nuse CIE formula: yes\ntransmittance: 0.6\n"
               "estimate intersection area: on\n");
}
void BM_ChibaSources(benchmark::State& state) {
  chiba(state, "grid size: 64 64 64\ntransmittance: 0.6\n" + nine_sources("source direction"));
}

void BM_Takenaka(benchmark::State& state) {
  auto field = sylva::env::make_takenaka(
      write_parameters("takenaka", "grid size: 64 64 64\nbeam radius: 1\n" + nine_sources("source")));
  run_passes(state, *field, canopy({std::numbers::pi_v<float>, 0.01f, 0, 0}));
}

void BM_Clover(benchmark::State& state) {
  auto field = sylva::env::make_clover(write_parameters(
      "clover", "grid range: 1000 1000\ngrid position: 0 0\ngrid size: 2000 2000\ntransmittance: 0.3\n"
                "remove old leaves: yes\n"));
  std::mt19937 random(2);
  std::uniform_real_distribution<float> ground(0, 1000);
  std::vector<Query> queries;
  for (int i = 0; i < kQueries / 2; ++i) queries.push_back(query(ground(random), ground(random), 0, {1, 3}));
  for (int i = 0; i < kQueries; ++i) queries.push_back(query(ground(random), ground(random), 0, {0, 0}));
  for (std::size_t i = 0; i < queries.size(); ++i) queries[i].id = i;
  run_passes(state, *field, queries);
}

BENCHMARK(BM_ChibaSky)->Name("Light/chiba/sky128/100000")->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_ChibaSkyArea)->Name("Light/chiba/sky128_area/100000")->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_ChibaSources)->Name("Light/chiba/sources9/100000")->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_Takenaka)->Name("Light/takenaka/sources9/100000")->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_Clover)->Name("Light/clover/100000")->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
