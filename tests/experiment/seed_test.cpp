// A run's seed (SimulationOptions::seed, `sylva run --seed`): the generators
// start as the model's own seeding would set them, and the model's own
// seeding is passed over.
#include <gtest/gtest.h>

#include <fstream>

#include "api/simulation.h"
#include "test_support.h"

namespace sylva {
namespace {

std::string derive(const std::string& model, std::optional<long> seed, bool window_seeding = false) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.seed = seed;
  options.cpfg_window_seeding = window_seeding;
  Simulation simulation(model, options, [](const std::string&) {});
  simulation.run();
  return simulation.string_text();
}

std::string lpfg_model(const std::string& dir, const std::string& name, const std::string& start) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << "#include <lpfgall.h>\nmodule A(float);\nderivation length: 3;\n" << start
                      << "axiom: A(0) A(0);\nA(x) : { produce A(ran(1)) A(ran(1) + x); }\n";
  return path;
}

TEST(RunSeed, IsTheModelsOwnSranAndPassesItOver) {
  const std::string dir = test::make_temp_dir("run-seed-lpfg");
  const std::string seeds_itself = lpfg_model(dir, "own.l", "Start: { sran(7); }\n");
  const std::string plain = lpfg_model(dir, "plain.l", "");
  const std::string by_model = derive(seeds_itself, std::nullopt);
  // --seed 7 is what sran(7) in Start gives.
  EXPECT_EQ(derive(plain, 7), by_model);
  // With a seed, the model's own sran(7) is passed over.
  EXPECT_EQ(derive(seeds_itself, 8), derive(plain, 8));
  EXPECT_NE(derive(plain, 8), by_model);
  // A run is its seed's alone: the same seed twice, the same string.
  EXPECT_EQ(derive(plain, 8), derive(plain, 8));
}

TEST(RunSeed, IsACpfgModelsSeedAsItsWindowTakesIt) {
  const std::string dir = test::make_temp_dir("run-seed-cpfg");
  auto model = [&](int seed) {
    const std::string path = dir + "/stochastic-" + std::to_string(seed) + ".l";
    std::ofstream(path) << "Lsystem: 1\nseed: " << seed << "\nderivation length: 2\nAxiom: A A A A A A A A A A A A\n"
                        << "A --> A B : 0.5\nA --> B : 0.5\nendlsystem\n";
    return path;
  };
  // cpfg's window seeds from seed: 5; --seed 5 does the same whatever seed: says.
  const std::string windowed = derive(model(5), std::nullopt, true);
  EXPECT_EQ(derive(model(5), 5), windowed);
  EXPECT_EQ(derive(model(9), 5), windowed);
  EXPECT_NE(derive(model(5), 6), windowed);
}

TEST(RunSeed, TheCommandLineTakesIt) {
  const std::string dir = test::make_temp_dir("run-seed-cli");
  const std::string plain = lpfg_model(dir, "plain.l", "");
  const ProcessResult r = test::run_sylva({"run", plain, "--seed", "7", "--string", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, derive(plain, 7));
}

}  // namespace
}  // namespace sylva
