// honda81 (EnviroManual 3.1.1): disks of one radius; of two colliding disks
// the one with the lower vigor is answered 0.
#include <gtest/gtest.h>

#include <cmath>

#include "env/programs/programs.h"
#include "env/programs/collision_scene.h"
#include "support/diagnostic.h"

namespace sylva::env::test {
namespace {

std::unique_ptr<Field> honda81(const std::string& parameters) {
  return make_honda81(invocation_with("honda81", {{"honda.e.par", parameters}}));
}

TEST(Honda81, LowerVigorOfTwoCollidingDisksIsStopped) {
  // Radius 0.5: centres 0.9 apart overlap (0.9 < 1), 1.5 apart do not.
  auto field = honda81("radius: 0.5\n");
  std::vector<Query> queries = {query_at({0, 0, 0}, {0.9f}), query_at({0.9f, 0, 0}, {0.5f}),
                                query_at({5, 0, 0}, {0.2f}), query_at({6.5f, 0, 0}, {0.8f})};
  auto answers = answer_all(*field, queries);
  EXPECT_EQ(first_answer(answers[0]), 1.0f);  // beats its neighbour
  EXPECT_EQ(first_answer(answers[1]), 0.0f);  // lower vigor, stopped
  EXPECT_EQ(first_answer(answers[2]), 1.0f);  // 1.5 apart: no collision
  EXPECT_EQ(first_answer(answers[3]), 1.0f);
  for (const Answer& answer : answers) EXPECT_FALSE(answer.set[1]);  // p2 unchanged
}

TEST(Honda81, TouchingDisksDoNotCollide) {
  auto field = honda81("radius: 0.5\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {1}), query_at({1, 0, 0}, {0.1f})});
  EXPECT_EQ(first_answer(answers[1]), 1.0f);  // exactly 2r apart
}

TEST(Honda81, EqualVigorKeepsBoth) {
  auto field = honda81("radius: 1\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0.7f}), query_at({0.5f, 0.5f, 0}, {0.7f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
}

TEST(Honda81, ChainStopsOnlyThoseBeatenByANeighbour) {
  // A row 1 apart, radius 0.6 (reach 1.2): each disk touches its direct
  // neighbours only. Vigors 0.5 0.9 0.3 0.4: disk 0 loses to 1, disk 2 to 1
  // and 3, disk 3 beats 2 and has no other neighbour.
  auto field = honda81("radius: 0.6\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0.5f}), query_at({1, 0, 0}, {0.9f}),
                                     query_at({2, 0, 0}, {0.3f}), query_at({3, 0, 0}, {0.4f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
  EXPECT_EQ(first_answer(answers[2]), 0.0f);
  EXPECT_EQ(first_answer(answers[3]), 1.0f);
}

TEST(Honda81, GroupsDoNotCollideWithEachOther) {
  auto field = honda81("radius: 1\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0.9f, 1}), query_at({0.1f, 0, 0}, {0.1f, 2}),
                                     query_at({0, 0.1f, 0}, {0.5f, 1}), query_at({0.2f, 0, 0}, {0.05f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);  // alone in group 2
  EXPECT_EQ(first_answer(answers[2]), 0.0f);  // group 1, loses to 0.9
  EXPECT_EQ(first_answer(answers[3]), 1.0f);  // group 0 by default, alone
}

TEST(Honda81, TwoDimensionsIgnoreZThreeDimensionsDoNot) {
  // Same x, y; 3 apart in z; radius 1.
  std::vector<Query> queries = {query_at({0, 0, 0}, {1}), query_at({0, 0, 3}, {0.5f})};
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n"), queries)[1]), 0.0f);
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n3d case: on\n"), queries)[1]), 1.0f);
  // In 3D the distance counts all three axes: (0.75, 0.75, 0.75) is 1.299
  // from the origin, closer than 2r = 2.
  std::vector<Query> diagonal = {query_at({0, 0, 0}, {1}), query_at({0.75f, 0.75f, 0.75f}, {0.5f})};
  EXPECT_EQ(first_answer(answer_all(*honda81("radius: 1\n3d case: on\n"), diagonal)[1]), 0.0f);
}

TEST(Honda81, VigorOneStopsEveryWeakerObject) {
  auto field = honda81("radius: 1\n");
  std::vector<Query> queries = {query_at({0, 0, 0}, {1})};
  for (int i = 0; i < 6; ++i) {
    float angle = static_cast<float>(i) * 1.047f;
    queries.push_back(query_at({1.5f * std::cos(angle), 1.5f * std::sin(angle), 0}, {0.99f}));
  }
  auto answers = answer_all(*field, queries);
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  for (std::size_t i = 1; i < answers.size(); ++i) EXPECT_EQ(first_answer(answers[i]), 0.0f) << i;
}

TEST(Honda81, ModulesWithoutParametersAreIgnored) {
  auto field = honda81("radius: 1\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {}), query_at({0, 0, 0}, {0.5f})});
  EXPECT_FALSE(answers[0].set.any());
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
}

TEST(Honda81, AgreesWithComparingEveryPairOnARandomScene) {
  // 3000 disks in a 40 x 40 square: the grid must find exactly the pairs a
  // comparison of all pairs finds.
  auto field = honda81("radius: 0.4\n");
  std::vector<Query> queries;
  std::uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  for (int i = 0; i < 3000; ++i) queries.push_back(query_at({40 * next(), 40 * next(), 0}, {next(), 0}));
  auto answers = answer_all(*field, queries);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    bool beaten = false;
    for (std::size_t j = 0; j < queries.size(); ++j) {
      double dx = queries[i].turtle.position[0] - queries[j].turtle.position[0];
      double dy = queries[i].turtle.position[1] - queries[j].turtle.position[1];
      if (dx * dx + dy * dy < 0.64 && queries[j].module.parameters[0] > queries[i].module.parameters[0]) beaten = true;
    }
    ASSERT_EQ(first_answer(answers[i]), beaten ? 0.0f : 1.0f) << i;
  }
}

TEST(Honda81, NeedsTheTurtlePosition) {
  auto field = honda81("radius: 1\n");
  Query query = query_at({0, 0, 0}, {1});
  query.turtle.position_count = 0;
  try {
    answer_all(*field, {query});
    FAIL() << "no error";
  } catch (const ModelError& error) {
    EXPECT_NE(std::string(error.what()).find("turtle position: %g %g"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("commfile.e:1"), std::string::npos) << error.what();
  }
}

TEST(Honda81, ParameterFileErrorsSayWhereAndWhat) {
  auto message = [](const std::string& parameters) {
    try {
      honda81(parameters);
    } catch (const ModelError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("3d case: on\n").find("needs 'radius:'"), std::string::npos);
  EXPECT_NE(message("radius: big\n").find("honda.e.par:1:9: error: expected a number, found 'big'"), std::string::npos)
      << message("radius: big\n");
  EXPECT_NE(message("radius: -1\n").find(":1:9: error: expected a radius greater than 0"), std::string::npos);
  EXPECT_NE(message("radius: 1\n3d case: maybe\n").find(":2:10: error: expected on or off, found 'maybe'"),
            std::string::npos)
      << message("radius: 1\n3d case: maybe\n");
  EXPECT_NE(message("radius: 1\ncolour: red\n").find(":2:1: error: unknown honda81 parameter 'colour:'"),
            std::string::npos);
  EXPECT_NE(message("radius 1\n").find(":1:1: error: expected 'name: value'"), std::string::npos);
  EXPECT_NE(message("radius: 1 2\n").find(":1:11: error: expected the end of the line"), std::string::npos)
      << message("radius: 1 2\n");
}

TEST(Honda81, MissingParameterFileIsAnError) {
  ProgramInvocation invocation;
  invocation.program = "honda81";
  invocation.e_file = "x.e";
  invocation.e_file_line = 3;
  EXPECT_THROW(make_honda81(invocation), ModelError);
  invocation.arguments = {"/nonexistent/honda.par"};
  try {
    make_honda81(invocation);
    FAIL();
  } catch (const ModelError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot open the honda81 parameter file"), std::string::npos);
  }
}

}  // namespace
}  // namespace sylva::env::test
