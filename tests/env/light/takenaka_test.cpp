// takenaka (EnviroManual 3.2.3): light reaching leaf clusters through other
// clusters, turned into photosynthates less the maintenance cost. Expected
// values are worked out by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "env/light/light_test_support.h"
#include "env/programs/programs.h"

namespace sylva::test::light {
namespace {

using env::make_takenaka;

constexpr float kPi = std::numbers::pi_v<float>;

std::unique_ptr<env::Field> takenaka(const std::string& name, const std::string& text) {
  return make_takenaka(invocation_with_file(name, "takenaka", "takenaka.par", text));
}

// Defaults: transmittance 0.1, efficiency 0.015, sparsity 1.5, beam 0. A
// cluster of area pi has matter of radius 1 and a sphere of radius 1.5.
const std::string kFromAbove = "grid size: 4 4 4\nsource: 0 1 0 1\n";

TEST(TakenakaTest, ClusterAboveLetsThroughTheTransmittance) {
  auto field = takenaka("takenaka-above", kFromAbove);
  std::vector<env::Query> q{query_at(0, 0, 0, {kPi, 0.002f, 0, 0}), query_at(0, 10, 0, {kPi, 0.01f, 0, 0})};
  auto a = answer_all(*field, q);
  // p2 = efficiency * area * flux - cost.
  EXPECT_NEAR(a[0].value[1], 0.015 * std::numbers::pi * 0.1 - 0.002, 1e-7);
  EXPECT_NEAR(a[1].value[1], 0.015 * std::numbers::pi * 1.0 - 0.01, 1e-7);
  // Only p2 is answered: the area stays.
  for (int i : {0, 1}) {
    EXPECT_EQ(a[i].set.count(), 1u);
    EXPECT_TRUE(a[i].set.test(1));
  }
}

TEST(TakenakaTest, SparsityEnlargesTheShadingSphere) {
  auto field = takenaka("takenaka-sparsity", kFromAbove);
  // B at 1.4 to the side of A's ray: inside B's sphere of radius 1.5 though
  // outside its matter (radius 1). C, above at 1.6 to the other side: missed.
  std::vector<env::Query> q{query_at(0, 0, 0, {kPi, 0}), query_at(1.4f, 10, 0, {kPi, 0}),
                            query_at(-1.6f, 20, 0, {kPi, 0})};
  EXPECT_NEAR(answer_all(*field, q)[0].value[1], 0.015 * std::numbers::pi * 0.1, 1e-7);
  auto wider = takenaka("takenaka-sparsity-2", kFromAbove + "parameter: 2\n");
  // Spheres of radius 2: C is hit too.
  EXPECT_NEAR(answer_all(*wider, q)[0].value[1], 0.015 * std::numbers::pi * 0.01, 1e-7);
}

TEST(TakenakaTest, BeamSeesTheCoveredPartOfItsDisk) {
  auto field = takenaka("takenaka-beam", kFromAbove + "beam radius: 1\ntransmittance: 0.2\n");
  // A's beam is its whole disk (radius 1.5); B's disk, radius 1.5 and 1.5 to
  // the side, covers (2 acos(1/2) - sqrt(3)/2) / pi = 0.391 of it, which lets
  // through 1 - 0.391 (1 - 0.2) of the light.
  double part = (2 * std::acos(0.5) - std::sqrt(3.0) / 2) / std::numbers::pi;
  std::vector<env::Query> q{query_at(0, 0, 0, {kPi, 0}), query_at(1.5f, 10, 0, {kPi, 0})};
  EXPECT_NEAR(answer_all(*field, q)[0].value[1], 0.015 * std::numbers::pi * (1 - part * 0.8), 1e-7);
}

TEST(TakenakaTest, ShadingClustersMultiplyAndSourcesAdd) {
  auto field = takenaka("takenaka-sources", "grid size: 4 4 4\nsource: 0 1 0 1\nsource: 1 0 0 1\nefficiency: 1\n");
  // From above: B and C in the way, 0.1 * 0.1 of 0.5; from +x: open, 0.5.
  std::vector<env::Query> q{query_at(0, 0, 0, {4, 1}), query_at(0, 5, 0, {kPi, 0}), query_at(0, 9, 0, {kPi, 0})};
  EXPECT_NEAR(answer_all(*field, q)[0].value[1], 4 * (0.5 * 0.01 + 0.5) - 1, 1e-6);
}

// Every pair of clusters tested directly, by the formula of the manual:
// sparsity 1.5, beam radius b, efficiency 1, no cost, so the answer is A Phi.
double flux_by_every_pair(const std::vector<env::Query>& q, std::size_t i, double t, double b,
                          const std::vector<std::array<double, 4>>& sources) {
  auto radius = [&](std::size_t k) { return 1.5 * std::sqrt(double(q[k].module.parameters[0]) / std::numbers::pi); };
  auto lens = [](double r1, double r2, double d) {
    if (d >= r1 + r2) return 0.0;
    if (d <= std::abs(r1 - r2)) return std::numbers::pi * std::min(r1, r2) * std::min(r1, r2);
    double alpha = std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1));
    double beta = std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2));
    return r1 * r1 * (alpha - std::sin(2 * alpha) / 2) + r2 * r2 * (beta - std::sin(2 * beta) / 2);
  };
  double flux = 0;
  for (const auto& s : sources) {
    double n = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    double intensity = s[3];
    double beam = b * radius(i);
    for (std::size_t j = 0; j < q.size(); ++j) {
      if (j == i) continue;
      double w[3];
      for (int k = 0; k < 3; ++k) w[k] = double(q[j].turtle.position[k]) - double(q[i].turtle.position[k]);
      double along = (w[0] * s[0] + w[1] * s[1] + w[2] * s[2]) / n;
      if (along <= 0) continue;
      double d = std::sqrt(std::max(0.0, w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - along * along));
      double covered = lens(beam, radius(j), d) / (std::numbers::pi * beam * beam);
      intensity *= 1 - covered * (1 - t);
    }
    flux += intensity;
  }
  return double(q[i].module.parameters[0]) * flux;
}

TEST(TakenakaTest, GridGivesTheSameAnswerAsTestingEveryPair) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(-1, 1), area(0.5f, 6);
  std::vector<env::Query> q;
  for (int i = 0; i < 2500; ++i) {
    float x, y, z;
    do {
      x = unit(random), y = unit(random), z = unit(random);
    } while (x * x + y * y + z * z > 1);
    float crown = static_cast<float>(i % 2);
    q.push_back(query_at(12 * crown + 9 * x, 9 * y, 9 * z + crown, {area(random), 0}));
  }
  std::vector<std::array<double, 4>> sources{{0, 1, 0, 0.4}, {0.5, 1, 0.2, 0.3}, {-1, 0.3, -0.6, 0.3}};
  auto field = takenaka("takenaka-pairs", "grid size: 4 4 4\nbeam radius: 0.7\ntransmittance: 0.3\nefficiency: 1\n"
                                          "source: 0 1 0 0.4\nsource: 0.5 1 0.2 0.3\nsource: -1 0.3 -0.6 0.3\n");
  auto a = answer_all(*field, q);
  for (std::size_t i = 0; i < q.size(); ++i)
    EXPECT_NEAR(a[i].value[1], flux_by_every_pair(q, i, 0.3, 0.7, sources), 2e-5 * q[i].module.parameters[0]) << i;
}

TEST(TakenakaTest, ModulesNeedAreaAndCost) {
  auto field = takenaka("takenaka-query", kFromAbove);
  std::vector<env::Query> q{query_at(0, 0, 0, {1})};
  EXPECT_NE(error_of([&] { answer_all(*field, q); })
                .find("has 1 parameters; expected 4 (the cluster's area, its maintenance cost, and two more)"),
            std::string::npos);
  q[0].module.parameters = {-1, 0};
  EXPECT_NE(error_of([&] { answer_all(*field, q); }).find("gives the area -1; expected 0 or more"),
            std::string::npos);
}

std::string takenaka_error(const std::string& text) {
  auto invocation = invocation_with_file("takenaka-errors", "takenaka", "takenaka.par", text);
  std::string message = error_of([&] { make_takenaka(invocation); });
  std::string prefix = (invocation.directory / "takenaka.par").string();
  EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
  return message.substr(std::min(message.size(), prefix.size()));
}

TEST(TakenakaTest, ParameterFileErrors) {
  EXPECT_EQ(takenaka_error("grid size: 8 8 8\n"),
            ": error: takenaka: the parameter file has no 'source: x y z intensity' line");
  EXPECT_EQ(takenaka_error("source: 0 1 0 1\nparameter: 0.5\n"),
            ":2:12: error: takenaka: expected the sparsity of matter in a sphere of 1 or more, found 0.5");
  EXPECT_EQ(takenaka_error("source: 0 1 0 1\nefficiency: high\n"),
            ":2:13: error: takenaka: expected a number (the efficiency), found 'high'");
  EXPECT_EQ(takenaka_error("source: 0 1 0 1\nbeam radius: 1.5\n"),
            ":2:14: error: takenaka: expected the beam radius (a fraction of the sphere's radius) between 0 and 1, "
            "found 1.5");
  std::string unknown = takenaka_error("sources: 0 1 0 1\n");
  EXPECT_EQ(unknown.rfind(":1:1: error: takenaka: unknown command 'sources:'; expected one of ", 0), 0u) << unknown;
}

}  // namespace
}  // namespace sylva::test::light
