// arvo (EnviroManual 3.1.3): segments tested against, and climbing along,
// the surfaces of a background file and of objects the model adds.
#include <gtest/gtest.h>

#include <cmath>

#include "env/programs/programs.h"
#include "env/programs/collision_scene.h"
#include "support/diagnostic.h"

namespace sylva::env::test {
namespace {

std::unique_ptr<Field> arvo(const std::string& parameters, const std::string& obstacles = "") {
  std::vector<std::pair<std::string, std::string>> files = {{"arvo.par", parameters}};
  if (!obstacles.empty()) files.push_back({"scene.dat", obstacles});
  return make_arvo(invocation_with("arvo", files));
}

// ?E(p...) followed by `next`, the turtle at `position` heading along
// `heading` with `up`.
Query segment_query(std::array<float, 3> position, std::array<float, 3> heading, std::vector<float> parameters,
                    ModuleRecord next, std::array<float, 3> up = {0, 0, 1}) {
  Query query = query_at(position, std::move(parameters));
  query.turtle.heading = heading;
  query.turtle.up = up;
  query.turtle.heading_count = 3;
  query.turtle.up_count = 3;
  query.following = std::move(next);
  return query;
}

void expect_vector(const Answer& answer, int first, std::array<float, 3> expected, float tolerance = 1e-5f) {
  for (int a = 0; a < 3; ++a) {
    ASSERT_TRUE(answer.set[first + a]);
    EXPECT_NEAR(answer.value[first + a], expected[a], tolerance) << "parameter " << first + a;
  }
}

const char* kWall = "polygon -10 5 -10  10 5 -10  10 5 10  -10 5 10\n";  // the plane y = 5

TEST(Arvo, SegmentHitsTheWallOnlyWithinItsLengthPlusTheSurfaceDistance) {
  auto field = arvo("surface distance: 0.5\nobstacles: scene.dat\n", kWall);
  auto answers = answer_all(*field, {segment_query({0, 0, 0}, {0, 1, 0}, {0, 0, 0, 0}, {"F", {4}}),
                                     segment_query({0, 0, 0}, {0, 1, 0}, {0, 0, 0, 0}, {"F", {4.6f}}),
                                     segment_query({0, 0, 0}, {0, -1, 0}, {0}, {"f", {40}})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);  // reaches 4.5 < 5
  EXPECT_FALSE(answers[0].set[1]);
  EXPECT_EQ(first_answer(answers[1]), 1.0f);  // reaches 5.1
  expect_vector(answers[1], 1, {0, -1, 0});   // facing the segment
  EXPECT_EQ(first_answer(answers[2]), 0.0f);  // pointing away
}

TEST(Arvo, TransformedSpheresAndCylinders) {
  auto field = arvo("surface distance: 0.1\nobstacles: scene.dat\n",
                    "/* an ellipsoid 3 high at y = 10 */\n"
                    "pushmatrix\ntranslate 0 10 0\nscale 1 3 1\nsphere 1\npopmatrix\n"
                    "#define R 1\n"
                    "translate 3 0 0 // a post along y at x = 3\ncylinder R 10\n");
  auto answers = answer_all(*field, {segment_query({0, 0, 0}, {0, 1, 0}, {0, 0, 0, 0}, {"F", {6.8f}}),
                                     segment_query({0, 0, 0}, {0, 1, 0}, {0, 0, 0, 0}, {"F", {7.2f}}),
                                     segment_query({0, 5, 0}, {1, 0, 0}, {0, 0, 0, 0}, {"F", {1.85f}}),
                                     segment_query({0, 5, 0}, {1, 0, 0}, {0, 0, 0, 0}, {"F", {1.95f}})});
  EXPECT_EQ(first_answer(answers[0]), 0.0f);  // the ellipsoid starts at y = 7
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
  expect_vector(answers[1], 1, {0, -1, 0});
  EXPECT_EQ(first_answer(answers[2]), 0.0f);  // the post's side is at x = 2
  EXPECT_EQ(first_answer(answers[3]), 1.0f);
  expect_vector(answers[3], 1, {-1, 0, 0});
}

TEST(Arvo, ConeSideNormal) {
  // Base radius 2 at y = 0, apex at y = 4: at y = 1 the radius is 1.5 and the
  // outward normal is (1, 0.5, 0) normalised.
  auto field = arvo("surface distance: 0\nobstacles: scene.dat\n", "cone 2 0 4\n");
  auto answers = answer_all(*field, {segment_query({5, 1, 0}, {-1, 0, 0}, {0, 0, 0, 0}, {"F", {3.6f}}),
                                     segment_query({0, -3, 0}, {0, 1, 0}, {0, 0, 0, 0}, {"F", {3.1f}})});
  EXPECT_EQ(first_answer(answers[0]), 1.0f);
  expect_vector(answers[0], 1, {0.894427f, 0.447214f, 0});
  EXPECT_EQ(first_answer(answers[1]), 1.0f);  // the base
  expect_vector(answers[1], 1, {0, -1, 0});
}

TEST(Arvo, AddedObjectsLastOnePassUnlessKept) {
  std::vector<Query> pass = {segment_query({0, 10, 0}, {0, 1, 0}, {}, {"S", {1}}),
                             segment_query({0, 0, 0}, {0, 1, 0}, {0}, {"F", {9.5f}})};
  std::vector<Query> later = {pass[1]};
  auto removing = arvo("surface distance: 0\nadd objects: on\n");
  EXPECT_EQ(first_answer(answer_all(*removing, pass)[1]), 1.0f);  // the sphere's surface is at y = 9
  EXPECT_EQ(first_answer(answer_all(*removing, later)[0]), 0.0f);
  auto keeping = arvo("surface distance: 0\nadd objects: on\nremove objects: off\n");
  answer_all(*keeping, pass);
  EXPECT_EQ(first_answer(answer_all(*keeping, later)[0]), 1.0f);
  auto ignoring = arvo("surface distance: 0\n");
  EXPECT_EQ(first_answer(answer_all(*ignoring, pass)[1]), 0.0f);
}

TEST(Arvo, AddedCylinderStandsAlongTheHeading) {
  // C(0.5, 4) at (0,0,0) heading +x: a rod from x = 0 to 4.
  auto field = arvo("surface distance: 0\nadd objects: on\n");
  auto answers = answer_all(*field, {segment_query({0, 0, 0}, {1, 0, 0}, {}, {"C", {0.5f, 4}}),
                                     segment_query({2, 3, 0}, {0, -1, 0}, {0, 0, 0, 0}, {"F", {2.6f}}),
                                     segment_query({6, 3, 0}, {0, -1, 0}, {0}, {"F", {5}})});
  EXPECT_EQ(first_answer(answers[1]), 1.0f);
  expect_vector(answers[1], 1, {0, 1, 0});
  EXPECT_EQ(first_answer(answers[2]), 0.0f);  // beyond the rod's end
}

const char* kFloor = "polygon -50 -50 0  50 -50 0  50 50 0  -50 50 0\n";

TEST(Arvo, NewSegmentFollowsTheFloor) {
  auto field = arvo("surface distance: 0.5\nmax surface distance: 1.5\nobstacles: scene.dat\n", kFloor);
  auto answers = answer_all(*field, {segment_query({0, 0, 0.5f}, {0, 1, 0}, {1, 0, 0, 0, 0, 0, 0}, {})});
  // Straight ahead: Q = (0, 1, 0.5), the floor 0.5 below it, so P = Q.
  expect_vector(answers[0], 0, {0, 1, 0});
  EXPECT_NEAR(answers[0].value[3], 1.0f, 1e-6);
  expect_vector(answers[0], 4, {0, 0, 1});
}

TEST(Arvo, NewSegmentTurnsAwayFromAWall) {
  // A wall across the way at y = 0.6. Straight ahead (Q = (0,1,0.25)) the
  // segment would pass through it; the next candidate, 90 degrees to the
  // turtle's left (-x for heading +y and up +z), is free.
  auto field = arvo("surface distance: 0.25\nmax surface distance: 0.5\ntries for Q: 4\nobstacles: scene.dat\n",
                    std::string(kFloor) + "polygon -50 0.6 0  50 0.6 0  50 0.6 10  -50 0.6 10\n");
  auto answers = answer_all(*field, {segment_query({0, 0, 0.25f}, {0, 1, 0}, {1, 0, 0, 0, 0, 0, 0}, {})});
  expect_vector(answers[0], 0, {-1, 0, 0});
  EXPECT_NEAR(answers[0].value[3], 1.0f, 1e-6);
  expect_vector(answers[0], 4, {0, 0, 1});
}

TEST(Arvo, NoSurfaceNearMeansNoSegment) {
  auto field = arvo("surface distance: 0.5\n");
  auto answers = answer_all(*field, {segment_query({0, 0, 0}, {0, 1, 0}, {1, 0, 0, 0, 0, 0, 0}, {})});
  EXPECT_EQ(answers[0].value[3], 0.0f);
  expect_vector(answers[0], 0, {0, 1, 0});
  expect_vector(answers[0], 4, {0, 0, 1});
}

TEST(Arvo, TheSameSeedGivesTheSameSegments) {
  std::string scene = "translate 0 0 -3\nsphere 3\n";
  std::string parameters = "surface distance: 0.2\nmax surface distance: 1\ntries for surface: 30\nseed: 7\n"
                           "obstacles: scene.dat\n";
  std::vector<Query> queries = {segment_query({0.3f, 0.2f, 0.25f}, {1, 0, 0}, {0.5f, 0, 0, 0, 0, 0, 0}, {})};
  auto first = answer_all(*arvo(parameters, scene), queries);
  auto second = answer_all(*arvo(parameters, scene), queries);
  for (int p = 0; p < 7; ++p) EXPECT_EQ(first[0].value[p], second[0].value[p]);
  // The tip keeps about the surface distance from the sphere.
  std::array<double, 3> tip{0.3, 0.2, 0.25};
  for (int a = 0; a < 3; ++a) tip[a] += first[0].value[a] * first[0].value[3];
  double from_centre = std::sqrt(tip[0] * tip[0] + tip[1] * tip[1] + (tip[2] + 3) * (tip[2] + 3));
  EXPECT_NEAR(from_centre, 3.2, 0.05);
}

TEST(Arvo, SegmentQueryNeedsAFollowingSegment) {
  auto field = arvo("surface distance: 0.5\n");
  EXPECT_THROW(answer_all(*field, {segment_query({0, 0, 0}, {0, 1, 0}, {0}, {})}), std::runtime_error);
  EXPECT_THROW(answer_all(*field, {segment_query({0, 0, 0}, {0, 1, 0}, {0}, {"A", {1}})}), std::runtime_error);
}

TEST(Arvo, ParameterAndObstacleFileErrors) {
  auto message = [](const std::string& parameters, const std::string& obstacles = "") {
    try {
      arvo(parameters, obstacles);
    } catch (const ModelError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("seed: 1\n").find("needs 'surface distance:'"), std::string::npos);
  EXPECT_NE(message("surface distance: 1\ngrid size: 4x4\n").find(":2:15: error: expected 3 numbers"),
            std::string::npos)
      << message("surface distance: 1\ngrid size: 4x4\n");
  EXPECT_EQ(message("surface distance: 1\ngrid size: 4x4x2\ndomain size: 1, 2, 3\nposition: -1 -1 -1\n"), "no error");
  EXPECT_NE(message("surface distance: 1\nobstacles: scene.dat\n", "sphere 1\nbox 1 2\n")
                .find("scene.dat:3:1: error: expected an edge length for 'box', found the end of the file"),
            std::string::npos)
      << message("surface distance: 1\nobstacles: scene.dat\n", "sphere 1\nbox 1 2\n");
  EXPECT_NE(message("surface distance: 1\nobstacles: scene.dat\n", "sphere 1\n  teapot 3\n")
                .find("scene.dat:2:3: error: expected a background command"),
            std::string::npos);
  EXPECT_NE(message("surface distance: 1\nobstacles: missing.dat\n").find("cannot open the arvo obstacles file"),
            std::string::npos);
}

}  // namespace
}  // namespace sylva::env::test
