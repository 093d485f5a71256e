// A branching plant of about a million modules: every module reaches the
// turtle, and the Scene holds one segment per F. (Its speed is measured by
// bench/turtle_bench.cpp, not here.)
#include "turtle/turtle_fixture.h"

namespace sylva::test::turtle_tests {
namespace {

// Each apex makes an internode, two branches and two apices (10 modules):
// after 17 steps 2^17 apices and 8 (2^17 - 1) other modules, 1,179,640 in all,
// of which 2^17 - 1 = 131,071 are F.
TEST(TurtleLargePlant, MillionModuleBranchingPlant) {
  auto sim = load_model("large-plant",
                        "module A(int);\n"
                        "derivation length: 17;\n"
                        "axiom: A(0);\n"
                        "A(n) : { produce F(1) SB Left(30) A(n+1) EB SB Right(25) RollL(137.5) A(n+1) EB; }\n");
  sim->run();
  ASSERT_EQ(sim->string().count_modules(sim->types()), 1179640u);
  Scene s = sim->scene(0);
  EXPECT_EQ(s.segments.size(), 131071u);
}

}  // namespace
}  // namespace sylva::test::turtle_tests
