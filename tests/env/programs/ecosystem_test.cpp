// ecosystem (EnviroManual 3.1.2): overlapping disks or spheres of different
// radii; the smaller (or, with vigor, the weaker) one is answered 0, by the
// rules of the Virtual Laboratory's program (src/env/programs/ecosystem.cpp).
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

// Disks lie in x and z (the turtle's y is left out), as the real program
// places them.
TEST(Ecosystem, SmallerOfTwoOverlappingDisksCollides) {
  auto field = ecosystem("grid size: 10 10\n");
  // Radii 2 and 1, 2.5 apart: overlap (2.5 < 3). A third disk of radius 0.5
  // at distance 4 from the second (along z), 4.7 from the first: free.
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {2}), query_at({2.5f, 0, 0}, {1}),
                                     query_at({2.5f, 0, 4}, {0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
}

// "<=" in both of the program's tests: an equal radius beats, and touching
// disks collide.
TEST(Ecosystem, EqualRadiiBothCollideAndTouchingCollides) {
  auto field = ecosystem("grid size: 4 4\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {1}), query_at({1.9f, 0, 0}, {1}),
                                     query_at({10, 0, 0}, {1}), query_at({12, 0, 0}, {1}),
                                     query_at({20, 0, 0}, {1}), query_at({22.5f, 0, 0}, {1})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
  EXPECT_EQ(first_answer(answers[2]), 0.0f);  // exactly r1 + r2 apart
  EXPECT_EQ(first_answer(answers[3]), 0.0f);
  EXPECT_EQ(first_answer(answers[4]), 1.0f);  // 2.5 apart
  EXPECT_EQ(first_answer(answers[5]), 1.0f);
}

TEST(Ecosystem, DiskInsideABiggerDiskCollides) {
  auto field = ecosystem("grid size: 1 1\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {5}), query_at({1, 1, 0}, {0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  EXPECT_EQ(first_answer(answers[1]), 0.0f);
}

TEST(Ecosystem, VigorDecidesBeforeRadius) {
  auto field = ecosystem("grid size: 8 8\nvigor: on\n");
  // Pair A: the big disk has the lower vigor and loses; having lost, it
  // stops nothing. Pair B: equal vigor, the strictly larger radius wins.
  // Pair C: equal vigor and radius: neither loses.
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {3, 0.2f}), query_at({2, 0, 0}, {1, 0.8f}),
                                     query_at({0, 0, 20}, {3, 0.5f}), query_at({2, 0, 20}, {1, 0.5f}),
                                     query_at({0, 0, 40}, {1, 0.5f}), query_at({1, 0, 40}, {1, 0.5f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
  EXPECT_EQ(first_answer(answers[3]), 0.0f);
  EXPECT_EQ(first_answer(answers[4]), 1.0f);
  EXPECT_EQ(first_answer(answers[5]), 1.0f);
  for (const Answer& answer : answers) EXPECT_FALSE(answer.set[1]);
}

// An object that has lost no longer stops the ones after it (string order).
TEST(Ecosystem, WithVigorALoserStopsNothing) {
  auto field = ecosystem("grid size: 8 8\nvigor: on\n");
  // 0 loses to 1 (a higher vigor). 2 overlaps only 0, whose vigor is higher
  // than its own, but 0 has lost by the time 2 is tested: 2 stays.
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {1, 0.5f}), query_at({-1.5f, 0, 0}, {1, 0.9f}),
                                     query_at({1.5f, 0, 0}, {1, 0.1f})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
  EXPECT_EQ(first_answer(answers[2]), 1.0f);
}

TEST(Ecosystem, ThreeDimensionsSeparateByY) {
  // In 2D the turtle's y is not used: these overlap; in 3D they are 2.5 apart.
  std::vector<Query> queries = {query_at({0, 0, 0}, {1}), query_at({0, 2.5f, 0}, {0.5f})};
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
  // The rule worked pair by pair in string order, in float as the program
  // computes it: an object loses to any colliding one that has not lost
  // before it is tested and has a higher vigor, or an equal vigor and a
  // strictly larger radius.
  std::vector<bool> lost(queries.size(), false);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const auto& pi = queries[i].module.parameters;
    for (std::size_t j = 0; j < queries.size(); ++j) {
      if (j == i || lost[j]) continue;
      const auto& pj = queries[j].module.parameters;
      float d2 = 0;
      for (int a = 0; a < 3; ++a) {
        const float d = queries[i].turtle.position[a] - queries[j].turtle.position[a];
        d2 += d * d;
      }
      const float reach = pi[0] + pj[0];
      const bool loses = pi[1] < pj[1] || (pi[1] == pj[1] && pi[0] < pj[0]);
      if (d2 <= reach * reach && loses) lost[i] = true;
    }
    ASSERT_EQ(first_answer(answers[i]), lost[i] ? 0.0f : 1.0f) << i;
  }
}

// The specification is read as the program reads it: numbers with atoi,
// anything else a warning; only a grid it could not hold stops it.
TEST(Ecosystem, SpecificationAsTheProgramReadsIt) {
  auto message = [](const std::string& parameters) {
    try {
      ecosystem(parameters);
    } catch (const std::exception& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("grid size: 10 ten\n3D case: one\n"), "no error");
  EXPECT_NE(message("grid size: 100000 100000 100000\n3d case: on\n").find("more than this program can hold"),
            std::string::npos);
}

TEST(Ecosystem, WithVigorAModuleWithOneParameterTakesNoPart) {
  auto field = ecosystem("grid size: 2 2\nvigor: on\n");
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {1}), query_at({0.5f, 0, 0}, {0.5f, 1})});
  EXPECT_FALSE(answers[0].set[0]);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);  // the other is not there to stop it
}

}  // namespace
}  // namespace sylva::env::test
