// The measures: the drawing's measures worked by hand, and the string's
// counted a second way from the string's text.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "api/simulation.h"
#include "experiment/measures.h"
#include "test_support.h"

namespace sylva::experiment {
namespace {

TEST(SceneMeasures, ExtentsLengthsAndLeafAreaByHand) {
  geometry::Scene scene;
  geometry::Segment a;
  a.start = {0, 0, 0};
  a.end = {0, 3, 0};
  geometry::Segment b;
  b.start = {0, 3, 0};
  b.end = {4, 6, 0};  // length 5
  scene.segments = {a, b};
  // A unit right triangle (area 0.5) as a polygon, a 2 x 2 square as a
  // surface (area 4) and a generalized cylinder's triangle (not a leaf).
  scene.add_triangles(geometry::TriangleGroup::Kind::Polygon, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {0, 1, 2}, 1, {});
  scene.add_triangles(geometry::TriangleGroup::Kind::Surface, {{0, 0, -1}, {2, 0, -1}, {2, 2, -1}, {0, 2, -1}}, {},
                      {0, 1, 2, 0, 2, 3}, 1, {});
  scene.add_triangles(geometry::TriangleGroup::Kind::GeneralizedCylinder, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {}, {0, 1, 2},
                      1, {});
  const SceneMeasures m = measure_scene(scene);
  EXPECT_DOUBLE_EQ(m.segment_length, 8);
  EXPECT_EQ(m.segments, 2);
  EXPECT_DOUBLE_EQ(m.leaf_area, 4.5);
  EXPECT_DOUBLE_EQ(m.height, 6);  // y from 0 to 6
  EXPECT_DOUBLE_EQ(m.width, 4);   // x from 0 to 4
  EXPECT_DOUBLE_EQ(m.depth, 2);   // z from -1 to 1
}

TEST(SceneMeasures, NothingDrawnMeasuresZero) {
  const SceneMeasures m = measure_scene(geometry::Scene{});
  EXPECT_EQ(m.height, 0);
  EXPECT_EQ(m.leaf_area, 0);
}

// The example tree after 6 steps with seed 3, measured, against the same
// string's text read with a regular expression.
TEST(Measures, CountsAndParameterStatisticsEqualTheStringsText) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  options.seed = 3;
  Simulation simulation(test::example_path("experiment/stochastic-tree.l"), options);
  simulation.run(6);
  const std::string text = simulation.string_text();
  double apices = 0, internodes = 0, sum = 0, least = HUGE_VAL, most = -HUGE_VAL;
  const std::regex module(R"((\bA|\bI)\(([^)]*)\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), module); it != std::sregex_iterator(); ++it) {
    if ((*it)[1] == "A") {
      ++apices;
    } else {
      ++internodes;
      const double length = std::stod((*it)[2]);
      sum += length;
      least = std::min(least, length);
      most = std::max(most, length);
    }
  }
  ASSERT_GT(apices, 1);
  const std::vector<MeasureSpec> specs = {{"a", "count(A)", {}},   {"i", "count(I)", {}},       {"s", "sum(I, 1)", {}},
                                          {"m", "mean(I, 1)", {}}, {"lo", "min(I, 1)", {}},      {"hi", "max(I, 1)", {}},
                                          {"r", "a / i", {}},      {"e", "-2 ^ 2 + (a - a)", {}}, {"x", "mean(\"A\", 2)", {}}};
  const Measures measures(specs, simulation.types());
  EXPECT_FALSE(measures.needs_scene());
  const std::vector<double> v = measures.evaluate(simulation.string(), simulation.types(), nullptr);
  EXPECT_EQ(v[0], apices);
  EXPECT_EQ(v[1], internodes);
  EXPECT_NEAR(v[2], sum, 1e-4 * sum);  // the text has 9 significant digits
  EXPECT_NEAR(v[3], sum / internodes, 1e-4);
  EXPECT_NEAR(v[4], least, 1e-6);
  EXPECT_NEAR(v[5], most, 1e-6);
  EXPECT_DOUBLE_EQ(v[6], apices / internodes);
  EXPECT_EQ(v[7], -4);  // unary minus binds looser than ^, as in mathematics
  EXPECT_GE(v[8], 0);   // lateral flags: 0 or 1
  EXPECT_LE(v[8], 1);
}

TEST(Measures, ErrorsNameTheColumnOfWhatIsWrong) {
  SimulationOptions options;
  options.build.cache_dir = SYLVA_TEST_CACHE_DIR;
  Simulation simulation(test::example_path("experiment/stochastic-tree.l"), options);
  auto error = [&](const std::string& expression) {
    try {
      Measures({{"m", expression, {"plan.toml", 4, 5}}}, simulation.types());
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("count(B)"), "plan.toml:4:11: error: the model has no module 'B' (measure 'm')");
  EXPECT_EQ(error("sum(I, 2)"), "plan.toml:4:12: error: module I has 1 parameter, not 2");
  EXPECT_EQ(error("sum(I)"), "plan.toml:4:10: error: expected ',' and the parameter's number (1 for the first) in the measure 'm'");
  EXPECT_NE(error("heigth").find("plan.toml:4:5: error: unknown name 'heigth'"), std::string::npos);
  EXPECT_NE(error("count(A) +").find("ends where a value was expected"), std::string::npos);
}

}  // namespace
}  // namespace sylva::experiment
