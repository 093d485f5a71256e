// density (Sylva's own program): neighbours within a radius, and their number
// per unit area or volume.
#include <gtest/gtest.h>

#include <numbers>

#include "env/programs/programs.h"
#include "env/programs/collision_scene.h"
#include "support/diagnostic.h"

namespace sylva::env::test {
namespace {

std::unique_ptr<Field> density(const std::string& parameters) {
  return make_density(invocation_with("density", {{"density.par", parameters}}));
}

TEST(Density, CountsOtherPointsCloserThanTheRadius) {
  auto field = density("radius: 2\n");
  // Points on the x axis at 0, 1, 1.5, 2 and 5: from 0 the others within 2
  // (not counting exactly 2) are 1 and 1.5.
  auto answers = answer_all(*field, {query_at({0, 0, 0}, {0, 0}), query_at({1, 0, 0}, {0}),
                                     query_at({1.5f, 0, 0}, {0}), query_at({2, 0, 0}, {0}),
                                     query_at({5, 0, 0}, {0, 0}), query_at({4, 4, 0}, {})});
  EXPECT_EQ(first_answer(answers[0]), 2.0f);
  EXPECT_EQ(first_answer(answers[1]), 3.0f);  // 0, 1.5, 2
  EXPECT_EQ(first_answer(answers[2]), 3.0f);  // 0, 1, 2
  EXPECT_EQ(first_answer(answers[3]), 2.0f);  // 1, 1.5 (0 and 5 are not closer than 2)
  EXPECT_EQ(first_answer(answers[4]), 0.0f);  // (4,4) is sqrt(17) away
  EXPECT_FALSE(answers[5].set.any());        // counted, but not answered
  EXPECT_NEAR(answers[0].value[1], 2 / (std::numbers::pi * 4), 1e-6);
  EXPECT_NEAR(answers[4].value[1], 0, 1e-9);
  EXPECT_FALSE(answers[1].set[1]);  // one parameter: only the count
}

TEST(Density, ThreeDimensionsUseVolume) {
  std::vector<Query> queries = {query_at({0, 0, 0}, {0, 0}), query_at({0, 0, 1.5f}, {0, 0}),
                                query_at({0.5f, 0, 0}, {0, 0})};
  auto flat = answer_all(*density("radius: 1\n"), queries);
  EXPECT_EQ(first_answer(flat[0]), 2.0f);
  auto solid = answer_all(*density("radius: 1\n3d case: on\n"), queries);
  EXPECT_EQ(first_answer(solid[0]), 1.0f);
  EXPECT_NEAR(solid[0].value[1], 1 / (4.0 / 3.0 * std::numbers::pi), 1e-6);
  EXPECT_EQ(first_answer(solid[1]), 0.0f);
}

TEST(Density, ParameterErrors) {
  EXPECT_THROW(density("radius: 0\n"), ModelError);
  EXPECT_THROW(density("verbose: on\n"), ModelError);
  EXPECT_THROW(density("radius: 1\nsize: 3\n"), ModelError);
}

}  // namespace
}  // namespace sylva::env::test
