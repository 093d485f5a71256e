// honda81 as the Virtual Laboratory's program computes it (ENVIRO/honda81):
// an object is stopped (answered 0) by another of its group whose vigor is
// equal or higher, at a distance of `radius` or less; in 2D the program
// compares x and z. The unit tests' answers are worked by hand from that
// rule; the model at the end was run with the reference lpfg and the
// reference honda81, built from the Virtual Laboratory's sources.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "env/programs/collision_scene.h"
#include "env/programs/programs.h"
#include "support/diagnostic.h"
#include "test_support.h"

namespace sylva::env::test {
namespace {

std::unique_ptr<Field> honda81(const std::string& parameters) {
  return make_honda81(invocation_with("honda81", {{"honda.spec", parameters}}));
}

TEST(Honda81, AnObjectOfEqualOrHigherVigorWithinTheRadiusStops) {
  // Radius 0.5: 0.4 apart collide, 1.5 apart do not.
  auto field = honda81("radius: 0.5\n3d case: on\n");
  std::vector<Query> queries = {query_at({0, 0, 0}, {0.9f}), query_at({0.4f, 0, 0}, {0.5f}),
                                query_at({5, 0, 0}, {0.2f}), query_at({6.5f, 0, 0}, {0.8f})};
  auto answers = answer_all(*field, queries);
  EXPECT_EQ(first_answer(answers[0]), 1.0f);  // no neighbour as vigorous
  EXPECT_EQ(first_answer(answers[1]), 0.0f);  // the 0.9 is within 0.5
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
  EXPECT_EQ(first_answer(answers[3]), 1.0f);
  for (const Answer& answer : answers) EXPECT_FALSE(answer.set[1]);  // only p1 is answered
}

TEST(Honda81, TouchingCollidesAndEqualVigorStopsBoth) {
  auto field = honda81("radius: 1\n3d case: on\n");
  // Exactly the radius apart (0.5, -1 and 0.25 are exact in binary).
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0.7f}), query_at({0, 1, 0}, {0.7f}),
                                     query_at({10, 0, 0}, {0.3f}), query_at({10.5f, 0, 0}, {0.25f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);  // 0.25 is weaker
  EXPECT_EQ(first_answer(answers[3]), 0.0f);
}

TEST(Honda81, TwoDimensionsCompareXAndZ) {
  // 5 apart in y, 0.5 apart in z: in 2D only x and z count.
  std::vector<Query> queries = {query_at({0, 0, 0}, {1}), query_at({0, 5, 0.5f}, {0.5f})};
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n"), queries)[1]), 0.0f);
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n3d case: on\n"), queries)[1]), 1.0f);
  // 3 apart in z: apart in 2D as in 3D.
  std::vector<Query> apart = {query_at({0, 0, 0}, {1}), query_at({0, 0, 3}, {0.5f})};
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n"), apart)[1]), 1.0f);
}

TEST(Honda81, TheGroupIsTheSecondParameterTruncated) {
  auto field = honda81("radius: 1\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0.9f, 1}), query_at({0.1f, 0, 0}, {0.1f, 2}),
                                     query_at({0, 0, 0.1f}, {0.5f, 1.8f}), query_at({0.2f, 0, 0}, {0.05f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);  // alone in group 2
  EXPECT_EQ(first_answer(answers[2]), 0.0f);  // 1.8 is group 1: loses to 0.9
  EXPECT_EQ(first_answer(answers[3]), 1.0f);  // group 0 by default, alone
}

TEST(Honda81, WithoutARadiusOnlyObjectsAtOnePointCollide) {
  // The radius defaults to 0: distance <= 0.
  auto field = honda81("3d case: on\n");
  auto answers = answer_all(*field, {query_at({1, 2, 3}, {0.5f}), query_at({1, 2, 3}, {0.5f}),
                                     query_at({1, 2, 3.001f}, {0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
}

TEST(Honda81, QueriesWithoutParametersOrPositionGetNoAnswer) {
  auto field = honda81("radius: 1\n");
  Query blind = query_at({0, 0, 0}, {0.9f});
  blind.turtle.position_count = 2;  // the real program needs three values
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {}), blind, query_at({0, 0, 0}, {0.5f})});
  EXPECT_FALSE(answers[0].set.any());
  EXPECT_FALSE(answers[1].set.any());
  EXPECT_EQ(first_answer(answers[2]), 1.0f);  // neither of the others takes part
}

TEST(Honda81, AgreesWithComparingEveryPairOnARandomScene) {
  // 3000 points in a 40 x 40 square of the x z plane: the grid must find
  // exactly the pairs a comparison of all pairs finds.
  auto field = honda81("radius: 0.8\n");
  const float radius = 0.8f, radius_squared = radius * radius;  // squared in float, as honda81 does
  std::vector<Query> queries;
  std::uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  for (int i = 0; i < 3000; ++i) queries.push_back(query_at({40 * next(), next(), 40 * next()}, {next(), 0}));
  auto answers = answer_all(*field, queries);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    bool beaten = false;
    for (std::size_t j = 0; j < queries.size(); ++j) {
      if (i == j) continue;
      const float dx = queries[i].turtle.position[0] - queries[j].turtle.position[0];
      const float dz = queries[i].turtle.position[2] - queries[j].turtle.position[2];
      if (dx * dx + dz * dz <= radius_squared && queries[j].module.parameters[0] >= queries[i].module.parameters[0])
        beaten = true;
    }
    ASSERT_EQ(first_answer(answers[i]), beaten ? 0.0f : 1.0f) << i;
  }
}

// The specification file as honda81 reads it: exact keywords, strtok's
// delimiters (so "0.5x" is 0.5), atof, and nothing that stops the program.
TEST(Honda81, ReadsItsFileAsTheRealProgramDoes) {
  const std::vector<Query> pair = {query_at({0, 0, 0}, {0.5f}), query_at({0.4f, 0, 0}, {0.5f})};
  // "Radius" is not "radius": radius stays 0 and the pair is 0.4 apart.
  testing::internal::CaptureStderr();
  EXPECT_EQ(first_answer(answer_all(*honda81("Radius: 1\n"), pair)[0]), 1.0f);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("honda.spec:1: warning: honda81 does not know 'Radius'"),
            std::string::npos);
  // A value ends at x , ; space tab or colon: "0.5x2" reads 0.5.
  EXPECT_EQ(first_answer(answer_all(*honda81("radius:0.5x2\n"), pair)[0]), 0.0f);
  // atof reads the number at the token's start, with a warning.
  testing::internal::CaptureStderr();
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 0.45cm\n"), pair)[0]), 0.0f);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("'0.45cm' is not a number"), std::string::npos);
  // "3d case" is on only for "on": 5 apart in y, at one point in x z.
  const std::vector<Query> in_y = {query_at({0, 0, 0}, {0.5f}), query_at({0, 5, 0}, {0.5f})};
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n3d case: on\n"), in_y)[0]), 1.0f);
  testing::internal::CaptureStderr();
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n3d case: yes\n"), in_y)[0]), 0.0f);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("'yes' is not 'on'"), std::string::npos);
}

TEST(Honda81, AMissingSpecificationFileLeavesTheDefaults) {
  ProgramInvocation invocation;
  invocation.program = "honda81";
  invocation.e_file = "x.e";
  invocation.e_file_line = 3;
  EXPECT_THROW(make_honda81(invocation), ModelError);  // no file named at all: the real one exits
  invocation.arguments = {"-e", "x.e", "/nonexistent/honda.spec"};
  testing::internal::CaptureStderr();
  auto field = make_honda81(invocation);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("cannot open its specification file"), std::string::npos);
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0.5f}), query_at({0, 0, 0}, {0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);  // radius 0: one point
}

// An lpfg model run end to end. The expected modules are what the reference
// lpfg printed with the reference honda81 (lpfg -b honda.l honda.e -out):
// pairs touching in x z but 5 apart in y, a group 2.7 that is group 2, an E2
// whose one-value answer lpfg drops, and a pair 1.0001 apart.
TEST(Honda81, AnLpfgModelGetsTheReferenceAnswers) {
  const std::string dir = sylva::test::make_temp_dir("honda81-lpfg");
  std::ofstream(dir + "/honda.l") << R"(#include <lpfgall.h>
module Go();
module Stop();
module Unanswered();
derivation length: 1;
EA20Array obj(float vigor, float grp)
{
  EA20Array a;
  for (int i = 0; i < 20; ++i) a[i] = 0;
  a[0] = vigor;
  a[1] = grp;
  return a;
}
Axiom: SB() MoveTo(0,0,0) EA20(obj(0.5,0)) EB() SB() MoveTo(1,5,0) EA20(obj(0.5,0)) EB()
       SB() MoveTo(10,0,0) EA20(obj(0.9,1)) EB() SB() MoveTo(10,0,0.5) EA20(obj(0.2,1)) EB()
       SB() MoveTo(20,0,0) EA20(obj(0.9,2)) EB() SB() MoveTo(20,0,0.5) EA20(obj(0.2,2.7)) EB()
       SB() MoveTo(30,0,0) EA20(obj(0.1,3)) EB() SB() MoveTo(30,0,0) EA20(obj(0.9,4)) EB()
       SB() MoveTo(40,0,0) E2(0.3,0) EB() SB() MoveTo(50,0,0) E1(0.3) EB()
       SB() MoveTo(60,0,0) EA20(obj(0.4,0)) EB() SB() MoveTo(60,0,1.0001) EA20(obj(0.3,0)) EB();
EA20(a): { if (a[0] == 1) produce Go(); else if (a[0] == 0) produce Stop(); else produce Unanswered(); }
E2(a,b): { if (a == 1) produce Go(); else if (a == 0) produce Stop(); else produce Unanswered(); }
E1(a): { if (a == 1) produce Go(); else if (a == 0) produce Stop(); else produce Unanswered(); }
)";
  std::ofstream(dir + "/honda.e") << "executable: honda81 -e honda.e honda.spec\ncommunication type: files\n"
                                     "turtle position: P: %f %f %f\n";
  std::ofstream(dir + "/honda.spec") << "radius: 1\n";
  ProcessResult run = sylva::test::run_sylva({"run", "honda.l", "honda.e"}, dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::string names;
  for (char c : run.out)
    if (c != ' ' && c != '\n') names += c;
  for (std::size_t open; (open = names.find('(')) != std::string::npos;) names.erase(open, names.find(')', open) - open + 1);
  EXPECT_EQ(names,
            "SBMoveToStopEBSBMoveToStopEBSBMoveToGoEBSBMoveToStopEBSBMoveToGoEBSBMoveToStopEBSBMoveToGoEBSBMoveToGoEB"
            "SBMoveToUnansweredEBSBMoveToGoEBSBMoveToGoEBSBMoveToGoEB");
  EXPECT_NE(run.err.find("1 answer of the environmental program ignored"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace sylva::env::test
