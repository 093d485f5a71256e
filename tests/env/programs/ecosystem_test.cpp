// ecosystem (EnviroManual 3.1.2): overlapping disks or spheres of different
// radii; the smaller (or, with vigor, the weaker) one is answered 0.
#include <gtest/gtest.h>

#include <cmath>

#include "env/programs/programs.h"
#include "env/programs/collision_scene.h"
#include "support/diagnostic.h"

namespace sylva::env::test {
namespace {

std::unique_ptr<Field> ecosystem(const std::string& parameters) {
  return make_ecosystem(invocation_with("ecosystem", {{"eco.par", parameters}}));
}

TEST(Ecosystem, SmallerOfTwoOverlappingDisksCollides) {
  auto field = ecosystem("grid size: 10 10\n");
  // Radii 2 and 1, 2.5 apart: overlap (2.5 < 3). A third disk of radius 0.5
  // at distance 4 from the second, 5.5 from the first: free.
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {2}), query_at({2.5f, 0, 0}, {1}),
                                     query_at({2.5f, 4, 0}, {0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
}

TEST(Ecosystem, EqualRadiiBothCollideTouchingDoesNot) {
  auto field = ecosystem("grid size: 4 4\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {1}), query_at({1.9f, 0, 0}, {1}),
                                     query_at({10, 0, 0}, {1}), query_at({12, 0, 0}, {1})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);  // "less than or equal to" the other's radius
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);  // exactly r1 + r2 apart
  EXPECT_EQ(first_answer(answers[3]), 1.0f);
}

TEST(Ecosystem, DiskInsideABiggerDiskCollides) {
  auto field = ecosystem("grid size: 1 1\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {5}), query_at({1, 1, 0}, {0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
}

TEST(Ecosystem, VigorDecidesBeforeRadius) {
  auto field = ecosystem("grid size: 8 8\nvigor: on\n");
  // Pair A: the big disk has the lower vigor and loses. Pair B: equal vigor,
  // the radius decides. Pair C: equal vigor and radius: both lose.
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {3, 0.2f}), query_at({2, 0, 0}, {1, 0.8f}),
                                     query_at({0, 20, 0}, {3, 0.5f}), query_at({2, 20, 0}, {1, 0.5f}),
                                     query_at({0, 40, 0}, {1, 0.5f}), query_at({1, 40, 0}, {1, 0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
  EXPECT_EQ(first_answer(answers[3]), 0.0f);
  EXPECT_EQ(first_answer(answers[4]), 0.0f);
  EXPECT_EQ(first_answer(answers[5]), 0.0f);
  for (const Answer& answer : answers) EXPECT_FALSE(answer.set[1]);
}

TEST(Ecosystem, ThreeDimensionsSeparateByZ) {
  std::vector<Query> queries = {query_at({0, 0, 0}, {1}), query_at({0, 0, 2.5f}, {0.5f})};
  EXPECT_EQ(first_answer(answer_all(*ecosystem("grid size: 5 5\n"), queries)[1]), 0.0f);
  EXPECT_EQ(first_answer(answer_all(*ecosystem("grid size: 5 5 5\n3d case: on\n"), queries)[1]), 1.0f);
  // The z of the grid size is optional in 3D too.
  EXPECT_EQ(first_answer(answer_all(*ecosystem("grid size: 5 5\n3d case: on\n"), queries)[1]), 1.0f);
}

TEST(Ecosystem, DisksAcrossVoxelBoundariesAreFound) {
  // A fine grid (50 x 50 over a 10 x 10 field): each disk spans several
  // voxels, and pairs straddle voxel borders.
  auto field = ecosystem("grid size: 50 x 50\n");
  std::vector<Query> queries;
  for (int i = 0; i < 10; ++i) queries.push_back(query_at({static_cast<float>(i), 0, 0}, {0.3f + 0.05f * i}));
  auto answers = answer_all(*field, queries);
  // Disk i (radius 0.3 + 0.05 i) and i+1 are 1 apart and overlap when
  // 0.65 + 0.1 i > 1, i.e. from i = 4 on. Each loses to its bigger right
  // neighbour: 4..8 collide, the last does not, 0..3 touch nothing.
  for (int i = 0; i < 10; ++i) EXPECT_EQ(first_answer(answers[i]), (i >= 4 && i <= 8) ? 0.0f : 1.0f) << i;
}

TEST(Ecosystem, AgreesWithComparingEveryPair) {
  auto field = ecosystem("grid size: 3 3 3\n3d case: on\nvigor: on\n");
  std::vector<Query> queries;
  std::uint32_t state = 777;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  for (int i = 0; i < 2000; ++i)
    queries.push_back(query_at({20 * next(), 20 * next(), 20 * next()}, {0.1f + next(), std::floor(3 * next())}));
  auto answers = answer_all(*field, queries);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    bool beaten = false;
    const auto& pi = queries[i].module.parameters;
    for (std::size_t j = 0; j < queries.size(); ++j) {
      if (j == i) continue;
      const auto& pj = queries[j].module.parameters;
      double d2 = 0;
      for (int a = 0; a < 3; ++a) {
        double d = queries[i].turtle.position[a] - queries[j].turtle.position[a];
        d2 += d * d;
      }
      double reach = static_cast<double>(pi[0]) + pj[0];
      bool loses = pi[1] != pj[1] ? pi[1] < pj[1] : pi[0] <= pj[0];
      if (d2 < reach * reach && loses) beaten = true;
    }
    ASSERT_EQ(first_answer(answers[i]), beaten ? 0.0f : 1.0f) << i;
  }
}

TEST(Ecosystem, ParameterErrors) {
  auto message = [](const std::string& parameters) {
    try {
      ecosystem(parameters);
    } catch (const ModelError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("vigor: on\n").find("needs 'grid size:'"), std::string::npos);
  EXPECT_NE(message("grid size: 10\n").find(":1:14: error: expected 2 or 3 numbers"), std::string::npos)
      << message("grid size: 10\n");
  EXPECT_NE(message("grid size: 10 ten\n").find(":1:15: error: expected a number, found 'ten'"), std::string::npos);
  EXPECT_NE(message("grid size: 10 0\n").find("expected whole numbers of voxels"), std::string::npos);
}

TEST(Ecosystem, VigorNeedsTwoParameters) {
  auto field = ecosystem("grid size: 2 2\nvigor: on\n");
  EXPECT_THROW(answer_all(*field, {query_at({0, 0, 0}, {1})}), std::runtime_error);
}

}  // namespace
}  // namespace sylva::env::test
