// The step that made each module (Simulation::birth_steps), worked by hand:
// a module a production rewrote is made at that step; one copied keeps its.
#include <gtest/gtest.h>

#include "api/simulation.h"
#include "test_support.h"

namespace sylva::test {
namespace {

using Births = std::vector<std::uint32_t>;

Births births_after(const std::string& name, const std::string& model, int steps) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation s(write_temp_file(name, name + ".l", model), options, [](const std::string&) {});
  s.track_births(true);
  s.begin();
  for (int i = 0; i < steps; ++i) s.step();
  EXPECT_EQ(s.birth_steps().size(), s.string().count_modules(s.types())) << s.string_text();
  return s.birth_steps();
}

TEST(BirthSteps, ProductionsMakeModulesCopiesKeepTheirStep) {
  // A -> F A: F F F A after three steps, the Fs made at steps 1, 2, 3.
  const char* model =
      "#include <lpfgall.h>\nmodule A();\nmodule X();\nderivation length: 3;\naxiom: X A;\n"
      "A() : { produce F(1) A; }\n";
  EXPECT_EQ(births_after("births-forward", model, 0), (Births{0, 0}));
  EXPECT_EQ(births_after("births-forward", model, 3), (Births{0, 1, 2, 3, 3}));
}

TEST(BirthSteps, BackwardDerivationToo) {
  // Backward: A -> A A doubles the As, X and B stay as the axiom made them.
  const char* model =
      "#include <lpfgall.h>\nmodule A();\nmodule B();\nmodule X();\nderivation length: 2;\n"
      "Start: { Backward(); }\naxiom: A X B;\nA() : { produce A A; }\n";
  EXPECT_EQ(births_after("births-backward", model, 1), (Births{1, 1, 0, 0}));
  EXPECT_EQ(births_after("births-backward", model, 2), (Births{2, 2, 2, 2, 0, 0}));
}

TEST(BirthSteps, DecompositionMakesWhatItExpands) {
  // Step 1 turns B into D; decomposition then expands D into E E.
  const char* model =
      "#include <lpfgall.h>\nmodule B();\nmodule D();\nmodule E();\nderivation length: 2;\naxiom: B E;\n"
      "B() : { produce D; }\ndecomposition:\nD() : { produce E E; }\n";
  EXPECT_EQ(births_after("births-decomposition", model, 1), (Births{1, 1, 0}));
}

TEST(BirthSteps, CutDropsABranchAndTheRestIsKept) {
  // Step 1: C -> Cut; step 2 cuts [ C ... ] up to its end bracket.
  const char* model =
      "#include <lpfgall.h>\nmodule A();\nmodule C();\nderivation length: 2;\naxiom: A SB C A EB A;\n"
      "C() : { produce Cut(); }\n";
  EXPECT_EQ(births_after("births-cut", model, 1), (Births{0, 0, 1, 0, 0, 0}));
  EXPECT_EQ(births_after("births-cut", model, 2), (Births{0, 0, 0, 0}));
}

TEST(BirthSteps, NotTrackedUnlessAskedFor) {
  build::BuildOptions options;
  options.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation s(write_temp_file("births-off", "off.l", "#include <lpfgall.h>\nmodule A();\naxiom: A;\n"), options);
  s.run(1);
  EXPECT_TRUE(s.birth_steps().empty());
}

}  // namespace
}  // namespace sylva::test
