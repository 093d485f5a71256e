// Tropisms (LPFG manual 5.11, 8.1.4; CPFG manual 8.1.8): after each F the
// heading turns toward T by elasticity * |H x T| radians; a torque turns the
// turtle around H instead. The first F is drawn before any bending.
#include "turtle/turtle_fixture.h"

#include <cmath>

namespace sylva::test::turtle_tests {
namespace {

turtle::TurtleSettings toward_x(float elasticity, float step = 0) {
  turtle::TurtleSettings s;
  turtle::Tropism t;
  t.direction = {1, 0, 0};
  t.elasticity = elasticity;
  t.step = step;
  s.tropisms.push_back(t);
  return s;
}

// H = (0,1,0), T = (1,0,0): |H x T| = 1, so H turns 0.5 rad toward +x:
// H = (sin 0.5, cos 0.5, 0) and the second F(1) ends at
// (0.4794255, 1.8775826, 0).
TEST(TurtleTropism, BendsTheHeadingTowardT) {
  Scene s = draw("tropism", "F(1) F(1)", toward_x(0.5f));
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[0].end, {0, 1, 0});
  expect_near(s.segments[1].end, {0.47942554f, 1.87758256f, 0});
}

// SetElasticity in a branch ends with the branch: the branch is straight,
// the main axis bends as before.
TEST(TurtleTropism, ElasticityIsPartOfTheBranchState) {
  Scene s = draw("tropism-branch", "SB SetElasticity(1, 0) F(1) F(1) EB F(1) F(1)", toward_x(0.5f));
  ASSERT_EQ(s.segments.size(), 4u);
  expect_near(s.segments[1].end, {0, 2, 0});
  expect_near(s.segments[3].end, {0.47942554f, 1.87758256f, 0});
}

// IncElasticity adds the step (0.25) to the initial 0; twice up, once down:
// 0.25 rad, so the second F ends at (sin 0.25, 1 + cos 0.25, 0).
TEST(TurtleTropism, IncAndDecElasticity) {
  Scene s = draw("tropism-inc", "IncElasticity(1) IncElasticity(1) DecElasticity(1) F(1) F(1) SetElasticity(7, 1)",
                 toward_x(0, 0.25f));
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[1].end, {0.24740396f, 1.96891242f, 0});
}

// The simple tropism (stropism, T = (-1,0,0)) with Elasticity(0.5): the
// mirror image of the first test.
TEST(TurtleTropism, SimpleTropismByElasticity) {
  turtle::TurtleSettings settings;
  settings.simple_tropism.direction = {-1, 0, 0};
  Scene s = draw("stropism", "F(1) F(1) Elasticity(0.5) F(1) F(1)", settings);
  ASSERT_EQ(s.segments.size(), 4u);
  expect_near(s.segments[1].end, {0, 2, 0});
  expect_near(s.segments[2].end, {0, 3, 0});
  expect_near(s.segments[3].end, {-0.47942554f, 3.87758256f, 0});
}

// With A = 90 (diatropism) a heading already at 90 degrees to T stays.
TEST(TurtleTropism, AngleToReach) {
  turtle::TurtleSettings settings = toward_x(0.5f);
  settings.tropisms[0].angle = 90;
  Scene s = draw("tropism-angle", "F(1) F(1)", settings);
  expect_near(s.segments[1].end, {0, 2, 0});
}

// A torque toward T = (1,0,0): H stays, U turns 0.5 rad around H toward
// +x: U = (sin 0.5, 0, cos 0.5).
TEST(TurtleTropism, TorqueTwistsAroundTheHeading) {
  turtle::TurtleSettings settings = toward_x(0.5f);
  settings.tropisms[0].torque = true;
  auto sim = load_model("torque", "derivation length: 0;\naxiom: F(1) GetHead(0,0,0) GetUp(0,0,0);\n");
  sim->run(0);
  expect_near(queried_floats(*sim, settings, mid::GetHead, 0, 3), {0, 1, 0});
  expect_near(queried_floats(*sim, settings, mid::GetUp, 0, 3), {0.47942554f, 0, 0.87758256f});
}

}  // namespace
}  // namespace sylva::test::turtle_tests
