// The turtle's position and frame (LPFG manual 5.1, 5.2, 5.4, 5.12). The
// initial frame is H = (0,1,0), L = (-1,0,0), U = (0,0,1) (CPFG manual:
// models grow up the screen). Every expected value is worked out by hand in
// the comment above it.
#include "turtle/turtle_fixture.h"

#include "io/string_text.h"

namespace sylva::test::turtle_tests {
namespace {

// F(1) goes up to (0,1,0); Left(90) turns H toward L, so H = (-1,0,0); the
// second F(1) ends at (-1,1,0).
TEST(TurtleMoves, ForwardLeftForward) {
  Scene s = draw("forward-left", "F(1) Left(90) F(1)");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[0].start, {0, 0, 0});
  expect_near(s.segments[0].end, {0, 1, 0});
  expect_near(s.segments[1].start, {0, 1, 0});
  expect_near(s.segments[1].end, {-1, 1, 0});
}

// Right(90) turns H away from L: H = (1,0,0), so F(2) ends at (2,0,0).
// TurnAround: H = (0,-1,0), F(1) ends at (0,-1,0).
TEST(TurtleMoves, RightAndTurnAround) {
  Scene s = draw("right-turn-around", "SB Right(90) F(2) EB TurnAround F(1)");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[0].end, {2, 0, 0});
  expect_near(s.segments[1].end, {0, -1, 0});
}

// Up pitches H toward U = (0,0,1); Down toward -U. With "corrected rotation"
// off (lpfg's old rotations) both go the other way.
TEST(TurtleMoves, UpAndDownAndTheOldRotations) {
  Scene s = draw("up-down", "SB Up(90) F(1) EB SB Down(90) F(1) EB SB Up(30) F(2) EB");
  ASSERT_EQ(s.segments.size(), 3u);
  expect_near(s.segments[0].end, {0, 0, 1});
  expect_near(s.segments[1].end, {0, 0, -1});
  // Up(30): H = (0, cos 30, sin 30); F(2) ends at (0, 1.7320508, 1).
  expect_near(s.segments[2].end, {0, 1.7320508f, 1});

  turtle::TurtleSettings old;
  old.corrected_rotation = false;
  Scene o = draw("up-down", "SB Up(90) F(1) EB SB Down(90) F(1) EB SB Up(30) F(2) EB", old);
  expect_near(o.segments[0].end, {0, 0, -1});
  expect_near(o.segments[1].end, {0, 0, 1});
}

// RollL(90) turns U toward L: U = (-1,0,0), L = (0,0,-1); Left(90) then
// turns H toward the new L, and F(1) ends at (0,0,-1). RollR the other way:
// L = (0,0,1), F(1) ends at (0,0,1).
TEST(TurtleMoves, Rolls) {
  Scene s = draw("rolls", "SB RollL(90) Left(90) F(1) EB SB RollR(90) Left(90) F(1) EB");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[0].end, {0, 0, -1});
  expect_near(s.segments[1].end, {0, 0, 1});
  // The segment carries the up vector it was drawn with: after RollL(90) and
  // Left(90) (a turn around U) U is still (-1,0,0).
  expect_near(s.segments[0].up, {-1, 0, 0});
}

// The stack: the branch F(1) from (0,1,0) toward -x, then the main axis goes
// on from (0,1,0) with H = (0,1,0).
TEST(TurtleMoves, BranchRestoresTheState) {
  Scene s = draw("branch", "F(1) SB Left(90) SetWidth(3) SetColor(5) F(1) EB F(1) EB F(1)");
  ASSERT_EQ(s.segments.size(), 4u);
  expect_near(s.segments[1].start, {0, 1, 0});
  expect_near(s.segments[1].end, {-1, 1, 0});
  EXPECT_FLOAT_EQ(s.segments[1].start_width, 3);
  EXPECT_EQ(s.segments[1].color, 5);
  expect_near(s.segments[2].start, {0, 1, 0});
  expect_near(s.segments[2].end, {0, 2, 0});
  EXPECT_FLOAT_EQ(s.segments[2].start_width, 1);
  EXPECT_EQ(s.segments[2].color, 1);
  // An EB without its SB changes nothing.
  expect_near(s.segments[3].start, {0, 2, 0});
  expect_near(s.segments[3].end, {0, 3, 0});
}

// f and g move without drawing.
TEST(TurtleMoves, InvisibleMoves) {
  Scene s = draw("invisible", "f(1) g(2) G(1)");
  ASSERT_EQ(s.segments.size(), 1u);
  expect_near(s.segments[0].start, {0, 3, 0});
  expect_near(s.segments[0].end, {0, 4, 0});
}

// MoveTo and MoveRel move without drawing; LineTo, LineRel and Line draw
// and leave the turtle at the end; the frame is untouched (F goes up).
TEST(TurtleMoves, AbsoluteAndRelativeMovesAndLines) {
  Scene s = draw("absolute",
                 "MoveTo(3,4,5) F(1) MoveRel3f(V3f(1,0,0)) F(1) LineTo(0,0,0) LineRel2f(V2f(0,2)) "
                 "Line3f(V3f(1,1,1), V3f(1,1,3)) F(1) MoveTo2d(V2d(7,8)) LineTo3d(V3d(7,8,1)) "
                 "Line2d(V2d(0,0), V2d(0,0))");
  ASSERT_EQ(s.segments.size(), 7u);
  expect_near(s.segments[0].start, {3, 4, 5});
  expect_near(s.segments[0].end, {3, 5, 5});
  expect_near(s.segments[1].start, {4, 5, 5});
  expect_near(s.segments[1].end, {4, 6, 5});
  expect_near(s.segments[2].start, {4, 6, 5});
  expect_near(s.segments[2].end, {0, 0, 0});
  expect_near(s.segments[3].end, {0, 2, 0});
  expect_near(s.segments[4].start, {1, 1, 1});
  expect_near(s.segments[4].end, {1, 1, 3});
  expect_near(s.segments[5].start, {1, 1, 3});
  expect_near(s.segments[5].end, {1, 2, 3});
  expect_near(s.segments[6].start, {7, 8, 0});
  expect_near(s.segments[6].end, {7, 8, 1});
  // Line2d between two equal points is ignored (closer than 1e-5).
}

// SetCoordinateSystem(2) at (0,1,0) after Left(90): H = (-1,0,0),
// L = (0,-1,0), U = (0,0,1). Local x runs along -L, y along H, z along U,
// each scaled by 2: MoveTo(1,0,0) is (0,1,0) + (0,2,0) = (0,3,0) and
// LineTo(0,1,0) is (0,1,0) + (-2,0,0) = (-2,1,0).
TEST(TurtleMoves, CoordinateSystem) {
  Scene s = draw("coordinates", "F(1) Left(90) SetCoordinateSystem(2) MoveTo(1,0,0) LineTo(0,1,0)");
  ASSERT_EQ(s.segments.size(), 2u);
  expect_near(s.segments[1].start, {0, 3, 0});
  expect_near(s.segments[1].end, {-2, 1, 0});
}

// RotateXYZ around world z by 90 turns H = (0,1,0) to (-1,0,0).
// RotateHLU around the local U is Left; around the local L (0,1,0 in HLU)
// by 90 turns H to -U = (0,0,-1).
TEST(TurtleMoves, RotationsAroundAxes) {
  Scene s = draw("rotate-axes",
                 "SB RotateXYZ(V3f(0,0,5), 90) F(1) EB SB RotateHLU(V3f(0,0,1), 90) F(1) EB "
                 "SB RotateHLU(V3f(0,1,0), 90) F(1) EB SB RotateXYZ(V3f(0,0,0), 90) F(1) EB");
  ASSERT_EQ(s.segments.size(), 4u);
  expect_near(s.segments[0].end, {-1, 0, 0});
  expect_near(s.segments[1].end, {-1, 0, 0});
  expect_near(s.segments[2].end, {0, 0, -1});
  expect_near(s.segments[3].end, {0, 1, 0});  // no axis: no rotation
}

// The query modules write the turtle's state into the string after a step.
// F(2) Left(90) F(1): position (-1,2,0), H = (-1,0,0), L = (0,-1,0), U = (0,0,1).
TEST(TurtleQuery, GetPosAndFrameAreWrittenBackAfterAStep) {
  auto sim = load_model("query",
                        "module A();\n"
                        "derivation length: 1;\n"
                        "axiom: F(2) Left(90) F(1) GetPos(0,0,0) GetHead(0,0,0) GetLeft(0,0,0) GetUp(0,0,0) A;\n"
                        "GetPos(x,y,z) < A() : { produce A; }\n");
  Simulation& d = *sim;
  ASSERT_TRUE(d.fills_query_modules());
  d.run(1);
  expect_near(module_floats(d, mid::GetPos, 0, 3), {-1, 2, 0});
  expect_near(module_floats(d, mid::GetHead, 0, 3), {-1, 0, 0});
  expect_near(module_floats(d, mid::GetLeft, 0, 3), {0, -1, 0});
  expect_near(module_floats(d, mid::GetUp, 0, 3), {0, 0, 1});
}

// A model that reads its GetPos: an apex grows a unit F per step while the
// GetPos before it is below y = 2.5. Step 1 sees y = 0 (the axiom's value
// written by the query pass), then 1, 2, 3: it stops after three F's.
TEST(TurtleQuery, ModelReadsThePositionItQueried) {
  auto sim = load_model("query-growth",
                        "module A();\n"
                        "derivation length: 6;\n"
                        "axiom: GetPos(0,0,0) A;\n"
                        "GetPos(x,y,z) < A() : { if (y < 2.5) produce F(1) GetPos(0,0,0) A; }\n");
  Simulation& d = *sim;
  d.run();
  Scene s = d.scene(0);
  ASSERT_EQ(s.segments.size(), 3u);
  expect_near(module_floats(d, mid::GetPos, 3, 3), {0, 3, 0});
}

// SetHead(1,0,0, 0,1,0): H = (1,0,0), U = (0,1,0), L = U x H = (0,0,-1).
// SetHead3f(1,0,0) from the initial frame: the half-turn-free rotation
// around (0,0,-1) keeps U = (0,0,1) and takes L to (0,1,0).
TEST(TurtleQuery, SetHeadAndSetHead3f) {
  auto sim = load_model("set-head",
                        "derivation length: 0;\n"
                        "axiom: SB SetHead(2,0,0, 0,3,0) GetHead(0,0,0) GetLeft(0,0,0) GetUp(0,0,0) EB "
                        "SB SetHead3f(V3f(1,0,0)) GetHead(0,0,0) GetLeft(0,0,0) GetUp(0,0,0) EB "
                        "SB SetHead(1,0,0, 1,0,0) GetHead(0,0,0) EB;\n");
  const Simulation& d = *sim;
  sim->run(0);
  expect_near(queried_floats(d, {}, mid::GetHead, 0, 3), {1, 0, 0});
  expect_near(queried_floats(d, {}, mid::GetLeft, 0, 3), {0, 0, -1});
  expect_near(queried_floats(d, {}, mid::GetUp, 0, 3), {0, 1, 0});
  expect_near(queried_floats(d, {}, mid::GetHead, 1, 3), {1, 0, 0});
  expect_near(queried_floats(d, {}, mid::GetLeft, 1, 3), {0, 1, 0});
  expect_near(queried_floats(d, {}, mid::GetUp, 1, 3), {0, 0, 1});
  // H parallel to U: ignored.
  expect_near(queried_floats(d, {}, mid::GetHead, 2, 3), {0, 1, 0});
}

// RollToVert after Left(45) RollL(90): H = (-a, a, 0) with a = 1/sqrt(2).
// L = V x H / |V x H| with V = (0,1,0): (0,0,a) normalized = (0,0,1);
// U = H x L = (a, a, 0), pointing up. H is unchanged.
// After Right(90) (H = (1,0,0)) and any roll: L = (0,0,-1), U = (0,1,0).
TEST(TurtleQuery, RollToVert) {
  auto sim = load_model("roll-to-vert",
                        "derivation length: 0;\n"
                        "axiom: SB Left(45) RollL(90) RollToVert GetHead(0,0,0) GetLeft(0,0,0) GetUp(0,0,0) EB "
                        "SB Right(90) RollL(37) RollToVert GetLeft(0,0,0) GetUp(0,0,0) EB "
                        "SB RollL(20) RollToVert GetUp(0,0,0) EB;\n");
  const Simulation& d = *sim;
  sim->run(0);
  const float a = 0.70710678f;
  expect_near(queried_floats(d, {}, mid::GetHead, 0, 3), {-a, a, 0});
  expect_near(queried_floats(d, {}, mid::GetLeft, 0, 3), {0, 0, 1});
  expect_near(queried_floats(d, {}, mid::GetUp, 0, 3), {a, a, 0});
  expect_near(queried_floats(d, {}, mid::GetLeft, 1, 3), {0, 0, -1});
  expect_near(queried_floats(d, {}, mid::GetUp, 1, 3), {0, 1, 0});
  // H vertical: every roll has H and U in a vertical plane; nothing changes.
  // RollL(20) turned U = (0,0,1) toward L = (-1,0,0): (-sin 20, 0, cos 20).
  expect_near(queried_floats(d, {}, mid::GetUp, 2, 3), {-0.34202014f, 0, 0.93969262f});
}

// Every primitive knows its module: F(1) at index 0, the branch's F at 3;
// an interpretation rule's F's carry the index of the module they replace.
TEST(TurtleProvenance, IndexAndIdOfTheModule) {
  auto sim = load_model("provenance",
                        "module A();\n"
                        "derivation length: 0;\n"
                        "axiom: F(1) SB Left(30) F(1) EB A Sphere(1);\n"
                        "interpretation:\n"
                        "A() : { produce F(1) Circle(1) F(1); }\n");
  sim->run(0);
  Scene s = sim->scene(0);
  ASSERT_EQ(s.segments.size(), 4u);
  EXPECT_EQ(s.segments[0].from.module_index, 0u);
  EXPECT_EQ(s.segments[1].from.module_index, 3u);
  EXPECT_EQ(s.segments[2].from.module_index, 5u);
  EXPECT_EQ(s.segments[3].from.module_index, 5u);
  EXPECT_EQ(s.segments[2].from.module_id, mid::F);
  ASSERT_EQ(s.circles.size(), 1u);
  EXPECT_EQ(s.circles[0].from.module_index, 5u);
  EXPECT_EQ(s.circles[0].from.module_id, mid::Circle);
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.spheres[0].from.module_index, 6u);
  expect_near(s.spheres[0].center, {0, 3, 0});
}

// The --turtle trace: one line per turtle command; user modules are silent.
TEST(TurtleTrace, OneLinePerCommand) {
  std::string trace;
  draw("trace", "F(1) Left(90) SB F(0.5) EB SetColor(3)", {}, &trace,
       "module A();");
  EXPECT_EQ(trace,
            "F(1) from (0,0,0) to (0,1,0)\n"
            "Left(90) H (-1,0,0) L (0,-1,0) U (0,0,1)\n"
            "SB depth 1\n"
            "F(0.5) from (0,1,0) to (-0.5,1,0)\n"
            "EB depth 0 at (0,1,0)\n"
            "SetColor(3)\n");
}

}  // namespace
}  // namespace sylva::test::turtle_tests
