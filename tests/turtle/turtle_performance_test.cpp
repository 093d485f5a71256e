// Interpretation speed on a branching plant of about a million modules.
// The goal is 10 million modules per second; the test fails only far below
// it (a loaded machine must not make it flaky) and prints what it measured.
#include "turtle/turtle_fixture.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace sylva::test::turtle_tests {
namespace {

// Each apex makes an internode, two branches and two apices (10 modules):
// after 17 steps 2^17 apices and 8 (2^17 - 1) other modules, 1,179,640 in all.
TEST(TurtlePerformance, MillionModuleBranchingPlant) {
  auto sim = load_model("performance",
                        "module A(int);\n"
                        "derivation length: 17;\n"
                        "axiom: A(0);\n"
                        "A(n) : { produce F(1) SB Left(30) A(n+1) EB SB Right(25) RollL(137.5) A(n+1) EB; }\n");
  derive::Derivation& d = sim->derivation();
  d.run();
  const std::size_t modules = d.string().count_modules(d.types());
  ASSERT_EQ(modules, 1179640u);

  double best_scene = 1e9, best_query = 1e9;
  std::size_t segments = 0;
  for (int round = 0; round < 5; ++round) {
    auto t0 = std::chrono::steady_clock::now();
    Scene s = turtle::interpret_scene(d, {});
    auto t1 = std::chrono::steady_clock::now();
    turtle::fill_query_modules(d, {});
    auto t2 = std::chrono::steady_clock::now();
    best_scene = std::min(best_scene, std::chrono::duration<double>(t1 - t0).count());
    best_query = std::min(best_query, std::chrono::duration<double>(t2 - t1).count());
    segments = s.segments.size();
  }
  EXPECT_EQ(segments, 131071u);
  const double scene_rate = static_cast<double>(modules) / best_scene;
  const double query_rate = static_cast<double>(modules) / best_query;
  std::printf("[ turtle   ] %zu modules: scene %.1f M modules/s, query pass %.1f M modules/s\n", modules,
              scene_rate / 1e6, query_rate / 1e6);
  EXPECT_GT(scene_rate, 2e6);
}

}  // namespace
}  // namespace sylva::test::turtle_tests
