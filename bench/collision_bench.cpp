// Collision programs answering one environmental pass (see bench/README.md).
//
//   Collision/<program>/<queries>
//       One pass of <queries> communication modules, placed at random in a
//       square (2D) or cube (3D) whose size keeps the number of objects per
//       unit area (volume) fixed, so that each object has a few neighbours
//       within reach whatever the count. Times Field::answer only: storing
//       the queries, building the grid, testing and answering.
//
// Counters: s/step (seconds per pass), colliding (objects answered 0).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "env/programs/programs.h"

namespace {

namespace fs = std::filesystem;

std::unique_ptr<sylva::env::Field> make_program(const std::string& program, const std::string& parameters) {
  fs::path dir = fs::temp_directory_path() / ("sylva-bench-" + program + "-" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "program.par") << parameters;
  sylva::env::ProgramInvocation invocation;
  invocation.program = program;
  invocation.arguments = {"program.par"};
  invocation.directory = dir;
  invocation.e_file = "bench.e";
  auto field = program == "honda81" ? sylva::env::make_honda81(invocation) : sylva::env::make_ecosystem(invocation);
  fs::remove_all(dir);
  return field;
}

// `count` queries at random, about one object per unit area or volume; the
// first parameter is a vigor (honda81) or a radius (ecosystem) in [low, high).
std::vector<sylva::env::Query> random_queries(std::size_t count, bool three_d, float low, float high) {
  std::mt19937 random(2024);
  std::uniform_real_distribution<float> unit(0, 1);
  float side = three_d ? std::cbrt(static_cast<float>(count)) : std::sqrt(static_cast<float>(count));
  std::vector<sylva::env::Query> queries(count);
  for (std::size_t i = 0; i < count; ++i) {
    sylva::env::Query& q = queries[i];
    q.id = i;
    q.module = {"?E", {low + (high - low) * unit(random)}};
    q.turtle.position = {side * unit(random), side * unit(random), three_d ? side * unit(random) : 0.0f};
    q.turtle.position_count = 3;
  }
  return queries;
}

void collision_pass(benchmark::State& state, const std::string& program, const std::string& parameters, bool three_d,
                    float low, float high) {
  auto field = make_program(program, parameters);
  auto queries = random_queries(static_cast<std::size_t>(state.range(0)), three_d, low, high);
  std::vector<sylva::env::Answer> answers(queries.size());
  double seconds = 0;
  for (auto _ : state) {
    std::fill(answers.begin(), answers.end(), sylva::env::Answer{});
    auto start = std::chrono::steady_clock::now();
    field->answer(queries, answers, 1);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(answers.data());
  }
  std::size_t colliding = 0;
  for (const auto& answer : answers) colliding += answer.value[0] == 0;
  state.counters["s/step"] = seconds / static_cast<double>(state.iterations());
  state.counters["colliding"] = static_cast<double>(colliding);
}

// Radius 0.3 at one object per unit area: about 1.1 neighbours within 2r.
BENCHMARK_CAPTURE(collision_pass, honda81_2d, "honda81", "radius: 0.3\n", false, 0.0f, 1.0f)
    ->Name("Collision/honda81_2d")->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(collision_pass, honda81_3d, "honda81", "radius: 0.3\n3d case: on\n", true, 0.0f, 1.0f)
    ->Name("Collision/honda81_3d")->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(collision_pass, honda81_point, "honda81", "radius: 0.01\n", false, 0.0f, 1.0f)
    ->Name("Collision/honda81_points")->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(collision_pass, ecosystem_2d, "ecosystem", "grid size: 10 10\n", false, 0.1f, 0.5f)
    ->Name("Collision/ecosystem_2d")->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
