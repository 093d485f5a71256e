// Stochastic productions in cpfg models with sub-L-systems (CPFG manual 4.5,
// 7.2). All L-systems draw from one random stream, drand48, which cpfg in
// batch never seeds: it starts from the C library's zero state whatever
// seed: says. Every module of a stochastic L-system takes one draw u in
// string order, and a module is rewritten by the first of its own
// L-system's productions whose cumulative probability reaches u times the
// total of that L-system's productions for it. The expected strings are
// worked out here with the C library's erand48 from the zero state, and
// the last is the reference cpfg's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "api/simulation.h"
#include "io/string_text.h"
#include "test_support.h"

namespace sylva::test {
namespace {

// L-system 1 rewrites the B outside the call: P, Q or R with weights 1, 1, 2
// (total 4). L-system 2 rewrites the B inside ?(2,1)...$: X with 30, Y with
// 70 (total 100). L-system 2's own seed: is not the stream's.
const char* const kModel =
    "Lsystem: 1\n"
    "seed: 1\n"
    "derivation length: 6\n"
    "Axiom: B?(2,1)B$\n"
    "B --> PB : 1\n"
    "B --> QB : 1\n"
    "B --> RB : 2\n"
    "endlsystem\n"
    "Lsystem: 2\n"
    "seed: 99\n"
    "Axiom: B\n"
    "B --> XB : 30\n"
    "B --> YB : 70\n"
    "endlsystem\n";

// The string after `steps` steps, derived by hand with erand48 from
// `state` (cpfg's batch runs: drand48's zero state).
std::string expected_after(int steps, unsigned short state[3]) {
  std::vector<std::string> modules = {"B", "?(2,1)", "B", "$"};
  for (int step = 0; step < steps; ++step) {
    std::vector<std::string> next;
    bool in_call = false;
    for (const std::string& m : modules) {
      const double u = erand48(state);  // every module draws, B or not
      if (m == "?(2,1)") in_call = true;
      if (m == "$") in_call = false;
      if (m != "B") {
        next.push_back(m);
        continue;
      }
      if (in_call) {
        next.push_back(100 * u - 30 <= 0 ? "X" : "Y");
      } else {
        const double r = 4 * u;
        next.push_back(r - 1 <= 0 ? "P" : r - 2 <= 0 ? "Q" : "R");
      }
      next.push_back("B");
    }
    modules = next;
  }
  std::string text;
  for (const std::string& m : modules) text += m;
  return text;
}

std::string expected_after(int steps) {
  unsigned short zero[3] = {0, 0, 0};
  return expected_after(steps, zero);
}

TEST(CpfgSubLsystemSeed, OneStreamAcrossLsystemsWithEachLsystemsTotals) {
  const std::string dir = make_temp_dir("cpfg-sub-seed");
  std::ofstream(dir + "/lsystem.l") << kModel;
  build::BuildOptions build;
  build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(dir + "/lsystem.l", build);
  simulation.begin();
  for (int steps = 1; steps <= 6; ++steps) {
    simulation.step();
    std::string text = io::format_string(simulation.string(), simulation.types());
    if (!text.empty() && text.back() == '\n') text.pop_back();
    EXPECT_EQ(text, expected_after(steps)) << "after " << steps << " steps";
  }
  // The reference cpfg (cpfg -g -str) gives this string after six steps.
  EXPECT_EQ(expected_after(6), "PPRRRRB?(2,1)XYYYYYB$");
}

// As cpfg's window seeds drand48: seed48({seed, 0, 155}) from the main
// L-system's seed: 1.
TEST(CpfgSubLsystemSeed, WindowSeedingStartsFromTheSeed) {
  const std::string dir = make_temp_dir("cpfg-sub-window-seed");
  std::ofstream(dir + "/lsystem.l") << kModel;
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.cpfg_window_seeding = true;
  Simulation simulation(dir + "/lsystem.l", options);
  simulation.run(6);
  std::string text = io::format_string(simulation.string(), simulation.types());
  if (!text.empty() && text.back() == '\n') text.pop_back();
  unsigned short seeded[3] = {1, 0, 155};
  EXPECT_EQ(text, expected_after(6, seeded));
  EXPECT_NE(text, expected_after(6));
}

TEST(CpfgSubLsystemSeed, ModulesOfADeterministicLsystemDoNotDraw) {
  // L-system 2 has no seed: its productions are not chosen at random (their
  // probabilities are read past with a warning) and its modules take no
  // draw, so the main L-system's B after the call draws next. The string is
  // the reference cpfg's.
  const std::string dir = make_temp_dir("cpfg-sub-deterministic");
  std::ofstream(dir + "/lsystem.l") << "Lsystem: 1\nseed: 1\nderivation length: 6\nAxiom: B?(2,1)B$B\n"
                                       "B --> PB : 1\nB --> QB : 1\nB --> RB : 2\nendlsystem\n"
                                       "Lsystem: 2\nAxiom: B\nB --> XB : 30\nB --> YB : 70\nendlsystem\n";
  ProcessResult r = run_sylva({"run", "lsystem.l"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "PQPQPRB?(2,1)XXXXXXB$PQRRPQB\n");
  EXPECT_NE(r.err.find("lsystem.l:11:12: warning: probability ignored"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sylva::test
